// `dsr bench`: parses the flags by its table (app/command_table.h), runs the sweep (src/analysis/bench_run.h) on a context of the
// chosen backend, and prints or writes what src/analysis/bench_report.h makes of the rows: a short
// summary on stdout (the goals met or not, where the rest went), progress on stderr, the markdown
// report with the full table and a plot (--report, out/bench.md by default), optional JSON. The
// exit status is 0 when the run completed, whatever the goals; non-zero only on an error.
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
#include "analysis/terminal_text.h"
#include "app/command_table.h"
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

}  // namespace

int cmd_bench(const std::vector<std::string>& argv) {
    BenchSettings flags;  // the bench command's table (app/command_table.h)
    parse_command_line(bench_command(flags), argv);
    const std::string scene_path = flags.scene, json_path = flags.json, report_path = flags.report;
    const bool quick = flags.quick;
    bench::Config cfg;
    cfg.quick = quick;
    if (quick)
        cfg.w = cfg.h = BenchSettings::kQuickSize, cfg.frames = BenchSettings::kQuickFrames,
        cfg.warmup = BenchSettings::kQuickWarmup;
    if (flags.width) cfg.w = flags.width, cfg.h = flags.height, cfg.size_given = true;
    if (flags.frames) cfg.frames = flags.frames, cfg.frames_given = true;
    const ShaderOptions& tiles = flags.tiles.shader;  // --tile-*: the option table's entries, its defaults
    cfg.tile_size = tiles.tile_size, cfg.tile_lights = tiles.tile_lights;
    cfg.tile_plan = tiles.tile_plan, cfg.tile_depth = tiles.tile_depth;
    // --lights: comma-separated counts (checked by the flag); "own" is the scene's own lights;
    // N-overlap and N-large the generated scenes of bench_scenes.h.
    cfg.lights_text = !flags.lights.empty() ? flags.lights : quick ? BenchSettings::kQuickLights : BenchSettings::kBenchLights;
    {
        std::stringstream ss(cfg.lights_text);
        for (std::string item; std::getline(ss, item, ',');) {
            const LightSpec spec = *parse_light_spec(item);
            cfg.lights.push_back(spec.count);
            cfg.light_sets.push_back(spec.set);
        }
    }
    cfg.geometries.clear();  // --light-geometry: which geometries get rows of their own
    for (const std::string& g : flags.geometries) cfg.geometries.push_back(light_geometry_from_name(g));

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
    // A large mesh (docs/benchmarks.md): a generated 1,002,528-triangle OBJ under build/bench/, loaded
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

    const auto [context_w, context_h] = bench::context_size(cfg);  // N-large may run at the demo's size
    auto ctx = create_context(context_desc(flags.context, context_w, context_h));
    const Caps caps = probe_caps();
    bench::Summary sum;
    sum.machine = bench::machine_name();
    sum.gl_renderer = caps.renderer, sum.gl_version = caps.version, sum.gl_vendor = caps.vendor;
    sum.config = cfg;
    char start[1024];
    std::snprintf(start, sizeof start,
                  "bench: %s; GL %s (%s); %dx%d, per row warm-up frames until %d in a row build no program and explore "
                  "no path (at most %d), then %d timed frames%s\n",
                  sum.machine.c_str(), caps.renderer.c_str(), caps.version.c_str(), cfg.w, cfg.h, cfg.warmup,
                  cfg.warmup + cfg.compile_warmup, cfg.frames, bench::large_frames_note(cfg).c_str());
    std::fputs(wrap_lines(start).c_str(), stderr);  // every line within the terminal's width (terminal_text.h)

    // Whether the invocation counter can judge the stencil goal (gl/invocation_probe.h).
    sum.invocation_probe = probe_invocation_counter(resource_dir("glsl120"));
    if (sum.invocation_probe)
        std::fprintf(stderr, "bench: invocation counter probe: %lld invocations, %lld samples passed, for %lld pixels failing the stencil test\n",
                     sum.invocation_probe->invocations, sum.invocation_probe->samples, sum.invocation_probe->pixels);
    const double t0 = now_ms();
    bench::Runner runner(cfg, caps, resource_dir("glsl120"));
    runner.progress = [](const std::string& line) { std::fputs(wrap_lines(line + "\n").c_str(), stderr); };
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
    sum.goal_results = bench::judge_goals(sum.rows, sum.scenes[0], own_counts[0], sum.invocation_probe);

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
    std::fflush(stderr);
    // Last, so it names only what was written and is what a terminal shows at the end.
    std::fputs(bench::text_summary(sum, report_path, json_path).c_str(), stdout);
    std::fflush(stdout);
    return 0;  // the run completed: goals not met are findings, not errors
}

}  // namespace dsr
