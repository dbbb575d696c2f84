// The invocation-counter probe (gl/invocation_probe.h): a quad all of whose fragments fail the
// stencil test passes no sample; what the invocation counter says of it is the GL's own behaviour.
// On llvmpipe it is the evidence behind the bench's "cannot be judged on this GL" for the stencil
// goal: 16 per 4x4 block and triangle, counted on entering the fragment function, before the
// stencil test.
#include <gtest/gtest.h>

#include "gl/caps.h"
#include "gl/invocation_probe.h"
#include "platform/context.h"
#include "platform/resources.h"

using namespace dsr;

TEST(InvocationProbe, RejectedQuadPassesNoSample) {
    auto ctx = create_context(ContextDesc{"osmesa", 256, 128});  // larger than the probe's quad
    const Caps caps = probe_caps();
    const std::optional<InvocationProbe> p = probe_invocation_counter(resource_dir("glsl120"), 64);
    if (!caps.pipeline_statistics) {
        EXPECT_FALSE(p);
        GTEST_SKIP() << "no ARB_pipeline_statistics_query";
    }
    ASSERT_TRUE(p);
    EXPECT_EQ(p->pixels, 64 * 64);
    EXPECT_EQ(p->samples, 0);  // the stencil test rejected every fragment
    std::printf("[ probe    ] %s: %lld invocations for %lld rejected pixels\n", caps.renderer.c_str(), p->invocations,
                p->pixels);
    if (caps.renderer.find("llvmpipe") != std::string::npos) {
        // 16 for every 4x4 block each of the quad's two triangles touches, before the stencil test:
        // 256 blocks, the 16 on the diagonal twice (measured: 4352).
        EXPECT_EQ(p->invocations % 16, 0);
        EXPECT_EQ(p->invocations, 16 * (256 + 16));
        EXPECT_TRUE(p->counts_rejected());
    }
}
