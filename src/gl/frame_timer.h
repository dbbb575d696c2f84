// Per-stage timing that does not serialise a GPU (docs/gpu.md measures both sources). Two sources:
//   gpu-timer  GL_TIME_ELAPSED queries (ARB_timer_query) around each stage, read once after
//              the frame: the GPU's own time per stage, one glFinish per frame.
//   wall       glFinish after each stage and the wall clock: what a software rasteriser needs,
//              since its timer queries do not measure rasterisation (docs/stats.md has the
//              figures).
// choose_timing decides on the running GL by measuring both on the same work.
#pragma once
#include <string>
#include <vector>

#include "gl/caps.h"
#include "gl/gl.h"

namespace dsr {

enum class TimingSource { wall, gpu_timer };
const char* timing_name(TimingSource s);  // "wall" | "gpu-timer"

// What choose_timing measured: the same full-screen passes timed both ways.
struct TimingCheck {
    TimingSource source = TimingSource::wall;
    double query_ms = -1, wall_ms = -1;  // -1: not measured (no timer queries)
    std::string reason;
};

// Timer queries where ARB_timer_query exists and they read at least half the wall-clock time
// of the same passes (drawn into a 1024x1024 target of their own with framebuffer objects;
// else over the current frame buffer of width x height, whose colour they overwrite: call
// before rendering); the wall clock otherwise. Measured once per process (the result is
// kept), unless set_timing_choice forced the choice before.
const TimingCheck& choose_timing(const Caps& caps, int width, int height);
// `--timing measure|wall|gpu-timer` (its default from $DSR_TIMING, app/environment.h): what
// choose_timing decides by; gpu-timer only where the GL has ARB_timer_query.
enum class TimingChoice { measure, wall, gpu_timer };
void set_timing_choice(TimingChoice c);

class FrameTimer {
public:
    explicit FrameTimer(TimingSource source = TimingSource::wall) : source_(source) {}
    ~FrameTimer();
    FrameTimer(const FrameTimer&) = delete;
    FrameTimer& operator=(const FrameTimer&) = delete;

    TimingSource source() const { return source_; }
    void set_source(TimingSource s) { source_ = s; }
    // Starts a frame of `slots` stages (all zero until timed).
    void begin_frame(int slots);
    // Stage `slot` runs between begin and end; stages do not nest.
    void begin(int slot);
    void end();
    // Reads every stage's time (ms) into stage_ms and returns the frame's wall time in ms,
    // from begin_frame until the GPU finished.
    double end_frame(std::vector<double>& stage_ms);

private:
    TimingSource source_;
    double frame_t0_ = 0, stage_t0_ = 0;
    int open_ = -1;
    std::vector<double> ms_;
    std::vector<GLuint> pool_;               // queries, reused across frames
    std::vector<std::pair<int, GLuint>> used_;  // (slot, query) of this frame
};

}  // namespace dsr
