// The tiles geometry's light stage as the GPU ran it (TileStats::gpu_*; `--stats`
// tiles.gpu_*): four GL timestamps a frame (ARB_timer_query's glQueryCounter), at the start of the
// depth spans' passes, at their end (before the read-back), before the first light draw and after
// the last. The GPU stamps each when it reaches it, so the second interval is what the GPU spent
// between the spans and the light draws: the read-back and the CPU's plan of the first batch, and
// the ambient pass, which is drawn there (DeferredShader::draw_lights); the rest of it the GPU
// waited. Read back a frame or more later, where the GPU has finished, never waited for. Off on a
// CPU rasteriser, whose timer queries do not time its rasterisation.
#pragma once
#include <array>

#include "deferred/frame_stats.h"
#include "gl/gpu_stamps.h"

namespace dsr {

class TileTimeline {
public:
    enum Mark { spans_begin, spans_end, draws_begin, draws_end, kMarks };

    explicit TileTimeline(bool on) : on_(on) {}
    TileTimeline(const TileTimeline&) = delete;
    TileTimeline& operator=(const TileTimeline&) = delete;
    // A timestamp of this frame's set. spans_begin starts a set (a frame whose spans were measured
    // but whose lights did not go through the tiles left its set unfinished: it is started again);
    // draws_begin without spans starts one too (no depth culling).
    void mark(Mark m);
    // After the draws: this frame's set is finished, and the intervals of the latest finished set
    // the GPU has done with go into stats (left at -1 where none is ready).
    void end_frame(TileStats& stats);

private:
    static constexpr int kSets = 4;  // frames in flight at most; an older set not read is dropped
    struct Set {
        std::array<GLuint, kMarks> q{};  // the stamps of this set (0: not issued)
        bool pending = false;            // finished, not yet read
    };
    bool on_;
    GpuStamps stamps_;
    std::array<Set, kSets> sets_;
    int current_ = 0;
    bool open_ = false;  // sets_[current_] has marks of this frame
};

}  // namespace dsr
