// The tiles' GPU timeline (tile_timeline.h).
#include "deferred/tile_timeline.h"

namespace dsr {

void TileTimeline::mark(Mark m) {
    if (!on_) return;
    Set& s = sets_[size_t(current_)];
    if (m == spans_begin || !open_) {  // a new set, or an unfinished one started again
        open_ = true;
        for (GLuint& q : s.q) {
            if (q) stamps_.release(q);
            q = 0;
        }
        s.pending = false;
    }
    if (s.q[size_t(m)]) stamps_.release(s.q[size_t(m)]);
    s.q[size_t(m)] = stamps_.stamp();
}

void TileTimeline::end_frame(TileStats& stats) {
    if (!on_ || !open_) return;
    sets_[size_t(current_)].pending = true;
    open_ = false;
    current_ = (current_ + 1) % kSets;
    sets_[size_t(current_)].pending = false;  // about to be reused: its results, if unread, dropped
    // The newest finished set whose last stamp the GPU has reached.
    for (int age = 1; age < kSets; ++age) {
        Set& s = sets_[size_t((current_ - age + kSets) % kSets)];
        if (!s.pending || !s.q[draws_end] || !GpuStamps::ready(s.q[draws_end])) continue;
        std::array<double, kMarks> ms{};
        for (int m = 0; m < kMarks; ++m)
            if (s.q[size_t(m)]) ms[size_t(m)] = GpuStamps::ms(s.q[size_t(m)]);
        const bool spans = s.q[spans_begin] && s.q[spans_end];
        stats.gpu_spans_ms = spans ? ms[spans_end] - ms[spans_begin] : -1;
        stats.gpu_wait_ms = spans ? ms[draws_begin] - ms[spans_end] : -1;
        stats.gpu_shade_ms = ms[draws_end] - ms[draws_begin];
        for (int older = age; older < kSets; ++older) sets_[size_t((current_ - older + kSets) % kSets)].pending = false;
        return;
    }
}

}  // namespace dsr
