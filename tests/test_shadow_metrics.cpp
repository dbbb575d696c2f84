// The shadow measures (src/analysis/shadow_metrics.h) on hand-made masks and images. No GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analysis/analytic_reference.h"
#include "analysis/shadow_metrics.h"
#include "dsr_error.h"

using namespace dsr;

namespace {
constexpr int W = 32, H = 16;

// Shadowed where x < edge.
Mask half(int edge) {
    Mask m(size_t(W) * H, 0);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < edge; ++x) m[size_t(y) * W + x] = 1;
    return m;
}

Image flat(float v) {
    Image img;
    img.width = W;
    img.height = H;
    img.rgba.assign(size_t(W) * H * 4, v);
    return img;
}
}  // namespace

// A straight edge at x = 10 (pixels 9 and 10 are its boundary): the renderer's edge moved by
// 1, 2 and 3 pixels puts its furthest wrong pixel 0, 1 and 2 pixels from the boundary.
TEST(ShadowMetrics, EdgeErrorIsTheDistanceToTheTracedEdge) {
    const Mask all(size_t(W) * H, 1), ref = half(10);
    const Mask b = shadow_boundary(ref, all, W, H);
    EXPECT_EQ(b[5 * W + 9], 1);
    EXPECT_EQ(b[5 * W + 10], 1);
    EXPECT_EQ(b[5 * W + 8], 0);
    EXPECT_EQ(b[5 * W + 11], 0);
    const ShadowEdgeError same = shadow_edge_error(ref, ref, all, W, H);
    EXPECT_EQ(same.mismatched, 0);
    EXPECT_EQ(same.boundary, 2 * H);
    EXPECT_EQ(same.ref_shadowed, 10 * H);
    for (int shift : {1, 2, 3}) {
        const ShadowEdgeError e = shadow_edge_error(ref, half(10 + shift), all, W, H);
        EXPECT_EQ(e.mismatched, shift * H);
        EXPECT_DOUBLE_EQ(e.max_px, shift - 1.0);
        EXPECT_EQ(e.beyond(1.5), shift == 3 ? H : 0);
    }
    // A lone wrong pixel far from the edge (acne-like): its distance counts.
    Mask spot = ref;
    spot[3 * W + 25] = 1;
    EXPECT_DOUBLE_EQ(shadow_edge_error(ref, spot, all, W, H).max_px, 15.0);
    // Pixels not considered neither make the boundary nor count.
    Mask some = all;
    for (int y = 0; y < H; ++y) some[size_t(y) * W + 10] = 0;
    EXPECT_EQ(shadow_edge_error(ref, ref, some, W, H).boundary, 0);
    // The boundary's domain can be wider than the pixels judged: the edge at x = 10 with only
    // x >= 12 considered is 2 pixels from a wrong pixel at x = 12 (the domain everything), and
    // no boundary at all in the considered pixels alone.
    Mask right(size_t(W) * H, 0);
    for (size_t p = 0; p < right.size(); ++p) right[p] = p % W >= 12;
    const Mask wrong12 = half(13);
    EXPECT_DOUBLE_EQ(shadow_edge_error(ref, wrong12, right, W, H, &all).max_px, 2.0);
    EXPECT_TRUE(std::isinf(shadow_edge_error(ref, wrong12, right, W, H).max_px));
    // No boundary at all and a mismatch: infinitely far.
    EXPECT_TRUE(std::isinf(shadow_edge_error(half(0), spot, all, W, H).max_px));
    EXPECT_THROW(shadow_edge_error(ref, Mask(3, 0), all, W, H), Error);
}

TEST(ShadowMetrics, ClassCutsAtHalfTheLightsTerm) {
    const Image off = flat(0.6f), dark = flat(0.2f);
    EXPECT_EQ(shadow_class(flat(0.2f), off, dark)[0], 1);   // all of the light removed
    EXPECT_EQ(shadow_class(flat(0.39f), off, dark)[0], 1);  // more than half
    EXPECT_EQ(shadow_class(flat(0.41f), off, dark)[0], 0);  // less than half
    EXPECT_EQ(shadow_class(off, off, dark)[0], 0);
    EXPECT_EQ(shadow_class(dark, dark, dark)[0], 0);         // the light adds nothing: never shadowed
    const Mask interior(size_t(W) * H, 1);
    EXPECT_EQ(shadow_considered(off, dark, interior, 0.3)[0], 1);
    EXPECT_EQ(shadow_considered(off, dark, interior, 0.5)[0], 0);
    EXPECT_EQ(shadow_considered(off, dark, Mask(size_t(W) * H, 0), 0.1)[0], 0);
}

