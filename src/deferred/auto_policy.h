// The auto geometry's rules from frame to frame (light_geometry_auto.cpp draws; this decides), a
// value in and a decision out. Pure: no GL (tests/test_auto_policy.cpp). Four rules:
//   keep     a priced frame that sent every light by quads, or every light by the tiles, and
//            explored nothing, is kept unpriced by the next kKeepFrames frames with as many
//            lights (one frame in kKeepFrames + 1 priced): pricing many lights costs the CPU
//            what a choice that stays the same does not need (docs/gpu.md has the figures);
//   explore  a path not yet measured may be tried, in kExploreFrames frames at most: a path
//            the constants overprice would otherwise never be drawn, so never measured;
//   rest     where the tiles would pay but their depth spans gave them no light, the spans are
//            not measured for the next kSpansRest such frames (the same lights would pay for
//            the spans every frame to learn the same);
//   time     a path's first draw is never timed (the GL compiles its programs then). On the wall
//            clock (a CPU rasteriser, glFinish around the passes) one priced draw of a path in
//            kTimedEvery, its second priced draw the first timed, and an exploring path's every
//            draw; on GPU timestamps, which do not stall the GPU, every draw after the first.
#pragma once
#include <array>
#include <cstddef>
#include <optional>

#include "deferred/light_cost.h"

namespace dsr {

// Arrays indexed by the path: plan.count[at(LightPath::tiles)].
constexpr size_t at(LightPath p) { return size_t(p); }
constexpr std::array<LightPath, kLightPaths> kAllLightPaths = {LightPath::quad, LightPath::volume, LightPath::tiles};

// How the auto geometry times a path's passes (path_timer.h).
enum class PathClock {
    none,        // not at all: the scales stay where they started
    wall,        // glFinish and the wall clock (a CPU rasteriser)
    gpu_stamps,  // GL timestamps, read back frames later (gpu_stamps.h)
};

// Each path measured enough not to be explored (LightCostCalibration::samples).
std::array<bool, kLightPaths> paths_measured(const LightCostCalibration& calib);

class AutoPolicy {
public:
    static constexpr int kKeepFrames = 7;
    static constexpr int kExploreFrames = 4;  // three draws measure a path twice; a fourth where a GPU's stamps were late
    static constexpr int kSpansRest = 8;
    static constexpr int kTimedEvery = 4;

    explicit AutoPolicy(PathClock clock) : clock_(clock) {}

    // keep. Whether a frame of `lights` lights keeps the last priced frame's choice; tiles_cull:
    // the tiles cull by depth spans (a kept tiles frame measures them, as the tiles do).
    bool keeps(size_t lights, bool tiles_cull) const;
    // A frame keeps() allowed: one of the kept frames spent; the path every light takes.
    LightPath keep_frame();
    // A priced frame's choice (its lights per path; whether it explored a path): the path the next
    // frames keep, if any.
    std::optional<LightPath> priced(const std::array<int, kLightPaths>& count, size_t lights, bool explored);
    std::optional<LightPath> kept_path() const { return kept_path_; }

    // explore. The paths a priced frame may explore: those not measured enough, that the frame can
    // draw (`drawable`: volumes where the hand-off exists, the tiles where they were priced), with
    // frames left.
    std::array<bool, kLightPaths> may_explore(const std::array<bool, kLightPaths>& measured,
                                              const std::array<bool, kLightPaths>& drawable) const;
    void explored(LightPath p) { --explore_left_[at(p)]; }

    // rest. A frame where the tiles would pay and cull by depth spans: whether it measures them
    // (false: a resting frame, spent).
    bool measure_spans();
    // Whether the next such frame would measure them.
    bool spans_awake() const { return spans_rest_ == 0; }
    // The spans a settled plan measured gave the tiles no light: they rest.
    void rest_spans() { spans_rest_ = kSpansRest; }
    // An exploring frame measured them: they do not rest.
    void wake_spans() { spans_rest_ = 0; }

    // time. Whether this draw of path p is timed; priced: the model priced its lights above 0
    // (only those calibrate); exploring: the frame explores p.
    bool time_draw(LightPath p, bool priced, bool exploring);

private:
    PathClock clock_;
    std::optional<LightPath> kept_path_;  // every light of the last priced frame took it
    int keep_left_ = 0;                   // kept frames left
    size_t priced_lights_ = 0;            // the lights of the frame that chose it
    std::array<int, kLightPaths> explore_left_ = {kExploreFrames, kExploreFrames, kExploreFrames};
    int spans_rest_ = 0;                                 // resting frames left
    std::array<unsigned, kLightPaths> priced_draws_{};   // each path's priced draws on the wall clock so far
    std::array<bool, kLightPaths> drawn_{};              // each path drawn at least once
};

}  // namespace dsr
