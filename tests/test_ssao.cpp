// SSAO (docs/ssao.md, Vasilovici §5): the kernel as pure math (ssao_kernel.h), then images of a box
// on a floor with and without --ssao on both depth paths and the copy render-target path
// (--caps no-fbo): creases darken, the open floor stays, no pixel brightens, SSAO off (or at
// strength 0) is exactly the image without it; and the CLI refuses bad values in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cli_fixture.h"
#include "deferred/ssao_kernel.h"
#include "dsr_error.h"
#include "render_fixture.h"

using namespace dsr;
using namespace dsr::test;

TEST(SsaoKernel, InsideTheHemisphereDeterministicAndScaledTowardsTheCentre) {
    for (int n : {4, 8, 16, 32, 64}) {
        const std::vector<glm::vec3> k = ssao_kernel(n);
        ASSERT_EQ(int(k.size()), n);
        EXPECT_EQ(k, ssao_kernel(n)) << "not deterministic";
        for (const glm::vec3& s : k) {
            const float len = glm::length(s);
            EXPECT_LE(len, 1.0f + 1e-6f);
            EXPECT_GT(len, 0.0f);
            EXPECT_GE(s.z, kSsaoMinZ * len - 1e-6f) << "in or below the tangent plane";
        }
        // Towards the centre: the first quarter's samples are shorter than the last quarter's.
        double first = 0, last = 0;
        const int q = std::max(1, n / 4);
        for (int i = 0; i < q; ++i) first += glm::length(k[size_t(i)]), last += glm::length(k[size_t(n - 1 - i)]);
        EXPECT_LT(first, 0.5 * last) << n << " samples";
    }
    EXPECT_NE(ssao_kernel(16), ssao_kernel(16, 7)) << "the seed is ignored";
    const std::vector<glm::vec3> r = ssao_rotations();
    ASSERT_EQ(int(r.size()), kSsaoTile * kSsaoTile);
    for (const glm::vec3& v : r) {
        EXPECT_NEAR(glm::length(v), 1.0f, 1e-5f);
        EXPECT_EQ(v.z, 0.0f);
    }
    EXPECT_EQ(r, ssao_rotations());
}

namespace {
constexpr int kN = 128;

// A white unit box on a white floor, looked at from above and in front; a strong ambient
// (0.6) so its occlusion shows, one light.
Scene box_on_floor() {
    Scene s;
    s.camera.pos = {0, 2.2f, 3.2f};
    s.camera.target = {0, 0.2f, 0};
    s.camera.near_plane = 0.1f;
    s.camera.far_plane = 40.0f;
    s.background = {0.1f, 0.1f, 0.3f};
    s.ambient = {0.6f, 0.6f, 0.6f};
    Material m;
    m.name = "white";
    m.diffuse = {0.9f, 0.9f, 0.9f};
    m.specular = {0.2f, 0.2f, 0.2f};
    s.materials.push_back(m);
    add_plane(s, 12.0f, {0, 0, 0}, 0);
    add_box(s, {1, 1, 1}, {0, 0.5f, 0}, 0);
    s.lights.push_back({{1.5f, 3, 2}, {0.3f, 0.3f, 0.3f}, 8.0f});
    return s;
}

struct Case {
    const char* name;
    DepthPath depth;
    std::vector<std::string> caps;
    int scale;
};

int lsb(const Image& im, int x, int y, int c) { return int(std::lround(im.rgba[size_t(4 * (y * im.width + x) + c)] * 255.0f)); }

// The window pixel of a world point (row 0 at the bottom, as read_pixels gives).
glm::ivec2 pixel_of(const Scene& s, glm::vec3 world) {
    const glm::vec4 c = s.camera.projection(1.0f) * s.camera.view() * glm::vec4(world, 1);
    return {int((c.x / c.w * 0.5f + 0.5f) * kN), int((c.y / c.w * 0.5f + 0.5f) * kN)};
}

// Mean and largest darkening (off - on, LSB over rgb) in a (2r+1)^2 window about p.
struct Darkening {
    double mean = 0;
    int most = 0;
};
Darkening darkening(const Image& off, const Image& on, glm::ivec2 p, int r) {
    Darkening d;
    int n = 0;
    for (int y = p.y - r; y <= p.y + r; ++y)
        for (int x = p.x - r; x <= p.x + r; ++x)
            for (int c = 0; c < 3; ++c) {
                const int v = lsb(off, x, y, c) - lsb(on, x, y, c);
                d.mean += v;
                d.most = std::max(d.most, std::abs(v));
                ++n;
            }
    d.mean /= n;
    return d;
}

// The case's depth path, SSAO off; with_ssao: on at the case's scale and `strength`.
ShaderOptions on_path(const Case& c) {
    ShaderOptions o;
    o.depth = c.depth;
    return o;
}
ShaderOptions with_ssao(const Case& c, float strength) {
    ShaderOptions o = on_path(c);
    o.ssao.on = true;
    o.ssao.scale = c.scale;
    o.ssao.strength = strength;
    return o;
}

class Ssao : public ::testing::TestWithParam<Case> {};
}  // namespace

