// A path's passes timed into the auto geometry's calibration (path_timer.h).
#include "deferred/path_timer.h"

#include "dsr_clock.h"
#include "gl/gl.h"

namespace dsr {

PathClock path_clock(const Caps& caps) {
    if (caps.software_rasterizer) return PathClock::wall;
    return gpu_timestamps(caps) ? PathClock::gpu_stamps : PathClock::none;
}

void PathTimer::collect(LightCostCalibration& calib) {
    std::vector<Pending> busy;
    for (const Pending& t : pending_) {
        if (!GpuStamps::ready(t.end)) {
            busy.push_back(t);
            continue;
        }
        if (t.raw_ms > 0) calib.add(t.path, GpuStamps::ms(t.end) - GpuStamps::ms(t.begin), t.raw_ms);
        release(t);
    }
    pending_.clear();
    for (const Pending& t : busy) {
        if (pending_.size() < 3 * kLightPaths)
            pending_.push_back(t);
        else
            release(t);
    }
}

void PathTimer::draw(LightPath p, bool timed, double raw_ms, LightCostCalibration& calib,
                     const std::function<void()>& draw) {
    if (!timed || clock_ == PathClock::none) {
        draw();
        return;
    }
    if (clock_ == PathClock::gpu_stamps) {
        const GLuint begin = stamps_.stamp();
        draw();
        pending_.push_back(Pending{p, begin, stamps_.stamp(), raw_ms});
        return;
    }
    glFinish();
    const double t0 = now_ms();
    draw();
    glFinish();
    calib.add(p, now_ms() - t0, raw_ms);
}

void PathTimer::release(const Pending& t) {
    stamps_.release(t.begin);
    stamps_.release(t.end);
}

}  // namespace dsr
