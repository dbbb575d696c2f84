// What one frame of the deferred shader measured: per-stage times and each stage's counts, in one
// small struct per part (the light passes, the tiles, auto's choice, the shadow stage, the forward
// stage, the passes run, the times). Pure data, no GL: render() returns it, `--stats`, the bench
// and the viewer read it; analysis/frame_stats_json.h writes it (docs/stats.md: the schema).
#pragma once
#include <array>
#include <optional>

#include "deferred/ambient_writer.h"
#include "deferred/auto_policy.h"
#include "deferred/light_cost.h"
#include "gl/frame_timer.h"

namespace dsr {

// Per-stage time of one frame, in milliseconds, from the FrameTimer (gl/frame_timer.h):
// GPU timer queries or glFinish + wall clock, as FrameStats::timing says. `frame` is always the
// wall time of render() until the GPU finished.
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

// The light passes: the frame's lights, what the light geometry (docs/light_geometry.md) drew
// and what its passes paid.
struct LightCounts {
    int total = 0, culled = 0, drawn = 0;
    // Samples that passed the light passes (occlusion queries): what survived the in-shader light
    // tests; 0 and not counted when fragments_counted is false (no occlusion queries).
    long long fragments = 0;
    bool fragments_counted = false;
    // Fragments that entered the light shader, summed over the light passes (ARB_pipeline_
    // statistics_query, GL_FRAGMENT_SHADER_INVOCATIONS_ARB): what the passes pay, discards
    // included. Null where the GL lacks the extension, never 0 for "not counted".
    std::optional<long long> invocations;
    // Each light draw's invocations times the lights each of its fragments evaluates, summed: the
    // pixel-light pairs the light passes paid for (light_queries.h), the count to hold against the
    // ideal where a pass shades several lights (screen, tiles). Null where invocations is.
    std::optional<long long> evaluations;
    long long scissor_pixels = 0;  // sum of the rectangles the light quads were limited to
    // The passes drawn (one per light; tiles: one per tile and group of lights), and the lights the
    // volume and stencil geometries drew as quads because their mesh reaches past the far plane,
    // where its back faces would be clipped away.
    int passes = 0;
    int as_quads = 0;
    // fragments as an optional: null where it was not counted.
    std::optional<long long> counted_fragments() const {
        return fragments_counted ? std::optional<long long>(fragments) : std::nullopt;
    }
};

// The tiles (light_geometry_tiles.h); `on` where the frame's light geometry may draw them (tiles,
// auto: draws_tiles), the rest 0 where no tile was planned.
struct TileStats {
    bool on = false;
    long long light_pairs = 0;  // (tile, light) pairs its plan shaded (tile_plan.h)
    // Batches drawn by the form that reads the lights' shared attenuation constants once
    // (ATT_SHARED: light_tiles.frag, light_tiles_flat.frag).
    int att_shared_batches = 0;
    // Batches whose lights the vertex shader read (Paths::tile_fetch_vertex; light_tiles_flat.vert).
    int vertex_batches = 0;
    bool depth = false;  // the plan culled by the tiles' depth spans (tile_depth.h)
    // Wall clock inside the light stage: the depth spans' two passes and read-back (which waits
    // for the G-buffer: on a GPU, a pipeline drain), and the plan with its vertices' upload.
    double depth_ms = 0, plan_ms = 0;
    // The tiles' CPU time by step (thread_cpu_ms, a frame): what the rendering thread spent
    // issuing the depth spans and taking them in (the wait apart), waiting for the GPU to reach
    // the spans' read-back (a driver that spins while it waits spends CPU time; one that sleeps
    // does not), culling (the tiles' boxes and the tiles each light keeps: tile_boxes,
    // tiles_kept), planning (TilePlanner) and uploading (the batches' vertices built and handed
    // to the GL). wait_ms: the same wait on the wall clock.
    double spans_cpu_ms = 0, wait_cpu_ms = 0, cull_cpu_ms = 0, plan_cpu_ms = 0, upload_cpu_ms = 0;
    double wait_ms = 0;
    // On a GPU (tile_timeline.h), ms of an earlier frame's light stage as the GPU ran it: the
    // spans' passes, the spans' end to the first light draw (read-back, plan and the ambient pass
    // drawn meanwhile), the light draws. -1: not measured (a CPU rasteriser, no timer queries,
    // none ready yet).
    double gpu_spans_ms = -1, gpu_wait_ms = -1, gpu_shade_ms = -1;
};

// --light-geometry auto (light_cost.h, auto_policy.h); `on` where the frame's geometry is auto.
// Arrays indexed by the path: lights[at(LightPath::tiles)].
struct AutoStats {
    bool on = false;
    std::array<int, kLightPaths> lights{};  // the lights each path took
    double predicted_ms = 0;  // what the model predicted for the light stage (the spans included)
    double handoff_ms = 0;    // what it priced the depth hand-off at (light_cost.h handoff_ms)
    bool spans = false;       // it measured the tiles' depth spans
    bool quad_depth = false;  // its batched quads drawn against the scene's depth (choose_quad_depth)
    bool kept = false;        // the frame kept the last priced frame's choice unpriced (one path for every light)
    std::optional<LightPath> explored;  // the path this priced frame drew to measure it (exploration_plan)
    std::array<double, kLightPaths> scale = {1, 1, 1};  // each path's calibration scale as used
};

// The shadow stage (shadow_stage.h): maps drawn this frame (a point light's six faces count six;
// maps reused from an earlier frame count none), the triangles drawn into them, and the map
// texels copied into the batched geometries' atlases (shadow_atlas.h; 0 where every atlas already
// held its maps, or none was made).
struct ShadowCounts {
    int maps = 0;
    long long triangles = 0;
    long long atlas_texels = 0;
};

// The forward stage (docs/forward.md): markers drawn, transparent objects blended and their draws.
struct ForwardCounts {
    int light_markers = 0;
    int transparent_objects = 0;
    int transparent_passes = 0;
};

// The pass skips (SkipOptions): whether this frame ran the depth pre-pass (§3.3.1) and the final
// pass (§3.6), and which pass wrote its ambient term (Listing 15; ambient_writer.h).
struct PassesRun {
    bool depth_prepass = true, final = true;
    int gbuffer_clears = 0;  // the G-buffer's colour targets cleared (GbufferClears)
    AmbientWriter ambient = AmbientWriter::pass_before_plan;
    // The depth complexity the pre-pass choice read (depth_prepass.h): fragments that pass the
    // depth test in draw order per pixel covered, as measured in an earlier frame; null before the
    // first measurement or where it is not measured (the skip off, no occlusion queries).
    std::optional<double> depth_complexity;
    bool ambient_in_material() const { return ambient == AmbientWriter::material_pass; }
    // Folded into a full-screen light's pass, or the light geometry's first batch.
    bool ambient_folded() const {
        return ambient == AmbientWriter::light_fold || ambient == AmbientWriter::geometry_first_batch;
    }
    bool ambient_in_handoff() const { return ambient == AmbientWriter::handoff; }
};

struct FrameStats {
    LightCounts lights;
    TileStats tiles;
    AutoStats auto_geometry;
    ShadowCounts shadows;
    ForwardCounts forward;
    PassesRun passes;
    StageTimes ms;
    TimingSource timing = TimingSource::wall;  // what `ms` was measured with
};

}  // namespace dsr
