// Image tests of the whole pipeline under OSMesa (GL_RENDERER is logged with each).
#include <gtest/gtest.h>

#include "deferred/deferred_shader.h"
#include "dsr_error.h"
#include "render_fixture.h"

using namespace dsr;
using namespace dsr::test;

namespace {
constexpr int kSize = 256;  // small enough for 2 cores; the default scene at 512 is the CLI's job
constexpr double kLsb = 1.0 / 255.0;
}  // namespace

// The two depth paths reconstruct the same positions: the corrected packing keeps 24 bits,
// the depth texture 24 bits, so shading differs by rounding only.
TEST(Pipeline, DepthPathsAgreeOnDefaultScene) {
    Scene s = default_scene();
    auto tex = render_scene(s, kSize, kSize, with_depth(DepthPath::texture));
    auto packed = render_scene(s, kSize, kSize, with_depth(DepthPath::packed));
    std::printf("[ renderer ] %s\n", tex.renderer.c_str());
    ImageDiff d = compare_logged("texture vs packed", packed.image, tex.image, 2 * kLsb);
    if (d.max_lsb() > 4 || d.failing_fraction() > 0.001) write_failure_images("depth_paths", packed.image, tex.image);
    EXPECT_LE(d.max_lsb(), 4.0);
    EXPECT_LE(d.failing_fraction(), 0.001);
    // The sphere test's boundary sees each path's rounding of the position: a handful of pixels.
    EXPECT_NEAR(double(tex.stats.lights.fragments), double(packed.stats.lights.fragments),
                1e-3 * tex.stats.lights.fragments);
}

// Listings 11/18 as written lose bytes in an 8-bit target (docs/errata.md): the literal
// packed path must be measurably worse than the corrected one, on the same scene.
TEST(Pipeline, LiteralPackingIsWorseThanCorrected) {
    Scene s = default_scene();
    auto tex = render_scene(s, kSize, kSize, with_depth(DepthPath::texture));
    ShaderOptions lit = with_depth(DepthPath::packed);
    lit.encoding = DepthEncoding::literal;
    auto literal = render_scene(s, kSize, kSize, lit);
    auto packed = render_scene(s, kSize, kSize, with_depth(DepthPath::packed));
    ImageDiff dl = compare_logged("texture vs literal packed", literal.image, tex.image, 2 * kLsb);
    ImageDiff dc = compare_images(packed.image, tex.image, 2 * kLsb);
    EXPECT_GT(dl.mean_abs, dc.mean_abs);
}

// Listing 2's literal v (eye to p) and h (from the unnormalised l) against Equations 1-5:
// diffuse is the same, highlights move, so the images differ (docs/errata.md #1-2).
TEST(Pipeline, ListingTwoLightingDiffers) {
    Scene s = default_scene();
    ShaderOptions lit;
    lit.listing2_literal = true;
    auto eq = render_scene(s, 128, 128, ShaderOptions{});
    auto li = render_scene(s, 128, 128, lit);
    ImageDiff d = compare_logged("equations vs listing 2", li.image, eq.image, 2 * kLsb);
    EXPECT_GT(d.max_lsb(), 16.0);
    EXPECT_GT(d.failing, 100);
}

// §3.4.2: the scissor rectangle only removes fragments the light cannot reach. Measured with
// the per-light depth test off, so every fragment in a rectangle is shaded.
TEST(Pipeline, ScissorChangesFragmentsNotImage) {
    Scene s = default_scene();
    ShaderOptions on, off;
    on.light_geometry = off.light_geometry = LightGeometry::quad;  // the tutorial's scissored quads (§3.4.2)
    on.skip.light_depth_test = off.skip.light_depth_test = false;
    on.skip.light_sphere_test = off.skip.light_sphere_test = false;
    off.scissor = false;
    auto a = render_scene(s, kSize, kSize, on);
    auto b = render_scene(s, kSize, kSize, off);
    ImageDiff d = compare_logged("scissor on vs off", a.image, b.image, kLsb);
    std::printf("[ stats    ] light_fragments on %lld, off %lld; scissor_pixels on %lld, off %lld\n",
                a.stats.lights.fragments, b.stats.lights.fragments, a.stats.lights.scissor_pixels, b.stats.lights.scissor_pixels);
    EXPECT_LE(d.max_lsb(), 1.0);
    EXPECT_LT(a.stats.lights.fragments, b.stats.lights.fragments);
    EXPECT_EQ(b.stats.lights.fragments, (long long)b.stats.lights.drawn * kSize * kSize);
    EXPECT_EQ(a.stats.lights.fragments, a.stats.lights.scissor_pixels);  // no fragment is lost inside a rectangle
}