TEST_P(Ssao, DarkensCreasesNotTheOpenFloorAndNeverBrightens) {
    const Case& c = GetParam();
    const Scene s = box_on_floor();
    const ShaderOptions off = on_path(c), on = with_ssao(c, 1.0f);
    const RenderResult a = render_scene(s, kN, kN, off, c.caps);
    const RenderResult b = render_scene(s, kN, kN, on, c.caps);
    ASSERT_EQ(b.paths.depth_path, c.depth);
    long long brighter = 0;
    for (int y = 0; y < kN; ++y)
        for (int x = 0; x < kN; ++x)
            for (int ch = 0; ch < 4; ++ch) brighter += lsb(b.image, x, y, ch) > lsb(a.image, x, y, ch);
    EXPECT_EQ(brighter, 0) << "channels SSAO made brighter";
    // The crease in front of the box: floor pixels just in front of its bottom front edge.
    const glm::ivec2 crease = pixel_of(s, {0, 0, 0.56f});
    const Darkening dc = darkening(a.image, b.image, crease, 2);
    EXPECT_GE(dc.mean, 4.0) << "crease at " << crease.x << "," << crease.y << " darkened by " << dc.mean << " LSB";
    // Open floor, 1.3 units (2.6 radii) and more from the box.
    for (glm::vec3 w : {glm::vec3(-1.8f, 0, -1.2f), glm::vec3(1.8f, 0, -1.2f), glm::vec3(0, 0, 1.8f), glm::vec3(0, 0, -6)}) {
        const glm::ivec2 p = pixel_of(s, w);
        ASSERT_TRUE(p.x >= 3 && p.y >= 3 && p.x < kN - 3 && p.y < kN - 3) << "not in view: " << p.x << "," << p.y;
        const Darkening d = darkening(a.image, b.image, p, 3);
        EXPECT_LE(d.most, 1) << "open floor at " << p.x << "," << p.y;
    }
    if (::testing::Test::HasFailure()) {
        write_failure_images(std::string("ssao_") + c.name, b.image, a.image);
    }
    EXPECT_GT(b.stats.ms.ssao, 0.0) << "the ssao stage is not timed";
    EXPECT_EQ(a.stats.ms.ssao, 0.0);
}

