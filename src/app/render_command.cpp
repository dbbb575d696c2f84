// `dsr render`: scene file -> Scene -> DeferredShader::render -> main buffer -> image file.
#include <algorithm>
#include <optional>
#include <cstdio>
#include <cstdlib>

#include <sys/resource.h>

#include <nlohmann/json.hpp>

#include "dsr_clock.h"
#include "analysis/bench_scenes.h"
#include "app/commands.h"
#include "analysis/frame_ideal.h"
#include "analysis/frame_stats_json.h"
#include "app/files.h"
#include "analysis/terminal_text.h"
#include "app/command_table.h"
#include "app/stage.h"
#include "deferred/deferred_shader.h"
#include "deferred/main_buffer_map.h"
#include "gl/caps.h"
#include "gl/check.h"
#include "gl/state.h"
#include "gl/readback.h"
#include "platform/context.h"
#include "platform/resources.h"
#include "scene/framing.h"
#include "scene/scene.h"
#include "scene/shadow_budget.h"

namespace dsr {

namespace {

using json = nlohmann::ordered_json;

// --lights N-shadow / own-shadow: the shadow maps' budget, at the texel size and clamp the
// shadow stage will allocate with (scene/shadow_budget.h), before any is made.
void check_shadow_budget(const RenderSettings& flags, const Scene& scene, const ShaderOptions& opts, const Caps& caps) {
    if (!(flags.lights && flags.lights->set == LightSet::shadow && opts.shadow_lights)) return;
    GLint max_texture = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
    const int texel_bytes = shadow_texel_bytes(shadow_maps_packed(caps), caps.fbo);
    const ShadowBudgetUse use = shadow_budget_use(scene.lights, texel_bytes, std::max(64, int(max_texture)));
    if (use.over)
        throw Error("dsr render: --lights: expected " +
                    shadow_budget_text(scene.lights[use.light], use.before, texel_bytes, std::max(64, int(max_texture))) +
                    " (light " + std::to_string(use.light + 1) + " of " + std::to_string(scene.lights.size()) + ")");
}

// The frames rendered: every one's stats, and the counted frame's.
struct RenderedFrames {
    std::vector<FrameStats> all;
    FrameStats counted;
};

RenderedFrames render_frames(DeferredShader& ds, const Scene& scene, int frames, int out_w, int out_h) {
    RenderedFrames r;
    // With several frames the timed ones do not count (two queries around every light draw are
    // the measurement's cost); one more frame after them counts, its times left out of the medians.
    ds.set_counting(frames == 1);
    for (int f = 0; f < frames; ++f) r.all.push_back(ds.render(scene, out_w, out_h));
    r.counted = r.all.back();
    if (frames > 1) {
        ds.set_counting(true);
        r.counted = ds.render(scene, out_w, out_h);
    }
    return r;
}

// The image to write. A float image file (.exr, .tif) of a float P-buffer 0 without an operator
// holds the light as it is, past 1 (docs/hdr.md; `linear`); every other output is the 8-bit main
// frame buffer's.
struct OutputImage {
    Image image;
    bool linear = false;
};

OutputImage read_output_image(DeferredShader& ds, const ShaderOptions& opts, View view, const std::string& out,
                              int out_w, int out_h) {
    const std::string ext = image_extension(out);
    const bool float_file = ext == ".exr" || ext == ".tif" || ext == ".tiff";
    OutputImage o;
    o.linear = view == View::final && float_file && opts.hdr.float_accum() && opts.hdr.tonemap == ToneMap::none &&
               !opts.hdr.output_srgb;
    o.image = opaque(o.linear ? ds.read_output_linear(out_w, out_h)
                     : view == View::final ? ds.read_output(out_w, out_h)
                                           : read_pixels(out_w, out_h));
    return o;
}

// The --stats keys that say what ran: the scene and sizes, the GL, the paths, the skips and the
// passes' settings.
void put_configuration(json& j, const RenderSettings& flags, const std::string& scene_path, const Scene& scene,
                       int out_w, int out_h, const Caps& caps, const Paths& paths, const ShaderOptions& opts) {
    const SkipOptions& skip = opts.skip;
    j["scene"] = scene_path;
    j["warnings"] = scene.warnings.size();  // what the readers substituted or ignored (stderr has each)
    j["size"] = {flags.width, flags.height};
    j["out_size"] = {out_w, out_h};
    j["view"] = view_name(flags.options.view);
    j["frames"] = flags.frames;
    j["gl_renderer"] = caps.renderer;
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
                  {"light_depth_test", skip.light_depth_test}, {"light_sphere_test", skip.light_sphere_test},
                  {"depth_prepass", skip.depth_prepass},
                  {"ambient_target", skip.ambient_target}, {"ambient", skip.ambient_pass}, {"final", skip.final_pass},
                  {"gbuffer_clears", skip.gbuffer_clears}};
    j["scissor"] = opts.scissor;
    j["gbuffer"] = opts.gbuffer_half ? "half" : "rgba8";
    j["bloom"] = opts.post.bloom;
    j["aa"] = opts.post.aa;
    j["gl_state_cache"] = gl_state().cache();
}

// The reported frame's stats (docs/stats.md) and the light geometry as run: the tiles' settings
// beside their counts, auto's choice against the light stage as measured.
void put_frame(json& j, const FrameStats& last, const std::vector<FrameStats>& all, const Paths& paths,
               const ShaderOptions& opts) {
    // The lights' counts, the passes run, the forward and shadow stages' counts, `tiles` and
    // `auto` where the geometry draws them, `timing` and `ms`.
    j.update(frame_stats_json(last));
    j["light_geometry"] = light_geometry_name(paths.light_geometry);  // as run: stencil may fall back to volume
    j["light_geometry_asked"] = light_geometry_name(opts.light_geometry);
    if (!paths.light_geometry_note.empty()) j["light_geometry_note"] = paths.light_geometry_note;
    if (paths.light_geometry == LightGeometry::stencil) j["stencil_faces"] = stencil_faces_name(paths.stencil_faces);
    if (draws_tiles(paths.light_geometry)) {  // the settings as run, beside the frame's counts
        j["tiles"]["size"] = paths.tile_size;
        j["tiles"]["lights_per_pass"] = paths.tile_lights;
        j["tiles"]["shape"] = paths.tile_points ? "points" : "quads";
        j["tiles"]["fetch"] = paths.tile_fetch_vertex ? "vertex" : "fragment";
    }
    // What the cost model chose (light_cost.h) against the light stage as measured (both medians
    // of the timed frames), and how many timed frames kept a choice or explored a path.
    if (last.auto_geometry.on) {
        j["auto"]["measured_lights_ms"] = last.ms.lights;
        j["auto"]["kept_frames"] = std::count_if(all.begin(), all.end(), [](const FrameStats& s) { return s.auto_geometry.kept; });
        j["auto"]["explored_frames"] =
            std::count_if(all.begin(), all.end(), [](const FrameStats& s) { return s.auto_geometry.explored.has_value(); });
    }
}

// High dynamic range, the depth hand-off and the forward stage, the shadow stage's settings.
void put_stages(json& j, const DeferredShader& ds, const Paths& paths, const ShaderOptions& opts, const Caps& caps,
                bool linear) {
    // High dynamic range (docs/hdr.md): the accumulation format, the operator and the exposure,
    // with the scale the counted frame's final pass applied (2^stops, or --exposure auto's).
    j["hdr"] = {{"accum", accum_format_name(opts.hdr.accum)}, {"tonemap", tone_map_name(opts.hdr.tonemap)},
                {"exposure_stops", opts.hdr.exposure}, {"exposure_auto", opts.hdr.exposure_auto},
                {"exposure_scale", ds.exposure_scale()}, {"output_srgb", opts.hdr.output_srgb},
                {"float_image", linear}};  // the image file holds P-buffer 0's values past 1
    j["depth_bounds"] = paths.depth_bounds;
    // The depth hand-off as run (docs/forward.md) (null: nothing needed it) and the forward stage's work.
    j["depth_handoff"] = paths.accum_depth ? nlohmann::json(depth_handoff_name(paths.depth_handoff)) : nlohmann::json(nullptr);
    j["forward_stage"] = paths.forward_stage;
    // The shadow stage (docs/shadows.md): maps drawn in the counted frame (a point light's six
    // faces count six) and the triangles drawn into them (without framebuffer objects once per
    // piece of the main frame buffer that draws them); the filter and the maps' format.
    j["shadows"] = opts.shadow_lights;
    j["shadow_filter"] = shadow_filter_name(opts.shadows.filter);
    j["shadow_map_format"] = !opts.shadow_lights ? nlohmann::json(nullptr)
                             : !shadow_maps_packed(caps) ? nlohmann::json("depth-texture")
                                                         : nlohmann::json("packed-rgb8");
}

// The ideal pixel-light pairs (read back from the G-buffer: only when --stats asks) and the
// world-space bounds of what is drawn (scene/framing.h: what `camera fit` frames).
void put_ideal_and_bounds(json& j, DeferredShader& ds, const Scene& scene) {
    const FrameIdeal ideal = frame_ideal_fragments(ds, scene);
    j["ideal_fragments"] = ideal.fragments ? nlohmann::json(*ideal.fragments) : nlohmann::json(nullptr);
    j["ideal_source"] = ideal.source;
    const SceneBounds b = scene_bounds(scene);
    auto v3 = [](const glm::dvec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); };
    j["bounds"] = b.vertices && b.finite ? nlohmann::json{{"min", v3(b.min)}, {"max", v3(b.max)},
                                                          {"centre", v3(b.centre)}, {"radius", b.radius}}
                                         : nlohmann::json(nullptr);
}

