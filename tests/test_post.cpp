// The post-processing stage (§3.5): bloom only adds light, anti-alias leaves flat regions
// alone and changes edges, both bloom sizes run, and Figures 6 and 11 match references.
#include <gtest/gtest.h>

#include <cmath>

#include "dsr_error.h"
#include "gl/state.h"
#include "render_fixture.h"

using namespace dsr;
using namespace dsr::test;

namespace {
constexpr double kLsb = 1.0 / 255.0;

struct Frame {
    Image image, factor;
    FrameStats stats;
    int bloom_w = 0;
};

Frame render_post(const Scene& s, int n, const PostOptions& post) {
    auto ctx = create_context(ContextDesc{"osmesa", n, n});
    Caps caps = probe_caps();
    ShaderOptions o;
    o.post = post;
    DeferredShader ds(caps, n, n, o, resource_dir("glsl120"));
    ds.set_scene(s);
    Frame f;
    f.stats = ds.render(s, n, n);
    f.image = read_pixels(n, n);
    ds.draw_view(View::blur_factor, s.camera, n, n);
    f.factor = read_pixels(n, n);
    f.bloom_w = ds.pbuffer_width(2);
    return f;
}

void reference_test(const std::string& name, const Image& actual) {
    std::string ref_path = resource_dir("tests") + "/ref/" + name + ".png";
    Image ref;
    try {
        ref = load_image(ref_path);
    } catch (const Error& e) {
        write_failure_images(name, actual, actual);
        FAIL() << "no reference: " << e.what();
    }
    ImageDiff d = compare_logged(name + " vs reference", actual, ref, 2 * kLsb);
    bool ok = d.max_lsb() <= 8 && d.failing_fraction() <= 0.001;
    if (!ok) write_failure_images(name, actual, ref);
    EXPECT_TRUE(ok) << "max " << d.max_lsb() << " LSB, failing " << d.failing_fraction();
}
}  // namespace

namespace {
// Renders a second frame after filling P-buffers 1-3 (the anti-alias and bloom targets) with a
// colour no pass writes; returns how many pixels of each still hold it, and whether P-buffer 0
// is the image the final pass showed.
struct PostTouch {
    long long untouched[4] = {0, 0, 0, 0}, pixels[4] = {0, 0, 0, 0};
    bool accum_is_image = false;
};
PostTouch post_touch(const PostOptions& post) {
    const int n = 64;
    Scene s = default_scene();
    auto ctx = create_context(ContextDesc{"osmesa", n, n});
    ShaderOptions o;
    o.post = post;
    DeferredShader ds(probe_caps(), n, n, o, resource_dir("glsl120"));
    ds.set_scene(s);
    ds.render(s, n, n);
    const float mark[4] = {64 / 255.0f, 128 / 255.0f, 192 / 255.0f, 1.0f};  // exact in 8 bits
    for (int b = 1; b < 4; ++b) {
        ds.fb_bind_render(b);
        gl_state().apply(fixed_function_2d());
        glClearColor(mark[0], mark[1], mark[2], mark[3]);
        glClear(GL_COLOR_BUFFER_BIT);
        ds.fb_unbind_render(b);
    }
    ds.render(s, n, n);
    PostTouch t;
    const Image shown = read_pixels(n, n);
    for (int b = 1; b < 4; ++b) {
        const Image img = ds.read_pbuffer(b);
        for (size_t p = 0; p < img.rgba.size(); p += 4) {
            bool same = true;
            for (int c = 0; c < 4; ++c) same &= std::fabs(img.rgba[p + c] - mark[c]) < 0.5 * kLsb;
            t.untouched[b] += same;
            t.pixels[b] += 1;
        }
    }
    const Image accum = ds.read_pbuffer(0);
    t.accum_is_image = compare_images(accum, shown, 0.5 * kLsb).max_lsb() < 0.5;
    return t;
}
}  // namespace

