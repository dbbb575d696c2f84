// `--light-geometry auto`: each light by the cheapest way for it, from a cost model. Pure: no GL.
// The model prices what each geometry pays for a light (docs/light_geometry.md, "auto"):
//   quad    a draw, and every pixel of its scissor rectangle through the light shader (§3.4.2)
//   volume  a draw of its mesh, and the rectangle's pixels rasterised and depth-tested, most
//           rejected before the shader; once a frame the depth hand-off
//   tiles   per tile it keeps after depth culling, its share of the tile's passes (G-buffer read
//           and blend once per group of lights, divided among the tile's lights) and its own term
//           in the shader's loop; once a frame the depth spans
// Given the per-light prices, choose_light_paths finds the assignment of least total cost, the
// per-frame costs included (it tries every set of paths in use). The constants
// are a GL's: default_light_costs gives the ones measured on a CPU rasteriser and on a GPU, and the
// auto geometry scales each geometry's by what its passes took in the frames before
// (LightCostCalibration), so the model follows the running GL.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "deferred/scissor.h"
#include "deferred/tile_plan.h"

namespace dsr {

enum class LightPath { quad, volume, tiles };
constexpr int kLightPaths = 3;
const char* light_path_name(LightPath p);  // "quad", "volume", "tiles"

// Milliseconds per draw and per million pixels.
struct LightCostModel {
    double quad_draw_ms = 0, quad_mpx_ms = 0;      // per light; per Mpx of its scissor rectangle
    // Per Mpx of its rectangle where the quad is drawn against the scene's depth (LightQuadBatch's
    // scene_depth: surfaces behind the light rejected before its shader).
    double quad_depth_mpx_ms = 0;
    double volume_draw_ms = 0, volume_mpx_ms = 0;  // per light; per Mpx of its scissor rectangle
    // The depth hand-off, per Mpx of the screen (once): a blit, or a gl_FragDepth pass (Paths::depth_handoff).
    double handoff_mpx_ms = 0, handoff_pass_mpx_ms = 0;
    // Where the hand-off's pass writes the ambient term (Paths::ambient_in_handoff), the frame draws
    // no ambient pass: the hand-off then costs its pass (handoff_ambient_mpx_ms) less the ambient
    // pass it replaces (ambient_mpx_ms), per Mpx of the screen; handoff_ms below.
    double handoff_ambient_mpx_ms = 0, ambient_mpx_ms = 0;
    // Not constants but the frame's (the auto geometry sets them): whether its hand-off is a pass,
    // and whether that pass writes the ambient term.
    bool handoff_pass = false, handoff_writes_ambient = false;
    double spans_mpx_ms = 0;                       // the tiles' depth spans, per Mpx of the screen (once)
    double tile_pass_mpx_ms = 0;                   // tiles: per Mpx of tile pixels per pass (read, blend)
    double tile_light_mpx_ms = 0;                  // tiles: per Mpx of (tile pixel, light) pairs
    double path_ms = 0;                            // once per path a frame uses (its state, its sync)
    // A shadowed light's lookup (shadow.glsl), per Mpx of the pixels it is priced at on any path
    // (its rectangle; the tiles it keeps): paid alike by every path, so it prices the frame more
    // than it moves the choice.
    double shadow_mpx_ms = 0;
    // The spans are measured only where the lights would cost more than this many times the spans
    // without tiles: below it, tiles cannot win back what finding out costs.
    double spans_worth = 4;
    // A path not yet measured (LightCostCalibration::samples below kExploreSamples) is tried in a
    // frame whose plan by it is predicted within this factor of the best (exploration_plan): else
    // a path the constants overprice is never drawn, so never measured, and stays overpriced. 2:
    // wide enough for the overpricing the bench scenes show (docs/light_cost.md, "explore_within").
    double explore_within = 2;
};

// Measured with `dsr render --frames N --stats` per geometry, on a CPU rasteriser (software) or a
// GPU; where and on what: docs/light_cost.md.
LightCostModel default_light_costs(bool software_rasterizer);
// The constants, one per line (dsr info).
std::string describe(const LightCostModel& m);

// What the depth hand-off adds to a frame of screen_px pixels: its blit or pass, or where it writes
// the ambient term, that pass less the ambient pass it spares the frame (never below 0).
double handoff_ms(const LightCostModel& m, double screen_px);

// What the model knows of one light.
struct LightFeature {
    double rect_px = 0;        // its scissor rectangle's pixels (the whole screen for a full one)
    bool volume_ok = true;     // its mesh can serve it (light_mesh.h past_far: not directional, not past far)
    bool tiles_ok = true;      // the tiles geometry may take it
    bool shadowed = false;     // it has a shadow map (LightCostModel::shadow_mpx_ms)
    // Tiles: the tiles it keeps (indices into the tile grid, row by row) after depth culling.
    std::vector<int> tiles;
};

// The frame's tiles as the model sees them.
struct TileGrid {
    int tile_px = 256;                // pixels of a whole tile (tile_size^2)
    int lights_per_pass = 32;
    std::vector<int> lights;          // per tile: how many lights keep it (over every light of the frame)
};

// The per-light tiles cover: for each light, the tiles its rectangle overlaps whose box its sphere
// reaches (depth culling as tile_plan.h TileDepth; without `depth`, every tile the rectangle
// overlaps), and per tile how many lights keep it. rects: the lights' scissor rectangles.
void tile_cover(const std::vector<ScissorRect>& rects, int width, int height, int tile_size, const TileDepth* depth,
                std::vector<LightFeature>& lights, TileGrid& grid);

// One light's price on each path (infinity where it cannot take that path), per-frame costs excluded.
std::array<double, kLightPaths> light_prices(const LightFeature& l, const TileGrid& grid, const LightCostModel& m,
                                             const std::array<double, kLightPaths>& scale);

struct LightPathPlan {
    std::vector<LightPath> path;                    // per light
    std::array<int, kLightPaths> count{};           // lights per path
    std::array<double, kLightPaths> predicted_ms{}; // per path, its per-frame cost included
    double predicted_total_ms = 0;
    // Its quads are drawn against the scene's depth, and priced so (choose_light_paths given the
    // savings): the hand-off is in predicted_ms, with the volumes' where there are any, else the quads'.
    bool quads_depth = false;
};

// Each light's saving where its quad is drawn against the scene's depth: its rectangle at
// quad_depth_mpx_ms instead of quad_mpx_ms, unscaled; 0 for a shadowed light (drawn alone, without it).
std::vector<double> quad_depth_savings(const std::vector<LightFeature>& lights, const LightCostModel& m);

// Each light's prices, unscaled (light_prices with scales 1), for choose_light_paths below.
using LightPrices = std::vector<std::array<double, kLightPaths>>;
LightPrices price_lights(const std::vector<LightFeature>& lights, const TileGrid& grid, const LightCostModel& m);

// The assignment of least predicted cost. screen_px: the frame's pixels (the per-frame costs);
// spans_paid: the spans are already measured (their cost is sunk); scale: each path's calibration.
// A path is left out entirely where `allowed` says so.
LightPathPlan choose_light_paths(const std::vector<LightFeature>& lights, const TileGrid& grid, double screen_px,
                                 const LightCostModel& m, const std::array<double, kLightPaths>& scale,
                                 const std::array<bool, kLightPaths>& allowed, bool spans_paid);
// The same from prices price_lights gave (each scaled here): the auto geometry prices once a frame.
// quad_depth_saving, when given (quad_depth_savings): the quads may also be drawn against the scene's
// depth, each for its quad price less its saving, the frame paying the hand-off for them (once: the
// volumes' hand-off serves them too); the plan says which (quads_depth).
LightPathPlan choose_light_paths(const LightPrices& raw, double screen_px, const LightCostModel& m,
                                 const std::array<double, kLightPaths>& scale,
                                 const std::array<bool, kLightPaths>& allowed, bool spans_paid,
                                 const std::vector<double>* quad_depth_saving = nullptr);

// A frame that measures a path the calibration has not measured enough (explore[p]): each light
// that can take the path takes it, the others keep their path in `best`. Of the paths to explore, the one whose plan
// is predicted cheapest, where that is within m.explore_within of best's (scale: as choose_light_paths';
// spans_paid: whether best already paid the spans). nullopt: none.
struct LightExploration {
    LightPath path = LightPath::quad;
    LightPathPlan plan;
};
std::optional<LightExploration> exploration_plan(const LightPrices& raw, const LightPathPlan& best, double screen_px,
                                                 const LightCostModel& m, const std::array<double, kLightPaths>& scale,
                                                 const std::array<bool, kLightPaths>& explore, bool spans_paid);

// Whether a plan's quads are drawn against the scene's depth: what that saves them (their pixels at
// quad_depth_mpx_ms instead of quad_mpx_ms; shadowed quads are drawn one by one without it)
// against the depth hand-off, which is paid already where the plan has volumes; always where the
// plan was priced so (quads_depth).
struct QuadDepthChoice {
    bool on = false;
    double raw_saving_ms = 0;  // the quads' saving, unscaled (what their raw prices drop by)
    double handoff_ms = 0;     // the hand-off this choice adds to the frame (0 where volumes pay it)
};
QuadDepthChoice choose_quad_depth(const LightPathPlan& plan, const std::vector<LightFeature>& lights,
                                  double screen_px, const LightCostModel& m, double quad_scale);

// Whether measuring the spans is worth it: the best plan without tiles costs more than
// spans_worth times the spans.
bool spans_worth_measuring(double best_without_tiles_ms, double screen_px, const LightCostModel& m);

// Each path's scale: measured / predicted ms of its passes, smoothed over frames (an exponential
// average, clamped to [0.1, 10]). A path not drawn in a frame keeps its scale. The default start,
// 1, is a guess: a path's first measurement replaces it (averaged with it, the 2.7x error the
// constants had on 32-large's tiles on one llvmpipe would take four timed frames to fall under
// 1.2x).
class LightCostCalibration {
public:
    LightCostCalibration() = default;
    // Starting scales, e.g. from DSR_LIGHT_COST_SCALE="quad,volume,tiles" (parse_cost_scale): given,
    // not guessed, so the measurements are averaged with them from the first.
    explicit LightCostCalibration(const std::array<double, kLightPaths>& start)
        : scale_(start), given_(true) {}
    const std::array<double, kLightPaths>& scale() const { return scale_; }
    // Measurements of path p so far (given scales: as many as exploring wants, kExploreSamples).
    int samples(LightPath p) const { return given_ ? kExploreSamples : samples_[size_t(p)]; }
    // What an exploring path is drawn for (light_geometry_auto.cpp): one timed draw on a noisy
    // machine may decide against the path (llvmpipe's tiles on the default scene measured at
    // 0.44-0.96 of the model in single draws), so two, averaged.
    static constexpr int kExploreSamples = 2;
    // One frame's measurement of a path's passes against what the model predicted for them, both
    // without the scale (raw model ms).
    void add(LightPath p, double measured_ms, double predicted_raw_ms);

private:
    std::array<double, kLightPaths> scale_{1, 1, 1};
    std::array<int, kLightPaths> samples_{0, 0, 0};
    bool given_ = false;  // scale_ started from given scales, not the guess
};

// "Q,V,T": three positive numbers, each path's starting scale (DSR_LIGHT_COST_SCALE: a large one keeps a
// path out, for measuring the others); throws dsr::Error naming what was expected.
std::array<double, kLightPaths> parse_cost_scale(const std::string& text);

}  // namespace dsr