TEST(ShadowMetrics, AcneBandAndContact) {
    const Image ref = flat(0.5f);
    Image got = ref;
    got.at(3, 4)[1] = 0.5f - 9.0f / 255;  // 9 LSB darker in green
    got.at(5, 4)[0] = 0.5f - 7.0f / 255;  // 7: within the threshold
    got.at(6, 4)[0] = 0.9f;               // brighter: not acne
    const Mask all(size_t(W) * H, 1);
    const AcneCount a = acne(got, ref, all, 8);
    EXPECT_EQ(a.pixels, W * H);
    EXPECT_EQ(a.darker, 1);
    EXPECT_NEAR(a.max_darker_lsb, 9, 1e-4);
    // The band: dilating an edge pixel by 2 covers the 13 pixels within distance 2.
    Mask one(size_t(W) * H, 0);
    one[size_t(8) * W + 16] = 1;
    const Mask d = dilate(one, W, H, 2);
    EXPECT_EQ(std::count(d.begin(), d.end(), 1), 13);
    EXPECT_EQ(occlusion_edges(half(10), W, H)[5 * W + 9], 1);
    EXPECT_EQ(occlusion_edges(half(10), W, H)[5 * W + 8], 0);
    // Contact: occluder at x in [10, 14), receiver elsewhere; the reference shadows x < 10, the
    // renderer x < 8 (a 2-pixel gap at the contact: peter-panning).
    Mask occ(size_t(W) * H, 0), rec(size_t(W) * H, 0);
    for (size_t p = 0; p < occ.size(); ++p) {
        const int x = int(p % W);
        occ[p] = x >= 10 && x < 14;
        rec[p] = !occ[p];
    }
    const ContactLeak c = contact_leak(half(10), half(8), all, rec, occ, W, H, 3);
    EXPECT_EQ(c.contact, 3 * H);  // x = 7, 8, 9 are within 3 of the occluder
    EXPECT_EQ(c.leaked, 2 * H);
    EXPECT_EQ(contact_leak(half(10), half(10), all, rec, occ, W, H, 3).leaked, 0);
}

// measure_shadow on the trace itself (nothing wrong), on the trace without its shadow (all of the
// contact leaks, every traced shadow pixel is wrong) and with a dark blotch on a lit floor (acne).
TEST(ShadowMetrics, MeasureShadowAgainstTheTrace) {
    Scene s;
    s.camera.pos = {0, 4, 5};
    s.camera.target = {0, 0.3f, 0};
    s.camera.near_plane = 0.5f;
    s.camera.far_plane = 30;
    s.ambient = glm::vec3(0.1f);
    Material m;
    m.name = "m";
    m.diffuse = glm::vec3(0.7f);
    m.specular = glm::vec3(0);
    s.materials.push_back(m);
    add_plane(s, 10, {0, 0, 0}, 0);
    add_box(s, {1, 1, 1}, {0, 0.5f, 0}, 0);
    Light l;
    l.pos = {1, 3, -2};
    l.radius = 10;
    l.color = glm::vec3(0.8f);
    l.shadow.on = true;
    s.lights.push_back(l);
    const int n = 96;
    const AnalyticTrace t = analytic_trace(s, n, n);
    const ShadowMeasure same = measure_shadow(s, t, t.image, 0, 1);
    EXPECT_EQ(same.edge.mismatched, 0);
    EXPECT_GT(same.edge.ref_shadowed, 100);
    EXPECT_EQ(same.acne.darker, 0);
    EXPECT_GT(same.leak.contact, 5);
    EXPECT_EQ(same.leak.leaked, 0);
    AnalyticOptions off;
    off.shadows = false;
    const ShadowMeasure none = measure_shadow(s, t, analytic_trace(s, n, n, off).image, 0, 1);
    EXPECT_EQ(none.edge.mismatched, none.edge.ref_shadowed);
    EXPECT_EQ(none.edge.got_shadowed, 0);
    EXPECT_EQ(none.leak.leaked, none.leak.contact);
    EXPECT_EQ(none.acne.darker, 0);
    Image blotch = t.image;
    int darkened = 0;
    for (int y = 5; y < 9; ++y)
        for (int x = 5; x < 9; ++x)
            if (t.mesh[size_t(y) * n + x] == 0 && !t.occluded[0][size_t(y) * n + x]) {
                blotch.at(x, y)[0] -= 20.0f / 255;
                ++darkened;
            }
    ASSERT_GT(darkened, 0);
    EXPECT_EQ(measure_shadow(s, t, blotch, 0, 1).acne.darker, darkened);
    Scene two = s;
    two.lights.push_back(l);
    EXPECT_THROW(measure_shadow(two, t, t.image, 0, 1), Error);
}
