// The analytic reference (src/analysis/analytic_reference.h) checked by hand, then the forward
// and deferred renderers measured against it on tests/data/analytic.scene (planes and spheres,
// constant materials, two lights). Every measured number is printed.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "analysis/analytic_reference.h"
#include "dsr_error.h"
#include "forward_fixture.h"

using namespace dsr;
using namespace dsr::test;

namespace {
constexpr int kSize = 128;
constexpr double kLsb = 1.0 / 255.0;

Scene analytic_scene() { return load_scene(resource_dir("tests") + "/data/analytic.scene"); }

// The best an 8-bit image can do: the reference rounded to the nearest code. Measuring an 8-bit
// render against it counts whole codes; against the float reference the unavoidable output
// rounding (<= 0.5 LSB) is included.
Image rounded(Image img) {
    for (float& v : img.rgba) v = std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f;
    return img;
}

double excluded_fraction(const std::vector<uint8_t>& mask) {
    size_t n = 0;
    for (uint8_t m : mask) n += !m;
    return double(n) / double(mask.size());
}

ImageDiff logged_masked(const std::string& name, const Image& a, const Image& b, const std::vector<uint8_t>& mask,
                        double thr) {
    ImageDiff d = compare_images_masked(a, b, mask, thr);
    std::printf("[ image    ] %s: max %.2f LSB, mean %.4f LSB, %lld/%lld interior pixels over %.1f LSB\n",
                name.c_str(), d.max_lsb(), d.mean_lsb(), d.failing, d.pixels, thr * 255);
    return d;
}

// A plane seen from straight above, one light above its centre: at the centre pixel (odd size,
// so its ray is the axis) l = v = h = n = +Y, and everything is computable by hand.
Scene plane_from_above() {
    Scene s;
    s.camera.pos = {0, 5, 0};
    s.camera.target = {0, 0, 0};
    s.camera.up = {0, 0, -1};
    s.camera.fov_deg = 60;
    s.camera.near_plane = 0.5f;
    s.camera.far_plane = 20;
    s.ambient = glm::vec3(0.1f);
    s.background = {0.25f, 0.5f, 0.75f};
    Material m;
    m.name = "m";
    m.diffuse = glm::vec3(0.5f);
    m.specular = glm::vec3(0.25f);
    m.shininess = 10;
    s.materials.push_back(m);
    s.meshes.push_back(make_plane(4, {0, 0, 0}, 0));
    s.lights.push_back({{0, 1, 0}, {1, 1, 1}, 2.0f});
    return s;
}
}  // namespace

TEST(Analytic, HandComputedPixels) {
    Scene s = plane_from_above();
    const int n = 65;
    AnalyticTrace t = analytic_trace(s, n, n);
    // Centre: ambient 0.1*0.5 + att (1 - 1/2) * (diffuse 1*0.5 + specular 1^10*0.25) = 0.425.
    EXPECT_NEAR(t.image.at(32, 32)[0], 0.425, 1e-6);
    EXPECT_EQ(t.mesh[32 * n + 32], 0);
    // The plane (4 wide, 5 below a 60-degree camera) does not reach the corners: background.
    EXPECT_EQ(t.mesh[0], -1);
    EXPECT_FLOAT_EQ(t.image.at(0, 0)[2], 0.75f);
    // A pixel whose point is beyond the light's radius sees the ambient term only: 0.05.
    // Pixel i has ray x = ((i + 0.5)/n*2 - 1) * tan(30deg), hitting the plane at 5x from the axis.
    const int i = 53;
    const double x = ((i + 0.5) / n * 2 - 1) * std::tan(3.14159265358979 / 6) * 5;
    ASSERT_LT(x, 2.0);                     // on the plane
    ASSERT_GT(std::sqrt(x * x + 1), 2.0);  // distance to the light > S_radius
    EXPECT_EQ(t.mesh[32 * n + i], 0);
    EXPECT_NEAR(t.image.at(i, 32)[0], 0.05, 1e-6);
    // Back faces are culled, as in GL: seen from below, the plane vanishes.
    Scene below = s;
    below.camera.pos = {0, -5, 0};
    below.camera.up = {0, 0, 1};
    EXPECT_EQ(analytic_trace(below, n, n).mesh[32 * n + 32], -1);
}

TEST(Analytic, RejectsTextureMaps) {
    EXPECT_THROW(analytic_reference(default_scene(), 8, 8), Error);
}

// The forward renderer against the trace: the same triangles and pixel-centre sampling, so the
// only differences are float against double arithmetic and the 8-bit output. Interior pixels
// (3x3 neighbourhood on one mesh in the trace): within the output rounding (measured max 0.50
// LSB, mean 0.16). All pixels: a pixel or so on a silhouette where GL's float edge test and the
// exact one disagree (measured 1 of 16384 over 2 LSB), bounded at 0.1%.
TEST(Analytic, ForwardMatchesTrace) {
    Scene s = analytic_scene();
    auto t0 = std::chrono::steady_clock::now();
    AnalyticTrace tr = analytic_trace(s, kSize, kSize);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const auto mask = interior_mask(tr, kSize, kSize);
    std::printf("[ stats    ] trace %dx%d in %.1f ms; %.2f%% of pixels on silhouettes excluded\n", kSize, kSize, ms,
                100 * excluded_fraction(mask));
    EXPECT_LE(excluded_fraction(mask), 0.06);
    for (ForwardMode mode : {ForwardMode::single, ForwardMode::multi}) {
        const char* name = mode == ForwardMode::single ? "forward single" : "forward multi";
        auto fwd = render_forward(s, kSize, kSize, forward_mode(mode));
        ImageDiff in = logged_masked(std::string(name) + " vs trace", fwd.image, tr.image, mask, kLsb);
        ImageDiff all = compare_logged(std::string(name) + " vs trace, all pixels", fwd.image, tr.image, 2 * kLsb);
        if (in.max_lsb() > 0.75) write_failure_images("forward_vs_trace", fwd.image, tr.image);
        EXPECT_LE(in.max_lsb(), 0.75);
        EXPECT_LE(in.mean_lsb(), 0.3);
        EXPECT_LE(all.failing_fraction(), 0.001);
    }
}

