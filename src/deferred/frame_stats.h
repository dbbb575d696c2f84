// What one frame of the deferred shader measured: per-stage times and the light passes' counts.
// Pure data, no GL: render() returns it, `--stats`, the bench and the viewer read it.
#pragma once
#include <optional>

#include "gl/frame_timer.h"

namespace dsr {

// Per-stage time of one frame, in milliseconds, from the FrameTimer (gl/frame_timer.h):
// GPU timer queries or glFinish + wall clock, as `timing` says. `frame` is always the wall
// time of render() until the GPU finished.
struct StageTimes {
    double geometry = 0, ambient = 0, lights = 0, bloom = 0, aa = 0, final = 0, frame = 0;
    double ssao = 0;        // the SSAO pass and its blur (0 with --ssao off)
    double depth_copy = 0;  // the depth hand-off: the G-buffer's depth onto P-buffer 0 (0 where not needed)
    double forward = 0;     // the forward stage: light markers and transparent surfaces (0 where not run)
    double shadows = 0;     // the shadow stage: every shadow map of the frame (0 where none is drawn)
    // CPU time of the rendering thread from the start of render() to its end-of-frame wait: the
    // submission cost (draw calls, state, uniforms). With glFinish-timed stages (llvmpipe) the
    // waits in between are in it as far as they spin; with timer queries (a GPU) they are not there.
    double cpu = 0;
    // Two parts of `cpu`: make_frame (culling, scissor rectangles, light parameters) and the
    // lighting stage (the light geometry's plan, the ambient pass, the light passes' submission).
    double cpu_make_frame = 0, cpu_lights = 0;
};

struct FrameStats {
    int lights_total = 0, lights_culled = 0, lights_drawn = 0;
    long long light_fragments = 0;  // samples that passed the light passes (occlusion queries): what
                                    // survived the in-shader light tests; 0 and not counted when
                                    // fragments_counted is false (no occlusion queries)
    bool fragments_counted = false;
    // Fragments that entered the light shader, summed over the light passes (ARB_pipeline_
    // statistics_query, GL_FRAGMENT_SHADER_INVOCATIONS_ARB): what the passes pay, discards
    // included. Null where the GL lacks the extension, never 0 for "not counted".
    std::optional<long long> light_invocations;
    // Each light draw's invocations times the lights each of its fragments evaluates, summed: the
    // pixel-light pairs the light passes paid for (light_queries.h), the count to hold against the
    // ideal where a pass shades several lights (screen, tiles). Null where light_invocations is.
    std::optional<long long> light_evaluations;
    // light_fragments as an optional: null where it was not counted.
    std::optional<long long> counted_light_fragments() const {
        return fragments_counted ? std::optional<long long>(light_fragments) : std::nullopt;
    }
    long long scissor_pixels = 0;   // sum of the rectangles the light quads were limited to
    // The light geometry (docs/light_geometry.md): the passes drawn (one per light; tiles: one per
    // tile and group of lights), the lights the volume and stencil geometries drew as quads because
    // their mesh reaches past the far plane, where its back faces would be clipped away.
    int light_passes = 0;
    int lights_as_quads = 0;
    long long tile_light_pairs = 0;  // tiles: (tile, light) pairs its plan shaded (tile_plan.h)
    // tiles, screen: batches drawn by the form that reads the lights' shared attenuation constants
    // once (ATT_SHARED: light_tiles.frag, light_tiles_flat.frag, light_screen.frag).
    int att_shared_batches = 0;
    // tiles: batches whose lights the vertex shader read (Paths::tile_fetch_vertex; light_tiles_flat.vert).
    int tile_vertex_batches = 0;
    bool tile_depth = false;         // tiles: the plan culled by the tiles' depth spans (tile_depth.h)
    // tiles, wall clock inside the light stage: the depth spans' two passes and read-back (which
    // waits for the G-buffer: on a GPU, a pipeline drain), and the plan with its vertices' upload.
    double tile_depth_ms = 0, tile_plan_ms = 0;
    // tiles on a GPU (tile_timeline.h), ms of an earlier frame's light stage as the GPU ran it: the
    // spans' passes, the spans' end to the first light draw (read-back, plan and the ambient pass
    // drawn meanwhile), the light draws. -1: not measured (a CPU rasteriser, no timer queries, none
    // ready yet).
    double tile_gpu_spans_ms = -1, tile_gpu_wait_ms = -1, tile_gpu_shade_ms = -1;
    // --light-geometry auto (light_cost.h): the lights each path took (quad, volume, tiles), what
    // the model predicted for the light stage (ms, the spans included), whether it measured the
    // tiles' depth spans, and each path's calibration scale as used.
    bool auto_geometry = false;
    int auto_lights[3] = {0, 0, 0};
    double auto_predicted_ms = 0;
    double auto_handoff_ms = 0;    // what the model priced the depth hand-off at (light_cost.h handoff_ms)
    bool auto_spans = false;
    bool auto_quad_depth = false;  // its batched quads drawn against the scene's depth (choose_quad_depth)
    bool auto_kept = false;        // the frame kept the last priced frame's choice unpriced (one path for every light)
    int auto_explored = -1;        // the path (LightPath) this priced frame drew to measure it (light_cost.h exploration_plan), else -1
    double auto_scale[3] = {1, 1, 1};
    // The forward stage (docs/forward.md): markers drawn, transparent objects blended and their draws.
    int light_markers = 0;
    int transparent_objects = 0;
    int transparent_passes = 0;
    // The shadow stage (shadow_stage.h): maps drawn this frame (a point light's six faces count
    // six; maps reused from an earlier frame count none) and the triangles drawn into them.
    int shadow_maps = 0;
    long long shadow_triangles = 0;
    // The batched geometries' shadow atlases (shadow_atlas.h): map texels copied into them this
    // frame (0 where every atlas already held its maps, or none was made).
    long long shadow_atlas_texels = 0;
    // The pass skips (SkipOptions): whether this frame ran the depth pre-pass (§3.3.1) and the
    // final pass (§3.6), and whether its ambient pass (Listing 15) was written by the material pass
    // (SkipOptions::ambient_target) or folded into a full-screen light's pass.
    bool depth_prepass_ran = true, final_pass_ran = true, ambient_in_material = false, ambient_folded = false;
    bool ambient_in_handoff = false;  // the depth hand-off's pass wrote the ambient term (Paths::ambient_in_handoff)
    // The depth complexity the pre-pass choice of this frame read (depth_prepass.h): fragments that
    // pass the depth test in draw order per pixel covered, as measured in an earlier frame; null
    // before the first measurement or where it is not measured (the skip off, no occlusion queries).
    std::optional<double> depth_complexity;
    StageTimes ms;
    TimingSource timing = TimingSource::wall;
};

}  // namespace dsr
