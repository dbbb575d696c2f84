// A second rasterizer: Mesa's softpipe renders the same scene as llvmpipe. Both run as
// separate `dsr render` processes (GALLIUM_DRIVER is read when the driver loads).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "analysis/image_metrics.h"
#include "cli_fixture.h"
#include "scene/image.h"

using namespace dsr::test;

namespace {
// Renders `scene` (empty: the default scene) with both drivers; returns (softpipe, llvmpipe).
std::pair<dsr::Image, dsr::Image> both_drivers(const std::string& scene, const std::string& tag) {
    std::string d = temp_dir();
    const std::string args = " render " + scene + " --size 128x96 --no-bloom --no-aa -o ";
    EXPECT_EQ(std::system(("GALLIUM_DRIVER=llvmpipe " + dsr_binary() + args + d + "/llvm.png >/dev/null").c_str()), 0);
    EXPECT_EQ(std::system(("GALLIUM_DRIVER=softpipe " + dsr_binary() + args + d + "/soft.png >/dev/null").c_str()), 0);
    return {dsr::load_image(d + "/soft.png"), dsr::load_image(d + "/llvm.png")};
}
}  // namespace

TEST(Legacy, SoftpipeIsTheRenderer) {
    EXPECT_EQ(std::system(("GALLIUM_DRIVER=softpipe " + dsr_binary() + " info | grep -q 'GL_RENDERER    softpipe'").c_str()), 0)
        << "GALLIUM_DRIVER=softpipe did not select softpipe";
}

// Constant materials: the two rasterizers agree to rounding (both IEEE float).
TEST(Legacy, SoftpipeAgreesWithLlvmpipeOnAnalyticScene) {
    auto [soft, llvm] = both_drivers(std::string(DSR_SOURCE_DIR) + "/tests/data/analytic.scene", "analytic");
    dsr::ImageDiff diff = dsr::compare_images(soft, llvm, 1.0 / 255.0);
    std::printf("[ image    ] analytic scene, softpipe vs llvmpipe: max %.1f LSB, mean %.4f LSB, %lld/%lld pixels over 1 LSB\n",
                diff.max_lsb(), diff.mean_lsb(), diff.failing, diff.pixels);
    EXPECT_LE(diff.max_lsb(), 1.001);  // 1 LSB, with room for the float reading of it
    EXPECT_LE(diff.mean_lsb(), 0.1);
}

// Textured: the drivers filter mipmapped textures differently (LOD and filtering details),
// so textured surfaces differ by several LSB while constant ones agree; the bound is on the
// mean, with the maximum logged.
TEST(Legacy, SoftpipeAgreesWithLlvmpipeOnDefaultScene) {
    auto [soft, llvm] = both_drivers("", "default");
    dsr::ImageDiff diff = dsr::compare_images(soft, llvm, 2.0 / 255.0);
    std::printf("[ image    ] default scene, softpipe vs llvmpipe: max %.1f LSB, mean %.4f LSB, %lld/%lld pixels over 2 LSB\n",
                diff.max_lsb(), diff.mean_lsb(), diff.failing, diff.pixels);
    EXPECT_LE(diff.mean_lsb(), 1.0);
    EXPECT_LE(diff.max_lsb(), 24.0);
    EXPECT_LE(diff.failing_fraction(), 0.15);
}
