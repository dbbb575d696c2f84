// Whether GL_FRAGMENT_SHADER_INVOCATIONS_ARB counts fragments that the stencil test rejects: the
// bench's stencil goal (docs/benchmarks.md: light_invocations <= 1.25 x ideal) can judge a geometry only on a
// GL that counts the fragments that reached the shader. Mesa's llvmpipe adds 16 per 4x4 block on
// entering its fragment function, before its depth and stencil tests (lp_state_fs.c:
// "Could use popcount on mask, but pixel accuracy is not required"; lp_query.c multiplies the
// count by LP_RASTER_BLOCK_SIZE squared); an NVIDIA GPU tests the stencil first.
#pragma once
#include <optional>
#include <string>

namespace dsr {

struct InvocationProbe {
    long long pixels = 0;       // the quad drawn, every pixel of which fails the stencil test
    long long invocations = 0;  // GL_FRAGMENT_SHADER_INVOCATIONS_ARB over that draw
    long long samples = 0;      // GL_SAMPLES_PASSED over that draw: 0 unless the stencil test is broken
    bool counts_rejected() const { return invocations > 0; }
};

// Draws a size x size quad into the current framebuffer, which must have stencil bits, with the
// stencil test GL_NEVER, counting both queries. nullopt where the GL lacks
// ARB_pipeline_statistics_query or occlusion queries, or the framebuffer has no stencil. Leaves the
// GL state as the state cache knows it.
std::optional<InvocationProbe> probe_invocation_counter(const std::string& shader_dir, int size = 64);

}  // namespace dsr
