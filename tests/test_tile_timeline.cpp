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

// A mark, then the CPU away for `ms` (llvmpipe stamps a timestamp as it processes the command,
// after glFinish: the gap shows between this stamp and the next).
void mark_then_wait(TileTimeline& t, TileTimeline::Mark m, int ms) {
    t.mark(m);
    glFinish();
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
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
    // A full frame: spans 5 ms, wait 30 ms, draws 60 ms on the CPU's clock (bounds far enough
    // apart that a sleep overshooting on a loaded machine does not blur which interval is which).
    mark_then_wait(t, TileTimeline::spans_begin, 5);
    mark_then_wait(t, TileTimeline::spans_end, 30);
    mark_then_wait(t, TileTimeline::draws_begin, 60);
    t.mark(TileTimeline::draws_end);
    glFinish();
    TileStats st;
    t.end_frame(st);
    EXPECT_GE(st.gpu_spans_ms, 4.0);
    EXPECT_LT(st.gpu_spans_ms, 25.0);
    EXPECT_GE(st.gpu_wait_ms, 29.0);
    EXPECT_LT(st.gpu_wait_ms, 75.0) << "the wait ran to the last draw's end";
    EXPECT_GE(st.gpu_shade_ms, 59.0);
    EXPECT_LT(st.gpu_shade_ms, 120.0);
    // Without spans (no depth culling): the draws alone.
    mark_then_wait(t, TileTimeline::draws_begin, 3);
    t.mark(TileTimeline::draws_end);
    glFinish();
    TileStats no_spans;
    t.end_frame(no_spans);
    EXPECT_EQ(no_spans.gpu_spans_ms, -1);
    EXPECT_EQ(no_spans.gpu_wait_ms, -1);
    EXPECT_GE(no_spans.gpu_shade_ms, 2.0);
    EXPECT_LT(no_spans.gpu_shade_ms, 20.0);
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
