// GL timestamps from a pool (gl/gpu_stamps.h): a released stamp's query is issued again instead
// of a new one, stamps outstanding at once are distinct, and a stamp the GL has reached reads the
// clock when it was issued (llvmpipe stamps as it processes the command: after glFinish, the CPU's
// sleep shows between two stamps).
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "gl/caps.h"
#include "gl/entry_points.h"
#include "gl/gpu_stamps.h"
#include "render_fixture.h"

namespace dsr {
namespace {

TEST(GpuStamps, ReusesReleasedQueriesAndReadsTheClock) {
    auto ctx = create_context(ContextDesc{"osmesa", 16, 16});
    const Caps caps = probe_caps();
    if (!caps.timer_query || !gl_entry.QueryCounter) GTEST_SKIP() << "no timer queries";
    GpuStamps stamps;
    const GLuint a = stamps.stamp();
    glFinish();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const GLuint b = stamps.stamp();
    glFinish();
    EXPECT_NE(a, b) << "two stamps outstanding share a query";
    ASSERT_TRUE(GpuStamps::ready(a));
    ASSERT_TRUE(GpuStamps::ready(b));
    const double gap = GpuStamps::ms(b) - GpuStamps::ms(a);
    EXPECT_GE(gap, 19.0);
    EXPECT_LT(gap, 200.0);
    stamps.release(a);
    const GLuint c = stamps.stamp();
    EXPECT_EQ(c, a) << "a released query was not issued again";
    glFinish();
    EXPECT_GE(GpuStamps::ms(c), GpuStamps::ms(b)) << "the reissued query kept its old result";
    stamps.release(b);
    stamps.release(c);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace dsr
