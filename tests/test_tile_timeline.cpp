// The tiles' GPU timeline (deferred/tile_timeline.h): its bookkeeping on the GL at hand (off by
// default on a CPU rasteriser, whose timestamps do not time rasterisation, so switched on here):
// the intervals it reports are the stamps' differences (the wait from the spans' end to the first
// draw, not to the last), a frame without spans reports the draws alone, and nothing is reported
// before a set is finished.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "deferred/tile_timeline.h"
#include "gl/caps.h"
#include "gl/entry_points.h"
#include "render_fixture.h"

namespace dsr {
namespace {

// A mark and its stamp's bracket on the CPU's clock: llvmpipe stamps a timestamp as it processes
// the command, so the stamp lies between the clock read before the mark and the one after glFinish.
// An interval between two stamps then lies between the brackets' inner and outer distances,
// however long a loaded machine keeps the thread away.
struct Stamp {
    double before = 0, after = 0;
};
double now_ms() {
    using namespace std::chrono;
    return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}
Stamp mark_then_wait(TileTimeline& t, TileTimeline::Mark m, int ms) {
    Stamp s;
    s.before = now_ms();
    t.mark(m);
    glFinish();
    s.after = now_ms();
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
    return s;
}
// The interval from stamp a to stamp b lies within the brackets (the clocks' granularity aside).
void expect_interval(double ms, const Stamp& a, const Stamp& b, const char* what) {
    const double slack = 0.5;
    EXPECT_GE(ms, b.before - a.after - slack) << what;
    EXPECT_LE(ms, b.after - a.before + slack) << what;
}

TEST(TileTimeline, ReportsTheIntervalsBetweenItsStamps) {
    auto ctx = create_context(ContextDesc{"osmesa", 16, 16});
    const Caps caps = probe_caps();
    if (!caps.timer_query || !gl_entry.QueryCounter) GTEST_SKIP() << "no timer queries";
    TileTimeline t(true);
    TileStats first;
    t.end_frame(first);  // nothing marked: nothing reported
    EXPECT_EQ(first.gpu_shade_ms, -1);
    // A frame whose spans were measured but whose lights did not go through the tiles (auto): its
    // set is left unfinished, and the next spans start it again.
    mark_then_wait(t, TileTimeline::spans_begin, 1);
    mark_then_wait(t, TileTimeline::spans_end, 1);
    // A full frame: spans 5 ms, wait 30 ms, draws 60 ms on the CPU's clock, each interval held to
    // its stamps' brackets (a wait that ran to the last draw's end would be the draws too long).
    const Stamp spans_begin = mark_then_wait(t, TileTimeline::spans_begin, 5);
    const Stamp spans_end = mark_then_wait(t, TileTimeline::spans_end, 30);
    const Stamp draws_begin = mark_then_wait(t, TileTimeline::draws_begin, 60);
    const Stamp draws_end = mark_then_wait(t, TileTimeline::draws_end, 0);
    TileStats st;
    t.end_frame(st);
    expect_interval(st.gpu_spans_ms, spans_begin, spans_end, "the spans");
    expect_interval(st.gpu_wait_ms, spans_end, draws_begin, "the wait: the spans' end to the first draw");
    expect_interval(st.gpu_shade_ms, draws_begin, draws_end, "the draws");
    // Without spans (no depth culling): the draws alone.
    const Stamp alone_begin = mark_then_wait(t, TileTimeline::draws_begin, 3);
    const Stamp alone_end = mark_then_wait(t, TileTimeline::draws_end, 0);
    TileStats no_spans;
    t.end_frame(no_spans);
    EXPECT_EQ(no_spans.gpu_spans_ms, -1);
    EXPECT_EQ(no_spans.gpu_wait_ms, -1);
    expect_interval(no_spans.gpu_shade_ms, alone_begin, alone_end, "the draws without spans");
    // Off: no queries, nothing reported.
    TileTimeline off(false);
    off.mark(TileTimeline::draws_begin);
    off.mark(TileTimeline::draws_end);
    TileStats none;
    off.end_frame(none);
    EXPECT_EQ(none.gpu_shade_ms, -1);
}

}  // namespace
}  // namespace dsr
