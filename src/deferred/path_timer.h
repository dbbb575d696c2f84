// What a path's passes took, into the auto geometry's calibration (LightCostCalibration): on the
// wall clock, glFinish before and after, as a CPU rasteriser's stages are timed; on GPU
// timestamps (ARB_timer_query's glQueryCounter, which may sit inside the frame timer's
// elapsed-time query), two stamps around the passes, read at a later frame's collect() where the
// GPU has reached them, never waited for. Which draws are timed is AutoPolicy::time_draw's.
#pragma once
#include <functional>
#include <vector>

#include "deferred/auto_policy.h"
#include "deferred/light_cost.h"
#include "gl/caps.h"
#include "gl/gpu_stamps.h"

namespace dsr {

// The clock this GL times a path by: the wall clock on a CPU rasteriser, GL timestamps where they
// time the GPU (gpu_timestamps), else none.
PathClock path_clock(const Caps& caps);

class PathTimer {
public:
    explicit PathTimer(PathClock clock) : clock_(clock) {}
    // The earlier frames' stamps the GPU has reached, into calib; those it has not wait (a few
    // frames' worth; older ones are given up). Once a frame, before its draws.
    void collect(LightCostCalibration& calib);
    // draw(), and where `timed`, what it took against raw_ms (the model's unscaled ms for the
    // path's lights) into calib: now on the wall clock, at a later collect() on GPU stamps.
    void draw(LightPath p, bool timed, double raw_ms, LightCostCalibration& calib, const std::function<void()>& draw);

private:
    struct Pending {  // a GPU measurement not yet read back
        LightPath path;
        GLuint begin, end;
        double raw_ms;
    };
    void release(const Pending& t);

    PathClock clock_;
    GpuStamps stamps_;
    std::vector<Pending> pending_;
};

}  // namespace dsr
