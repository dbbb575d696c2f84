// --depth position16|position32, the G-buffer of LearnOpenGL, the lecture and Vasilovici
// (eye-space position stored in a float target; docs/depth_precision.md). Image tests against the
// depth-texture path, and the one-line refusal when float targets are forced off. choose_paths' side is in tests/test_paths.cpp, the accuracy bounds in
// tests/test_stress.cpp (the ratio and coords cases of both paths).
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_fixture.h"
#include "render_fixture.h"

using namespace dsr;
using namespace dsr::test;

namespace {
constexpr int kSize = 128;
constexpr double kLsb = 1.0 / 255.0;
}  // namespace

// Both position paths shade the default scene like the depth texture: the stored position and
// the one rebuilt from 24-bit depth differ by rounding, well under one 8-bit step of light.
TEST(PipelinePosition, PositionPathsMatchDepthTextureWithinTwoLsb) {
    const Scene s = default_scene();
    const RenderResult tex = render_scene(s, kSize, kSize, with_depth(DepthPath::texture));
    std::printf("[ renderer ] %s\n", tex.renderer.c_str());
    for (DepthPath d : {DepthPath::position16, DepthPath::position32}) {
        const RenderResult pos = render_scene(s, kSize, kSize, with_depth(d));
        SCOPED_TRACE(depth_path_name(d));
        EXPECT_EQ(pos.paths.depth, depth_path_name(d));
        EXPECT_EQ(pos.paths.gbuffer_targets, 4);
        const ImageDiff diff = compare_logged(std::string("texture vs ") + depth_path_name(d), pos.image, tex.image, 2 * kLsb);
        if (diff.max_lsb() > 2) write_failure_images(depth_path_name(d), pos.image, tex.image);
        EXPECT_LE(diff.max_lsb(), 2.0);
        EXPECT_GT(pos.stats.lights.fragments, 0);
    }
}

// EXT_framebuffer_object alone (no-arb-fbo): every target RGBA32F, and the frame still renders.
TEST(PipelinePosition, ExtFramebufferObjectAloneMakesEveryTargetFloat) {
    const Scene s = default_scene();
    const RenderResult r = render_scene(s, 64, 64, with_depth(DepthPath::position32), {"no-arb-fbo"});
    EXPECT_EQ(r.paths.gbuffer_formats, std::vector<TargetFormat>(4, TargetFormat::rgba32f));
    EXPECT_EQ(r.paths.gbuffer_bytes_per_pixel, 68);
    EXPECT_GT(r.stats.lights.fragments, 0);
}

// Forcing float targets off refuses both paths with one line naming what is missing.
TEST(CliPosition, NoFloatRefusesPositionPathsInOneLine) {
    for (const char* d : {"position16", "position32"}) {
        const RunResult r = run("render --size 32x32 -o " + temp_dir() + "/p.png --depth " + std::string(d) + " --caps no-float");
        EXPECT_NE(r.status, 0) << d;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << d << ": " << r.output;
        EXPECT_NE(r.output.find("needs a float G-buffer target"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("forced off: no-float"), std::string::npos) << r.output;
    }
}