// The run's own costs: reading the scene, the triangles a frame, peak memory, each frame's time.
void put_run_costs(json& j, const Scene& scene, double load_ms, const std::vector<FrameStats>& all) {
    const size_t triangles = scene.triangle_count();
    struct rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    j["load_ms"] = load_ms;
    j["triangles"] = triangles;
    j["peak_rss_mb"] = double(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
    j["frame_ms"] = nlohmann::json::array();  // each frame's wall time, in order: ms.frame is their median
    for (const FrameStats& s : all) j["frame_ms"].push_back(s.ms.frame);
}

}  // namespace

int cmd_render(const std::vector<std::string>& argv) {
    RenderSettings flags;  // the render command's table (app/command_table.h)
    flags.options.shader.light_cost_scale = light_cost_scale_from_environment();  // --light-cost-scale's default
    parse_command_line(render_command(flags), argv);
    const std::string out = flags.output(), stats_path = flags.stats;
    const std::string scene_path = flags.scene.empty() ? resource_dir("data") + "/default.scene" : flags.scene;
    const int w = flags.width, h = flags.height, frames = flags.frames;
    int out_w = flags.out_width, out_h = flags.out_height;
    const RenderOptions& ro = flags.options;

    // Outputs: whole or none, never an input (scene/output_set.h); refused before the work.
    OutputSet outputs("dsr render");
    if (flags.out.empty()) outputs.make_dir("-o", kOutDir);  // the default's folder, kept only with the image
    outputs.add("-o", out);
    if (!stats_path.empty()) outputs.add("--stats", stats_path);

    const double load_start = now_ms();
    Scene scene = load_scene(scene_path, flags.load);  // every input error surfaces before any output
    add_scene_inputs(outputs, scene.inputs);
    if (flags.lights) scene = bench_scene(scene, *flags.lights);  // the bench's lights (bench_scenes.h)
    const double load_ms = now_ms() - load_start;
    const Stage stage("rendering " + scene_path);
    if (out_w == 0) out_w = w, out_h = h;
    const View view = ro.view;
    // The no-FBO path renders its buffers inside the main frame buffer: make it fit both.
    auto ctx = create_context(context_desc(flags.context, std::max(w, out_w), std::max(h, out_h)));
    Caps caps = probe_caps(split_caps(caps_with_environment(flags.caps)));
    // depth auto: choose_paths decides (the depth texture where ARB_depth_texture exists).
    const ShaderOptions opts = ro.resolved(scene);
    check_shadow_budget(flags, scene, opts, caps);

    DeferredShader ds(caps, w, h, opts, resource_dir("glsl120"));
    ds.set_scene(scene);
    // Headless: the image is read back, never shown, so the final pass may be left out (final_pass).
    ds.set_read_back(view == View::final);
    const RenderedFrames frames_run = render_frames(ds, scene, frames, out_w, out_h);
    const std::vector<FrameStats>& all = frames_run.all;
    if (view != View::final) ds.draw_view(view, scene.camera, out_w, out_h);
    const OutputImage img = read_output_image(ds, opts, view, out, out_w, out_h);

    // The counted frame's counts with the timed frames' medians for its times (frame_stats_json.h).
    const FrameStats last = reported_frame(all, frames_run.counted);
    const Paths& paths = ds.paths();
    json j;
    put_configuration(j, flags, scene_path, scene, out_w, out_h, caps, paths, opts);
    put_frame(j, last, all, paths, opts);
    put_stages(j, ds, paths, opts, caps, img.linear);
    if (!stats_path.empty()) put_ideal_and_bounds(j, ds, scene);  // reads the G-buffer back: only when asked for
    put_run_costs(j, scene, load_ms, all);

    outputs.put_image("-o", out, img.image);
    // A path that is not UTF-8 (the scene's, given by the user) is written with U+FFFD, not refused.
    if (!stats_path.empty())
        outputs.put_text("--stats", stats_path, j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    outputs.commit();
    // Two lines, each within the terminal's width (a long output path wrapped: terminal_text.h).
    char line[4096];
    std::snprintf(line, sizeof line,
                  "wrote %s (%dx%d, view %s, depth %s)\n  %d/%d lights drawn, %lld light fragments, frame %.2f ms median of %d\n",
                  out.c_str(), out_w, out_h, view_name(view), j["depth_path"].get<std::string>().c_str(), last.lights.drawn,
                  last.lights.total, last.lights.fragments, last.ms.frame, frames);
    std::fputs(wrap_lines(line).c_str(), stdout);
    return 0;
}

}  // namespace dsr
