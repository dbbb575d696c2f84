// The shadow measures (src/analysis/shadow_metrics.h) on hand-made masks and images. No GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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