// With bloom and anti-alias off no post pass is drawn: no time is charged to them, and
// P-buffers 1-3 keep what was in them through a whole frame. With either on, its buffers are
// written (so the check can fail).
TEST(Post, OffCostsNothing) {
    Frame f = render_post(default_scene(), 64, PostOptions{});
    EXPECT_EQ(f.stats.ms.bloom, 0.0);
    EXPECT_EQ(f.stats.ms.aa, 0.0);
    const PostTouch off = post_touch(PostOptions{});
    for (int b = 1; b < 4; ++b) {
        EXPECT_GT(off.pixels[b], 0) << b;
        EXPECT_EQ(off.untouched[b], off.pixels[b]) << "P-buffer " << b << " written with post off";
    }
    EXPECT_TRUE(off.accum_is_image);
    PostOptions bloom;
    bloom.bloom = true;
    const PostTouch b = post_touch(bloom);
    EXPECT_EQ(b.untouched[1], b.pixels[1]) << "bloom alone leaves the anti-alias buffer";
    EXPECT_LT(b.untouched[2], b.pixels[2] / 2);
    EXPECT_LT(b.untouched[3], b.pixels[3] / 2);
    PostOptions aa;
    aa.aa = true;
    const PostTouch a = post_touch(aa);
    EXPECT_LT(a.untouched[1], a.pixels[1] / 2);  // after the swap, 1 holds the un-anti-aliased frame
    EXPECT_EQ(a.untouched[2], a.pixels[2]);
    EXPECT_EQ(a.untouched[3], a.pixels[3]);
    std::printf("[ post     ] P-buffer 1/2/3 pixels untouched: off %lld/%lld/%lld, bloom %lld/%lld/%lld, aa %lld/%lld/%lld "
                "of %lld/%lld/%lld\n",
                off.untouched[1], off.untouched[2], off.untouched[3], b.untouched[1], b.untouched[2], b.untouched[3],
                a.untouched[1], a.untouched[2], a.untouched[3], off.pixels[1], off.pixels[2], off.pixels[3]);
}

// Eq. 7: where the normal target is constant the factor is 0 and the offsets vanish, so the
// pixel is its own colour; at edges the factor is large and pixels change.
TEST(Post, AntiAliasKeepsFlatRegionsAndChangesEdges) {
    Scene s = default_scene();
    PostOptions aa;
    aa.aa = true;
    Frame plain = render_post(s, 128, PostOptions{});
    Frame with = render_post(s, 128, aa);
    long long flat = 0, flat_changed = 0, edge = 0, edge_changed = 0;
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x) {
            float f = with.factor.at(x, y)[0];
            bool changed = false;
            for (int c = 0; c < 3; ++c) changed |= std::fabs(with.image.at(x, y)[c] - plain.image.at(x, y)[c]) > 0.5 * kLsb;
            if (f == 0.0f) ++flat, flat_changed += changed;
            if (f >= 0.5f) ++edge, edge_changed += changed;
        }
    std::printf("[ aa       ] flat pixels %lld (%lld changed), edge pixels %lld (%lld changed)\n", flat, flat_changed,
                edge, edge_changed);
    EXPECT_GT(flat, 128 * 128 / 4);
    EXPECT_EQ(flat_changed, 0);
    EXPECT_GT(edge, 100);
    EXPECT_GT(edge_changed, edge / 4);
}

// The listing's kernel (4 neighbours, (-1,1) twice) finds different edges from Eq. 7's 8.
TEST(Post, ListingKernelDiffersFromText) {
    Scene s = default_scene();
    PostOptions text, listing;
    text.aa = listing.aa = true;
    listing.aa_kernel = AaKernel::listing;
    Frame a = render_post(s, 96, text), b = render_post(s, 96, listing);
    ImageDiff d = compare_logged("blur factor text vs listing kernel", b.factor, a.factor, 2 * kLsb);
    EXPECT_GT(d.failing, 50);
}

// Bloom adds P-buffer 3 to P-buffer 0 with an additive blend: nothing gets darker.
TEST(Post, BloomOnlyAddsLightAtBothScales) {
    Scene s = default_scene();
    Frame plain = render_post(s, 128, PostOptions{});
    for (int scale : {2, 4}) {
        PostOptions b;
        b.bloom = true;
        b.bloom_scale = scale;
        Frame f = render_post(s, 128, b);
        EXPECT_EQ(f.bloom_w, 128 / scale);
        EXPECT_GT(f.stats.ms.bloom, 0.0);
        long long darker = 0, brighter = 0;
        for (size_t i = 0; i < f.image.rgba.size(); ++i) {
            if (i % 4 == 3) continue;
            darker += f.image.rgba[i] < plain.image.rgba[i];
            brighter += f.image.rgba[i] > plain.image.rgba[i];
        }
        std::printf("[ bloom    ] 1/%d: %lld channels brighter, %lld darker\n", scale, brighter, darker);
        EXPECT_EQ(darker, 0);
        EXPECT_GT(brighter, 1000);
    }
}

// Figure 6: ambient + three lights + post (bloom and anti-alias).
TEST(Post, Figure6MatchesReference) {
    PostOptions p;
    p.bloom = p.aa = true;
    reference_test("fig6_256", render_post(default_scene(), 256, p).image);
}

// Figure 11 (right): with bloom.
TEST(Post, Figure11MatchesReference) {
    PostOptions p;
    p.bloom = true;
    reference_test("fig11_with_bloom_256", render_post(default_scene(), 256, p).image);
}
