// Old GL 2.x paths: every combination of the four fallbacks renders the default scene like
// the all-capabilities path. The matrix runs at a small non-power-of-two size here (so the
// power-of-two padding is exercised); `make test-legacy` runs it at 640x480
// (DSR_TEST_SIZE=640x480; also DSR_TEST_SIZE=N for NxN).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "render_fixture.h"

using namespace dsr;
using namespace dsr::test;

namespace {
constexpr double kLsb = 1.0 / 255.0;

// DSR_TEST_SIZE: WxH, or N for NxN; unset: the small default.
void test_size(int& w, int& h) {
    const char* e = std::getenv("DSR_TEST_SIZE");
    if (!e) return;
    char* end = nullptr;
    w = h = int(std::strtol(e, &end, 10));
    if (end && *end == 'x') h = int(std::strtol(end + 1, &end, 10));
    if (w <= 0 || h <= 0 || (end && *end)) {
        ADD_FAILURE() << "DSR_TEST_SIZE: expected WxH or N, got '" << e << "'";
        w = 120, h = 90;
    }
}
// The default options of the matrix: bloom and anti-alias on, the tutorial's quads.
ShaderOptions matrix_options() {
    ShaderOptions opts;
    opts.post.bloom = opts.post.aa = true;  // the post passes sample padded buffers too
    // The tutorial's quads: the light fragments below compare the work, and auto's choice of paths
    // follows the capabilities (without framebuffer objects the tiles cull nothing).
    opts.light_geometry = LightGeometry::quad;
    return opts;
}

// Every combination of the four fallbacks against the all-capabilities image of s.
void check_every_combination(const Scene& s, const ShaderOptions& opts) {
    const char* names[4] = {"no-mrt", "no-depth-texture", "no-fbo", "no-npot"};
    int w = 120, h = 90;
    test_size(w, h);
    auto full = render_scene(s, w, h, opts);
    std::printf("[ renderer ] %s, %dx%d, bloom + anti-alias on%s\n", full.renderer.c_str(), w, h,
                opts.shadow_lights ? ", shadows" : "");
    std::printf("[ matrix   ] %-45s %-8s %-10s %-5s %-5s %8s %9s %8s\n", "forced off", "depth", "gbuffer", "rt",
                "tex", "max LSB", "mean LSB", "> 2 LSB");
    for (int mask = 0; mask < 16; ++mask) {
        std::vector<std::string> off;
        for (int b = 0; b < 4; ++b)
            if (mask & (1 << b)) off.push_back(names[b]);
        ShaderOptions o = opts;
        o.depth = (mask & 2) ? DepthPath::packed : DepthPath::texture;  // what `auto` picks
        RenderResult r;
        ASSERT_NO_THROW(r = render_scene(s, w, h, o, off)) << "mask " << mask;  // GL errors throw
        std::string label;
        for (auto& n : off) label += (label.empty() ? "" : ",") + n;
        ImageDiff d = compare_images(r.image, full.image, 2 * kLsb);
        std::printf("[ matrix   ] %-45s %-8s %-10s %-5s %-5s %8.1f %9.4f %7.3f%%\n",
                    label.empty() ? "(none)" : label.c_str(), r.paths.depth.c_str(), r.paths.gbuffer.c_str(),
                    r.paths.render_target.c_str(), r.paths.textures.c_str(), d.max_lsb(), d.mean_lsb(),
                    100 * d.failing_fraction());
        EXPECT_EQ(r.paths.gbuffer, (mask & 1) || (mask & 4) ? "per-target" : "mrt") << label;
        EXPECT_EQ(r.paths.depth, (mask & 2) ? "packed" : "texture") << label;
        EXPECT_EQ(r.paths.render_target, (mask & 4) ? "copy" : "fbo") << label;
        EXPECT_EQ(r.paths.textures, (mask & 8) ? "pow2" : "npot") << label;
        // Same lights, same fragments: the fallbacks change where bytes live, not what is lit. The
        // packed codec and the copied depth (no-fbo) rebuild positions that differ in the last
        // bits, so a pixel whose surface point lies on a light's sphere to within float rounding
        // may fall on either side: at 640x480 one fragment in 194459 did. At most 1 in 10^5.
        const long long tol = std::max(1LL, full.stats.lights.fragments / 100000);
        EXPECT_LE(std::llabs(r.stats.lights.fragments - full.stats.lights.fragments), tol) << label;
        // Tolerance: the depth paths differ by rounding (1 LSB), the copy path by up to 3; the pow2
        // path's bloom add keeps to the content's edge texels (post_stage.cpp, draw_quad_clamped).
        EXPECT_LE(d.max_lsb(), 8.0) << label;
        EXPECT_LE(d.failing_fraction(), 0.01) << label;
        if (d.max_lsb() > 8.0 || d.failing_fraction() > 0.01)
            write_failure_images(std::string(opts.shadow_lights ? "fallback_shadow_" : "fallback_") + std::to_string(mask),
                                 r.image, full.image);
    }
}
}  // namespace

TEST(Fallbacks, EveryCombinationMatchesFullCapabilities) { check_every_combination(default_scene(), matrix_options()); }

// The same with the first light casting shadows (docs/shadows.md): without framebuffer objects its
// six faces are drawn in the main frame buffer, piece by piece (a 768 x 512 atlas in 120 x 90), and
// copied into the map; without depth textures they are packed.
TEST(Fallbacks, EveryCombinationMatchesFullCapabilitiesWithShadows) {
    Scene s = default_scene();
    s.lights[0].shadow.on = true;
    s.lights[0].shadow.size = 256;
    ShaderOptions opts = matrix_options();
    opts.shadow_lights = true;
    check_every_combination(s, opts);
    // The shadow is in the picture (149 pixels over 2 LSB at 120x90), so the maps are compared too.
    Scene plain = s;
    plain.lights[0].shadow.on = false;
    EXPECT_GT(compare_images(render_scene(s, 120, 90, opts).image, render_scene(plain, 120, 90, opts).image, 2 * kLsb).failing, 50);
}