// Beyond the tutorial: the per-light depth test rejects surfaces outside the light's depth
// span before shading. Those surfaces get nothing from the light, so the image is unchanged.
TEST(Pipeline, LightDepthTestChangesFragmentsNotImage) {
    Scene s = default_scene();
    ShaderOptions with, without;
    with.light_geometry = without.light_geometry = LightGeometry::quad;  // one counted pass per light
    with.skip.light_sphere_test = without.skip.light_sphere_test = false;
    without.skip.light_depth_test = false;
    for (DepthPath p : {DepthPath::texture, DepthPath::packed}) {
        with.depth = without.depth = p;
        auto a = render_scene(s, kSize, kSize, with);
        auto b = render_scene(s, kSize, kSize, without);
        ImageDiff d = compare_logged("light depth test on vs off", a.image, b.image, kLsb);
        std::printf("[ stats    ] light_fragments with the test %lld, without %lld\n", a.stats.lights.fragments,
                    b.stats.lights.fragments);
        EXPECT_EQ(d.max_abs, 0.0);
        EXPECT_LT(a.stats.lights.fragments, b.stats.lights.fragments * 3 / 4);
    }
}

// The sphere test rejects surface points outside the light's sphere, where att = 0: the image is
// exactly the same, and the shaded fragments come down to the ideal count.
TEST(Pipeline, LightSphereTestChangesFragmentsNotImage) {
    Scene s = default_scene();
    ShaderOptions with, without;
    without.skip.light_sphere_test = false;
    auto a = render_scene(s, kSize, kSize, with);
    auto b = render_scene(s, kSize, kSize, without);
    std::printf("[ stats    ] light_fragments with the sphere test %lld, without %lld\n", a.stats.lights.fragments,
                b.stats.lights.fragments);
    EXPECT_EQ(compare_images(a.image, b.image, 0).max_abs, 0.0);
    EXPECT_LT(a.stats.lights.fragments, b.stats.lights.fragments);
}

// Zero-colour lights and lights whose rectangle is empty are skipped; without the skip they
// are drawn for nothing, and the image is the same.
TEST(Pipeline, EmptyLightSkipChangesWorkNotImage) {
    Scene s = default_scene();
    Light dark = s.lights[0];
    dark.color = glm::vec3(0);
    s.lights.push_back(dark);
    ShaderOptions with, without;
    without.skip.empty_lights = false;
    auto a = render_scene(s, 128, 128, with);
    auto b = render_scene(s, 128, 128, without);
    EXPECT_EQ(compare_images(a.image, b.image, 0).max_abs, 0.0);
    EXPECT_EQ(a.stats.lights.drawn + 1, b.stats.lights.drawn);
}

// Shader variants per material only remove work: the image without them differs only by the
// flat normal map's 8-bit tilt (128/255 is not 0.5, ~0.2 degrees) on materials without a map,
// which the red ball's shininess-256 highlight amplifies to 9 LSB on a few pixels.
TEST(Pipeline, MaterialVariantsChangeWorkNotImage) {
    Scene s = default_scene();
    ShaderOptions with, without;
    without.skip.material_variants = false;
    auto a = render_scene(s, 128, 128, with);
    auto b = render_scene(s, 128, 128, without);
    ImageDiff d = compare_logged("material variants on vs off", a.image, b.image, 2 * kLsb);
    EXPECT_LE(d.max_lsb(), 16.0);
    EXPECT_LE(d.failing_fraction(), 0.001);
}