// SSAO off renders exactly the image without it, whatever its parameters; at strength 0 the AO
// buffer is 1 everywhere and the ambient pass's multiply changes nothing.
TEST_P(Ssao, OffOrStrengthZeroIsExactlyTheImageWithout) {
    const Case& c = GetParam();
    const Scene s = box_on_floor();
    const ShaderOptions plain = on_path(c), zero = with_ssao(c, 0.0f);
    ShaderOptions off = plain;
    off.ssao.radius = 3;
    off.ssao.samples = 64;
    off.ssao.scale = 2;
    const RenderResult a = render_scene(s, kN, kN, plain, c.caps);
    const RenderResult b = render_scene(s, kN, kN, off, c.caps);
    const RenderResult z = render_scene(s, kN, kN, zero, c.caps);
    EXPECT_EQ(a.image.rgba, b.image.rgba) << "SSAO's parameters changed the image with SSAO off";
    EXPECT_EQ(a.image.rgba, z.image.rgba) << "SSAO at strength 0 changed the image";
}

INSTANTIATE_TEST_SUITE_P(Paths, Ssao,
                         ::testing::Values(Case{"texture", DepthPath::texture, {}, 1},
                                           Case{"texture_half", DepthPath::texture, {}, 2},
                                           Case{"packed", DepthPath::packed, {}, 1},
                                           Case{"packed_half", DepthPath::packed, {}, 2},
                                           Case{"no_fbo", DepthPath::texture, {"no-fbo"}, 1},
                                           Case{"no_fbo_packed_half", DepthPath::packed, {"no-fbo"}, 2}),
                         [](const ::testing::TestParamInfo<Case>& i) { return std::string(i.param.name); });

// The ssao view is the AO buffer: white on the open floor and the background, darker at the crease.
TEST(SsaoView, ShowsTheAoBuffer) {
    const Scene s = box_on_floor();
    auto ctx = create_context(ContextDesc{"osmesa", kN, kN});
    ShaderOptions o;
    o.ssao.on = true;
    DeferredShader ds(probe_caps(), kN, kN, o, resource_dir("glsl120"));
    ds.set_scene(s);
    ds.render(s, kN, kN);
    ds.draw_view(View::ssao, s.camera, kN, kN);
    const Image v = read_pixels(kN, kN);
    const glm::ivec2 open = pixel_of(s, {1.8f, 0, -1.2f}), crease = pixel_of(s, {0, 0, 0.56f});
    EXPECT_EQ(lsb(v, open.x, open.y, 0), 255);
    EXPECT_EQ(lsb(v, kN / 2, kN - 2, 0), 255) << "background";
    EXPECT_LT(lsb(v, crease.x, crease.y, 0), 230);
    ShaderOptions no;
    DeferredShader plain(probe_caps(), kN, kN, no, resource_dir("glsl120"));
    plain.set_scene(s);
    plain.render(s, kN, kN);
    EXPECT_THROW(plain.draw_view(View::ssao, s.camera, kN, kN), Error);
}

TEST(SsaoCli, BadValuesAreOneClearErrorAndTheViewRenders) {
    const char* cases[][2] = {
        {"--ssao-samples 0", "--ssao-samples: expected an integer in [4, 64], got '0'"},
        {"--ssao-samples 1000", "--ssao-samples: expected an integer in [4, 64], got '1000'"},
        {"--ssao-scale 3", "--ssao-scale: expected 1|2, got '3'"},
        {"--ssao-radius -1", "--ssao-radius: expected a number in"},
        {"--ssao-strength x", "--ssao-strength: expected a number in"},
    };
    for (const auto& c : cases) {
        RunResult r = run(std::string("render --size 64x64 --ssao ") + c[0] + " -o " + test_output_dir() + "/ssao_bad.png");
        EXPECT_NE(r.status, 0) << c[0];
        EXPECT_NE(r.output.find(c[1]), std::string::npos) << c[0] << " said: " << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << c[0] << " said: " << r.output;
    }
    const std::string out = test_output_dir() + "/ssao_view.png";
    RunResult r = run("render --size 64x64 --view ssao --ssao-scale 2 --ssao-samples 8 -o " + out);
    EXPECT_EQ(r.status, 0) << r.output;
    struct stat st {};
    EXPECT_EQ(stat(out.c_str(), &st), 0);
}
