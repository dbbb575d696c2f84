// `dsr render`: scene file -> Scene -> DeferredShader::render -> main buffer -> image file.
#include <algorithm>
#include <optional>
#include <cstdio>
#include <cstdlib>

#include <sys/resource.h>

#include <nlohmann/json.hpp>

#include "dsr_clock.h"
#include "app/args.h"
#include "analysis/bench_scenes.h"
#include "app/commands.h"
#include "analysis/frame_ideal.h"
#include "app/files.h"
#include "app/render_flags.h"
#include "app/stage.h"
#include "deferred/deferred_shader.h"
#include "gl/caps.h"
#include "gl/check.h"
#include "gl/state.h"
#include "gl/readback.h"
#include "platform/context.h"
#include "platform/resources.h"
#include "scene/scene.h"

namespace dsr {

namespace {

bool has_ext(const std::string& path, const char* ext) {
    std::string e = ext;
    if (path.size() < e.size()) return false;
    std::string tail = path.substr(path.size() - e.size());
    std::transform(tail.begin(), tail.end(), tail.begin(), ::tolower);
    return tail == e;
}

}  // namespace

int cmd_render(const std::vector<std::string>& argv) {
    Args args("render", argv);
    std::string scene_path, out = "out.png", stats_path, lights_arg;
    int w = 512, h = 512, out_w = 0, out_h = 0, frames = 1;
    RenderOptions ro;  // the option table's flags (deferred/option_table.h)
    std::string caps_list = std::getenv("DSR_CAPS") ? std::getenv("DSR_CAPS") : "";
    std::string context = default_context_backend();  // --context, else $DSR_CONTEXT
    int egl_device = -1;                               // --egl-device, else $DSR_EGL_DEVICE, else 0
    while (!args.done()) {
        std::string a = args.next();
        if (a == "-o" || a == "--output") out = args.value(a);
        else if (a == "--size") args.size_value(a, w, h);
        else if (a == "--frames") frames = args.int_value(a, 1, 100000);
        else if (a == "--stats") stats_path = args.value(a);
        else if (a == "--lights") lights_arg = args.value(a);
        else if (a == "--out-size") args.size_value(a, out_w, out_h);
        else if (parse_render_flag(args, a, ro)) continue;
        else if (a == "--caps") caps_list += "," + args.value(a);
        else if (a == "--context") context = args.value(a);
        else if (a == "--egl-device") egl_device = args.int_value(a, 0, 15);
        else if (a == "--gl-state-cache") gl_state().set_cache(args.on_off(a));
        else if (a == "--debug-gl") set_debug_gl(true);
        else if (!a.empty() && a[0] == '-') args.fail("unknown option '" + a + "'");
        else if (scene_path.empty()) scene_path = a;
        else args.fail("expected one scene file, got also '" + a + "'");
    }
    if (!has_ext(out, ".png") && !has_ext(out, ".exr") && !has_ext(out, ".tif") && !has_ext(out, ".tiff") &&
        !has_ext(out, ".jpg") && !has_ext(out, ".ppm"))
        args.fail("-o: expected a file ending .png, .exr, .tif, .jpg or .ppm, got '" + out + "'");
    if (!stats_path.empty() && !has_ext(stats_path, ".json"))
        args.fail("--stats: expected a file ending .json, got '" + stats_path + "'");
    if (scene_path.empty()) scene_path = resource_dir("data") + "/default.scene";
    std::optional<LightSpec> light_spec;
    if (!lights_arg.empty() && !(light_spec = parse_light_spec(lights_arg)))
        args.fail("--lights: expected 'own', a count N in [0, 65536], N-overlap (N a multiple of 8) or N-large, got '" +
                  lights_arg + "'");

    // Outputs: whole or none, never an input (scene/output_set.h); refused before the work.
    OutputSet outputs("dsr render");
    outputs.add("-o", out);
    if (!stats_path.empty()) outputs.add("--stats", stats_path);

    const double load_start = now_ms();
    Scene scene = load_scene(scene_path);  // every input error surfaces before any output
    add_scene_inputs(outputs, scene.inputs);
    if (light_spec) scene = bench_scene(scene, *light_spec);  // the bench's lights (bench_scenes.h)
    const double load_ms = now_ms() - load_start;
    const Stage stage("rendering " + scene_path);
    if (out_w == 0) out_w = w, out_h = h;
    const View view = ro.view;
    // The no-FBO path renders its buffers inside the main frame buffer: make it fit both.
    auto ctx = create_context(ContextDesc{context, std::max(w, out_w), std::max(h, out_h), egl_device});
    Caps caps = probe_caps(split_caps(caps_list));
    // depth auto: choose_paths decides (the depth texture where ARB_depth_texture exists).
    const ShaderOptions opts = ro.resolved(scene);
    const PostOptions& post = opts.post;
    const SkipOptions& skip = opts.skip;

    DeferredShader ds(caps, w, h, opts, resource_dir("glsl120"));
    ds.set_scene(scene);
    std::vector<FrameStats> all;
    // With several frames the timed ones do not count (two queries around every light draw are
    // the measurement's cost); one more frame after them counts, its times left out of the medians.
    ds.set_counting(frames == 1);
    for (int f = 0; f < frames; ++f) all.push_back(ds.render(scene, out_w, out_h));
    FrameStats counted = all.back();
    if (frames > 1) {
        ds.set_counting(true);
        counted = ds.render(scene, out_w, out_h);
    }
    if (view != View::final) ds.draw_view(view, out_w, out_h);
    Image img = opaque(read_pixels(out_w, out_h));

    const FrameStats& last = counted;
    auto med = [&](double StageTimes::*field) {
        std::vector<double> v;
        for (auto& s : all) v.push_back(s.ms.*field);
        return median(v);
    };
    nlohmann::ordered_json j;
    j["scene"] = scene_path;
    j["size"] = {w, h};
    j["out_size"] = {out_w, out_h};
    j["view"] = view_name(view);
    j["frames"] = frames;
    j["gl_renderer"] = caps.renderer;
    const Paths& paths = ds.paths();
    j["depth_path"] = paths.depth;
    j["paths"] = {{"depth", paths.depth}, {"gbuffer", paths.gbuffer}, {"render_target", paths.render_target},
                  {"textures", paths.textures}};
    j["caps_forced_off"] = caps.forced_off;
    j["depth_encoding"] = paths.depth_path == DepthPath::packed    ? encoding_name(opts.encoding)
                          : paths.depth_path == DepthPath::texture ? "depth-texture"
                                                                   : paths.depth.c_str();  // position16 | position32
    j["gbuffer_bytes_per_pixel"] = paths.gbuffer_bytes_per_pixel;
    j["lighting"] = opts.listing2_literal ? "listing" : "equations";
    j["skips"] = {{"variants", skip.material_variants}, {"empty_lights", skip.empty_lights},
                  {"light_depth_test", skip.light_depth_test}, {"light_sphere_test", skip.light_sphere_test}};
    j["scissor"] = opts.scissor;
    j["gbuffer"] = opts.gbuffer_half ? "half" : "rgba8";
    j["bloom"] = post.bloom;
    j["aa"] = post.aa;
    j["timing"] = timing_name(last.timing);  // what the per-stage ms below were measured with
    j["gl_state_cache"] = gl_state().cache();
    j["lights_total"] = last.lights_total;
    j["lights_culled"] = last.lights_culled;
    j["lights_drawn"] = last.lights_drawn;
    // null where the GL cannot count them (no occlusion queries / no ARB_pipeline_statistics_query)
    const std::optional<long long> frags = last.counted_light_fragments();
    j["light_fragments"] = frags ? nlohmann::json(*frags) : nlohmann::json(nullptr);
    j["light_invocations"] = last.light_invocations ? nlohmann::json(*last.light_invocations) : nlohmann::json(nullptr);
    j["scissor_pixels"] = last.scissor_pixels;
    j["light_geometry"] = light_geometry_name(paths.light_geometry);  // as run: stencil may fall back to volume
    j["light_geometry_asked"] = light_geometry_name(opts.light_geometry);
    if (!paths.light_geometry_note.empty()) j["light_geometry_note"] = paths.light_geometry_note;
    if (paths.light_geometry == LightGeometry::stencil) j["stencil_faces"] = stencil_faces_name(paths.stencil_faces);
    if (paths.light_geometry == LightGeometry::tiles) j["tiles"] = {{"size", paths.tile_size}, {"lights_per_pass", paths.tile_lights}, {"tile_light_pairs", last.tile_light_pairs}, {"depth_culling", last.tile_depth}, {"depth_ms", last.tile_depth_ms}, {"plan_ms", last.tile_plan_ms}};
    j["depth_bounds"] = paths.depth_bounds;
    j["light_passes"] = last.light_passes;
    // Issue 13: the depth hand-off as run (null: nothing needed it) and the forward stage's work.
    j["depth_handoff"] = paths.accum_depth ? nlohmann::json(depth_handoff_name(paths.depth_handoff)) : nlohmann::json(nullptr);
    j["forward_stage"] = paths.forward_stage;
    j["light_markers"] = last.light_markers;
    j["transparent_objects"] = last.transparent_objects;
    j["transparent_passes"] = last.transparent_passes;
    j["lights_as_quads"] = last.lights_as_quads;
    if (!stats_path.empty()) {  // reads the G-buffer back: only when asked for
        const FrameIdeal ideal = frame_ideal_fragments(ds, scene);
        j["ideal_fragments"] = ideal.fragments ? nlohmann::json(*ideal.fragments) : nlohmann::json(nullptr);
        j["ideal_source"] = ideal.source;
    }
    j["ms"] = {{"geometry", med(&StageTimes::geometry)}, {"ambient", med(&StageTimes::ambient)},
               {"lights", med(&StageTimes::lights)},     {"bloom", med(&StageTimes::bloom)},
               {"aa", med(&StageTimes::aa)},             {"final", med(&StageTimes::final)},
               {"depth_copy", med(&StageTimes::depth_copy)}, {"ssao", med(&StageTimes::ssao)},
               {"forward", med(&StageTimes::forward)},
               {"cpu", med(&StageTimes::cpu)}, {"frame", med(&StageTimes::frame)}};
    const size_t triangles = scene.triangle_count();
    struct rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    j["load_ms"] = load_ms;
    j["triangles"] = triangles;
    j["peak_rss_mb"] = double(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
    j["frame_ms"] = nlohmann::json::array();  // each frame's wall time, in order: ms.frame is their median
    for (const FrameStats& s : all) j["frame_ms"].push_back(s.ms.frame);

    outputs.put_image("-o", out, img);
    // A path that is not UTF-8 (the scene's, given by the user) is written with U+FFFD, not refused.
    if (!stats_path.empty())
        outputs.put_text("--stats", stats_path, j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    outputs.commit();
    std::printf("wrote %s (%dx%d, view %s, depth %s, %d/%d lights drawn, %lld light fragments, frame %.2f ms median of %d)\n",
                out.c_str(), out_w, out_h, view_name(view), j["depth_path"].get<std::string>().c_str(), last.lights_drawn, last.lights_total,
                last.light_fragments, med(&StageTimes::frame), frames);
    return 0;
}

}  // namespace dsr