// Issue 6: "analytic scene within 2 LSB for the depth-texture path". On interior pixels the
// deferred image is within 2 codes of the correctly rounded reference (measured max 2 at 96,
// 128 and 256; against the float reference max 2.07 LSB at 128, 1 pixel of 15650 just over 2).
// The error is the deferred path's quantisation (next test), not geometry: the forward renderer
// on the same triangles is within 0.5 LSB. Silhouette pixels are excluded as above; over all
// pixels at most 0.1% may be over 2 LSB (measured 2 of 16384).
TEST(Analytic, DeferredDepthTextureWithinTwoLsb) {
    Scene s = analytic_scene();
    AnalyticTrace tr = analytic_trace(s, kSize, kSize);
    const auto mask = interior_mask(tr, kSize, kSize);
    ShaderOptions tex;
    tex.depth = DepthPath::texture;
    auto def = render_scene(s, kSize, kSize, tex);
    std::printf("[ renderer ] %s\n", def.renderer.c_str());
    ImageDiff q = logged_masked("deferred (depth texture) vs rounded trace", def.image, rounded(tr.image), mask,
                                2 * kLsb);
    ImageDiff f = logged_masked("deferred (depth texture) vs trace", def.image, tr.image, mask, 2 * kLsb);
    ImageDiff all = compare_logged("deferred (depth texture) vs trace, all pixels", def.image, tr.image, 2 * kLsb);
    if (q.max_lsb() > 2) write_failure_images("deferred_vs_trace", def.image, tr.image);
    EXPECT_LE(q.max_lsb(), 2.0);
    EXPECT_LE(f.failing_fraction(), 0.001);
    EXPECT_LE(f.mean_lsb(), 0.3);
    EXPECT_LE(all.failing_fraction(), 0.001);

    // The packed path rebuilds the same 24-bit depth codes (tests/test_pipeline.cpp); logged.
    ShaderOptions packed;
    packed.depth = DepthPath::packed;
    auto pk = render_scene(s, kSize, kSize, packed);
    ImageDiff p = logged_masked("deferred (packed depth) vs rounded trace", pk.image, rounded(tr.image), mask,
                                2 * kLsb);
    EXPECT_LE(p.max_lsb(), 2.0);
}

// Where the deferred error comes from: the trace with the deferred path's roundings switched on
// one at a time (AnalyticOptions). Measured at 128 (interior, max / mean LSB against the plain
// trace): 8-bit normals 1.70 / 0.059, 8-bit materials and shininess code 0.32 / 0.096, 8-bit
// accumulation of the 3 passes 1.32 / 0.216, all three 2.10 / 0.244; the deferred render is
// 2.07 / 0.247. Against the full model the deferred image is off by 0 codes on 91%, 1 code on
// 8.5% of channels (mean 0.054 LSB), a rare 2-3 (0.10% of pixels) where float and double land
// on opposite sides of a rounding step (a normal component one code off moves a highlight). So the model accounts for the error: the deferred path's mean error
// against the model must be well under its mean error against the reference.
TEST(Analytic, DeferredErrorIsGBufferAndPassQuantisation) {
    Scene s = analytic_scene();
    AnalyticTrace tr = analytic_trace(s, kSize, kSize);
    const auto mask = interior_mask(tr, kSize, kSize);
    AnalyticOptions normals, materials, passes, model;
    normals.gbuffer_normals_8bit = true;
    materials.gbuffer_materials_8bit = true;
    passes.passes_8bit = true;
    model.gbuffer_normals_8bit = model.gbuffer_materials_8bit = model.passes_8bit = true;
    logged_masked("trace, 8-bit normals vs trace", analytic_trace(s, kSize, kSize, normals).image, tr.image, mask,
                  2 * kLsb);
    logged_masked("trace, 8-bit materials vs trace", analytic_trace(s, kSize, kSize, materials).image, tr.image,
                  mask, 2 * kLsb);
    logged_masked("trace, 8-bit passes vs trace", analytic_trace(s, kSize, kSize, passes).image, tr.image, mask,
                  2 * kLsb);
    const Image m = analytic_trace(s, kSize, kSize, model).image;
    logged_masked("trace, all three vs trace", m, tr.image, mask, 2 * kLsb);

    auto def = render_scene(s, kSize, kSize, ShaderOptions{});
    ImageDiff vs_ref = compare_images_masked(def.image, tr.image, mask, 2 * kLsb);
    ImageDiff vs_model = logged_masked("deferred vs model", def.image, m, mask, 1.5 * kLsb);
    EXPECT_LE(vs_model.mean_lsb(), 0.1);
    // Measured 0.10% of pixels off by 2 codes or more; a 5% error in the shininess decode
    // (exp2(11a) * 1.05 in lighting.glsl) gave 0.56%.
    EXPECT_LE(vs_model.failing_fraction(), 0.003);
    EXPECT_LE(vs_model.max_lsb(), 4.0);
    EXPECT_LT(vs_model.mean_lsb(), 0.5 * vs_ref.mean_lsb());
}
