// `dsr bench`: parses the flags, runs the sweep (src/analysis/bench_run.h) on a context of the
// chosen backend, and prints or writes what src/analysis/bench_report.h makes of the rows: the
// table on stdout, progress on stderr, optional JSON and a markdown report with a plot.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "dsr_clock.h"
#include "analysis/bench_report.h"
#include "analysis/large_mesh.h"
#include "analysis/bench_run.h"
#include "app/args.h"
#include "app/commands.h"
#include "app/files.h"
#include "app/stage.h"
#include "dsr_error.h"
#include "gl/caps.h"
#include "platform/context.h"
#include "platform/resources.h"
#include "scene/image.h"
#include "scene/scene.h"

namespace dsr {

namespace {

std::string dir_of(const std::string& path) {
    size_t s = path.find_last_of('/');
    return s == std::string::npos ? "" : path.substr(0, s + 1);
}

bool ends_with(const std::string& s, const std::string& e) {
    return s.size() >= e.size() && s.compare(s.size() - e.size(), e.size(), e) == 0;
}

}  // namespace

int cmd_bench(const std::vector<std::string>& argv) {
    Args args("bench", argv);
    std::string scene_path, json_path, report_path, lights_arg, geometry_arg, tile_plan;
    std::string backend = default_context_backend();  // --context, else $DSR_CONTEXT
    int w = 0, h = 0, frames = 0, tile_size = 0, tile_lights = 0;
    bool quick = false;
    int tile_depth = -1;  // --tile-depth; -1: the default
    while (!args.done()) {
        std::string a = args.next();
        if (a == "--quick") quick = true;
        else if (a == "--json") json_path = args.value(a);
        else if (a == "--report") report_path = args.value(a);
        else if (a == "--size") args.size_value(a, w, h);
        else if (a == "--frames") frames = args.int_value(a, 1, 1000);
        else if (a == "--lights") lights_arg = args.value(a);
        else if (a == "--light-geometry") geometry_arg = args.value(a);
        else if (a == "--tile-size") tile_size = args.int_value(a, 8, 512);
        else if (a == "--tile-lights") tile_lights = args.int_value(a, 1, 32);
        else if (a == "--tile-plan") tile_plan = args.value(a);
        else if (a == "--tile-depth") tile_depth = args.on_off(a) ? 1 : 0;
        else if (a == "--context") backend = args.value(a);
        else if (!a.empty() && a[0] == '-') args.fail("unknown option '" + a + "'");
        else if (scene_path.empty()) scene_path = a;
        else args.fail("expected one scene file, got also '" + a + "'");
    }
    bench::Config cfg;
    cfg.quick = quick;
    if (quick) cfg.w = cfg.h = 128, cfg.frames = 3, cfg.warmup = 1;
    if (w) cfg.w = w, cfg.h = h;
    if (frames) cfg.frames = frames;
    if (tile_size) cfg.tile_size = tile_size;
    if (tile_lights) cfg.tile_lights = tile_lights;
    if (tile_depth >= 0) cfg.tile_depth = tile_depth == 1;
    if (!tile_plan.empty()) {
        if (tile_plan != "lists" && tile_plan != "groups") args.fail("--tile-plan: expected lists or groups, got '" + tile_plan + "'");
        cfg.tile_plan = tile_plan == "groups" ? TileGrouping::groups : TileGrouping::lists;
    }
    // --lights: comma-separated counts; "own" is the scene's own lights; N-overlap and N-large the
    // generated scenes of bench_scenes.h.
    cfg.lights_text = !lights_arg.empty() ? lights_arg
                      : quick             ? "own,32,256"
                                          : "own,32,256,1024,1024-overlap,32-large";
    {
        std::stringstream ss(cfg.lights_text);
        std::string item;
        while (std::getline(ss, item, ',')) {
            const std::optional<LightSpec> spec = parse_light_spec(item);
            if (!spec)
                args.fail("--lights: expected a comma-separated list of 'own', counts N in [0, 65536], N-overlap "
                          "(N a multiple of 8) or N-large, got '" + item + "' in '" + cfg.lights_text + "'");
            cfg.lights.push_back(spec->count);
            cfg.light_sets.push_back(spec->set);
        }
        if (cfg.lights.empty()) args.fail("--lights: expected at least one count, got ''");
    }
    if (!geometry_arg.empty()) {  // --light-geometry: which geometries get rows of their own
        cfg.geometries.clear();
        std::stringstream ss(geometry_arg);
        std::string item;
        while (std::getline(ss, item, ',')) {
            if (item != "quad" && item != "volume" && item != "stencil" && item != "tiles")
                args.fail("--light-geometry: expected a comma-separated list of quad, volume, stencil, tiles, got '" +
                          geometry_arg + "'");
            cfg.geometries.push_back(light_geometry_from_name(item));
        }
    }
    if (!json_path.empty() && !ends_with(json_path, ".json"))
        args.fail("--json: expected a file ending .json, got '" + json_path + "'");
    if (!report_path.empty() && !ends_with(report_path, ".md"))
        args.fail("--report: expected a file ending .md, got '" + report_path + "'");

    // No SCENE: the default scene and the analytic test scene (constant materials, so it also
    // has an analytic reference). Every scene is loaded before any measurement.
    std::vector<std::string> scenes;
    if (!scene_path.empty()) {
        scenes.push_back(scene_path);
    } else {
        scenes.push_back(resource_dir("data") + "/default.scene");
        try {
            scenes.push_back(resource_dir("tests") + "/data/analytic.scene");
        } catch (const Error&) {
            std::fprintf(stderr, "bench: tests/data/analytic.scene not found; benchmarking the default scene only\n");
        }
    }
    // A large mesh (issue 11): a generated 1,002,528-triangle OBJ under build/bench/, loaded
    // through the OBJ loader like a user's model; its own lights only (a light sweep over it
    // would measure the lights again). Left out of --quick and of runs given a SCENE.
    std::vector<bool> own_only(scenes.size(), false);
    if (scene_path.empty() && !quick) {
        const std::string dir = std::string(DSR_SOURCE_DIR) + "/build/bench";
        std::fprintf(stderr, "bench: writing the large-mesh scene under %s (once)\n", dir.c_str());
        scenes.push_back(write_grid_scene(dir, 708));
        own_only.push_back(true);
    }
    // The outputs, refused now if one is an input (scene/output_set.h), written together at the end.
    OutputSet outputs("dsr bench");
    std::vector<int> own_counts;
    for (auto& s : scenes) {
        const Scene loaded = load_scene(s);
        own_counts.push_back(int(loaded.lights.size()));
        if (s == scene_path) add_scene_inputs(outputs, loaded.inputs);
    }
    const std::string plot_path = report_path.empty() ? "" : dir_of(report_path) + bench::file_stem(report_path) + "_plot.png";
    for (const std::string& p : {json_path, report_path})  // one level, like `figures -o`
        if (!dir_of(p).empty()) outputs.make_dir(p == json_path ? "--json" : "--report", dir_of(p));
    if (!json_path.empty()) outputs.add("--json", json_path);
    if (!report_path.empty()) outputs.add("--report", report_path), outputs.add("--report's plot", plot_path);
    const Stage stage("benchmarking");

    auto ctx = create_context(ContextDesc{backend, cfg.w, cfg.h});
    const Caps caps = probe_caps();
    bench::Summary sum;
    sum.machine = bench::machine_name();
    sum.gl_renderer = caps.renderer, sum.gl_version = caps.version, sum.gl_vendor = caps.vendor;
    sum.config = cfg;
    std::fprintf(stderr, "bench: %s; GL %s (%s); %dx%d, %d warm-up + %d timed frames per row\n", sum.machine.c_str(),
                 caps.renderer.c_str(), caps.version.c_str(), cfg.w, cfg.h, cfg.warmup, cfg.frames);

    // Whether the invocation counter can judge the stencil goal (gl/invocation_probe.h).
    sum.invocation_probe = probe_invocation_counter(resource_dir("glsl120"));
    if (sum.invocation_probe)
        std::fprintf(stderr, "bench: invocation counter probe: %lld invocations, %lld samples passed, for %lld pixels failing the stencil test\n",
                     sum.invocation_probe->invocations, sum.invocation_probe->samples, sum.invocation_probe->pixels);
    const double t0 = now_ms();
    bench::Runner runner(cfg, caps, resource_dir("glsl120"));
    runner.progress = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    const bool has_own = std::find(cfg.lights.begin(), cfg.lights.end(), -1) != cfg.lights.end();
    if (!has_own && own_only.back())
        std::fprintf(stderr, "bench: --lights has no 'own': the large-mesh scene is left out\n");
    int total = 0;
    for (size_t k = 0; k < scenes.size(); ++k) total += own_only[k] ? int(has_own) : int(cfg.lights.size());
    int index = 0;
    for (size_t k = 0; k < scenes.size(); ++k)
        for (size_t i = 0; i < cfg.lights.size(); ++i) {
            if (own_only[k] && cfg.lights[i] != -1) continue;
            runner.run_scene(scenes[k], cfg.lights[i], int(i), index++, total);
        }
    sum.seconds = (now_ms() - t0) / 1000;
    sum.rows = runner.rows();
    sum.notes = runner.notes();
    std::fprintf(stderr, "bench: %zu rows in %.0f s\n", sum.rows.size(), sum.seconds);

    for (auto& s : scenes) sum.scenes.push_back(bench::file_stem(s));
    sum.goals = bench::goals(sum.rows, sum.scenes[0], own_counts[0], sum.invocation_probe);
    std::fputs(bench::text_report(sum).c_str(), stdout);
    std::fflush(stdout);  // the table before the stderr lines that follow

    if (!json_path.empty())
        outputs.put_text("--json", json_path,
                         bench::to_json(sum).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    if (!report_path.empty()) {
        // The plot beside the report: <stem>_plot.png, linked relatively.
        outputs.put_image("--report's plot", plot_path, bench::plot_rows(sum.rows, sum.scenes));
        outputs.put_text("--report", report_path, bench::markdown_report(sum, bench::file_stem(report_path) + "_plot.png"));
    }
    outputs.commit();
    for (const std::string& w : outputs.written()) std::fprintf(stderr, "bench: wrote %s\n", w.c_str());
    return 0;
}

}  // namespace dsr