// A light outside the view frustum is culled (Listing 17) and changes nothing.
TEST(Pipeline, LightOutsideFrustumIsCulled) {
    Scene s = default_scene();
    auto base = render_scene(s, 128, 128, ShaderOptions{});
    Light behind;
    behind.pos = s.camera.pos + 50.0f * glm::normalize(s.camera.pos - s.camera.target);
    behind.color = glm::vec3(1);
    behind.radius = 1.0f;
    s.lights.push_back(behind);
    auto more = render_scene(s, 128, 128, ShaderOptions{});
    EXPECT_EQ(more.stats.lights.total, base.stats.lights.total + 1);
    EXPECT_EQ(more.stats.lights.culled, base.stats.lights.culled + 1);
    EXPECT_EQ(more.stats.lights.fragments, base.stats.lights.fragments);
    EXPECT_EQ(compare_images(more.image, base.image, 0).max_abs, 0.0);
}

// Pixels with no surface keep the background colour (the ambient alpha test, unlit by
// Listing 20's zero-normal branch), and no pixel is NaN.
TEST(Pipeline, BackgroundStaysBackground) {
    Scene s = lit_sphere_scene();
    for (DepthPath p : {DepthPath::texture, DepthPath::packed}) {
        auto r = render_scene(s, 64, 64, with_depth(p));
        const float* corner = r.image.at(0, 0);
        EXPECT_NEAR(corner[0], 0.2f, 0.5 * kLsb);
        EXPECT_NEAR(corner[1], 0.4f, 0.5 * kLsb);
        EXPECT_NEAR(corner[2], 0.6f, 0.5 * kLsb);
        const float* centre = r.image.at(32, 32);
        EXPECT_GT(centre[0], 0.9f);  // lit head-on: ambient 0.5 + diffuse ~0.97 saturates
    }
}

// §3.2: a P-buffer is never a render target and a texture at once.
TEST(PBuffer, RenderTargetAndTextureAtOnceFails) {
    auto ctx = create_context(ContextDesc{"osmesa", 16, 16});
    PBufferDesc d;
    d.width = d.height = 16;
    d.color_formats = {GL_RGBA8};
    PBuffer pb("test", d);
    pb.bind_render();
    EXPECT_THROW(pb.bind_texture(0, 0), Error);
    pb.unbind_render();
    pb.bind_texture(0, 0);
    EXPECT_THROW(pb.bind_render(), Error);
    pb.unbind_texture(0, 0);
    EXPECT_NO_THROW(pb.bind_render());
    pb.unbind_render();
}

// The regression image: the default scene through the default path, against tests/ref
// (tests/ref/README.md: how it was made, what checks it independently). Tolerance: llvmpipe is
// deterministic on one machine and the reference was made on this machine's llvmpipe, so
// max <= 2 LSB with at most 0.01% of pixels over 1 LSB (tests/ref/README.md; it was max 8 with 0.1% over
// 2). Another CPU (SIMD width, LLVM version) may round differently: find out why before
// making a new reference.
TEST(Pipeline, DefaultSceneMatchesReference) {
    Scene s = default_scene();
    auto r = render_scene(s, kSize, kSize, ShaderOptions{});
    std::printf("[ renderer ] %s\n", r.renderer.c_str());
    std::string ref_path = resource_dir("tests") + "/ref/default_texture_256.png";
    Image ref;
    try {
        ref = load_image(ref_path);
    } catch (const Error& e) {
        write_failure_images("default_texture_256", r.image, r.image);
        FAIL() << "no reference: " << e.what() << " (the actual image was written to build/test-output)";
    }
    ImageDiff d = compare_logged("default scene vs reference", r.image, ref, 1 * kLsb);
    bool ok = d.max_lsb() <= 2 && d.failing_fraction() <= 1e-4;
    if (!ok) write_failure_images("default_texture_256", r.image, ref);
    EXPECT_TRUE(ok) << "max " << d.max_lsb() << " LSB, failing " << d.failing_fraction();
}
