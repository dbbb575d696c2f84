// The auto geometry's rules from frame to frame (auto_policy.h).
#include "deferred/auto_policy.h"

namespace dsr {

std::array<bool, kLightPaths> paths_measured(const LightCostCalibration& calib) {
    std::array<bool, kLightPaths> m{};
    for (const LightPath p : kAllLightPaths) m[at(p)] = calib.samples(p) >= LightCostCalibration::kExploreSamples;
    return m;
}

bool AutoPolicy::keeps(size_t lights, bool tiles_cull) const {
    return kept_path_ && keep_left_ > 0 && lights == priced_lights_ && (*kept_path_ != LightPath::tiles || tiles_cull);
}

LightPath AutoPolicy::keep_frame() {
    --keep_left_;
    return *kept_path_;
}

std::optional<LightPath> AutoPolicy::priced(const std::array<int, kLightPaths>& count, size_t lights, bool explored) {
    kept_path_.reset();
    for (const LightPath p : {LightPath::quad, LightPath::tiles})
        if (!explored && lights > 0 && count[at(p)] == int(lights)) kept_path_ = p;
    keep_left_ = kept_path_ ? kKeepFrames : 0;
    priced_lights_ = lights;
    return kept_path_;
}

std::array<bool, kLightPaths> AutoPolicy::may_explore(const std::array<bool, kLightPaths>& measured,
                                                      const std::array<bool, kLightPaths>& drawable) const {
    std::array<bool, kLightPaths> e{};
    for (const LightPath p : kAllLightPaths) e[at(p)] = explore_left_[at(p)] > 0 && !measured[at(p)] && drawable[at(p)];
    return e;
}

bool AutoPolicy::measure_spans() {
    if (spans_rest_ == 0) return true;
    --spans_rest_;
    return false;
}

bool AutoPolicy::time_draw(LightPath p, bool priced, bool exploring) {
    const bool first = !drawn_[at(p)];
    drawn_[at(p)] = true;
    // Priced draws are counted from a path's first, so its second is the first timed.
    const bool counted_turn = clock_ == PathClock::wall && priced && priced_draws_[at(p)]++ % kTimedEvery == 1;
    if (first) return false;
    switch (clock_) {
        case PathClock::wall: return priced && (counted_turn || exploring);
        case PathClock::gpu_stamps: return true;
        case PathClock::none: return false;
    }
    return false;
}

}  // namespace dsr
