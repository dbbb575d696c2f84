// The tiles' depth spans made on the CPU from the G-buffer read back (deferred/tile_spans.h) against
// brute force: the surface test against light_tiles.frag's float arithmetic for every byte triple,
// and each tile's span against every lit pixel's eye z as surface_eye_z computes it in float.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "deferred/reconstruct.h"
#include "deferred/tile_spans.h"

using namespace dsr;

namespace {

// light_tiles.frag's test in float: length(byte / 255 - 0.5) > 0.1.
bool lit_in_float(int r, int g, int b) {
    const float x = float(r) / 255.0f - 0.5f, y = float(g) / 255.0f - 0.5f, z = float(b) / 255.0f - 0.5f;
    return std::sqrt(x * x + y * y + z * z) > 0.1f;
}

// surface_eye_z (depth_codec.glsl, the depth-texture path) in float, as the shader computes it.
float eye_z_float(float depth, glm::vec2 planes, float far_plane) {
    return -planes.y / std::min(planes.x + depth, planes.y / far_plane);
}

}  // namespace

TEST(TileSpans, SurfaceTestIsTheShadersForEveryByteTriple) {
    int lit = 0;
    for (int r = 0; r < 256; ++r)
        for (int g = 0; g < 256; ++g)
            for (int b = 0; b < 256; ++b) {
                const std::uint8_t n[4] = {std::uint8_t(r), std::uint8_t(g), std::uint8_t(b), 0};
                ASSERT_EQ(lit_normal(n), lit_in_float(r, g, b)) << r << " " << g << " " << b;
                lit += lit_normal(n);
            }
    EXPECT_GT(lit, 16000000);  // all but the grey ball about (127.5, 127.5, 127.5)
    EXPECT_LT(lit, 16777216);
}

// Random frames: partial tiles at the right and top edges, a padded row stride, background pixels
// (normal 128,128,128) in patches and whole tiles, a third of the normals near the surface test's
// edge, a few degenerate, surfaces at depths over the whole range, a few at 0 and 1 exactly;
// near/far from 0.01/10 to 1/1e6.
TEST(TileSpans, EveryLitPixelLiesInItsTilesSpanAndTheSpanIsTight) {
    std::mt19937 rng(20261205u);
    std::uniform_real_distribution<float> uni(0.0f, 1.0f);
    const struct { int w, h, stride, tile; float n, f; } cases[] = {
        {37, 29, 64, 8, 0.01f, 10.0f}, {64, 48, 64, 16, 0.1f, 100.0f}, {50, 70, 50, 16, 1.0f, 1e6f},
        {33, 17, 40, 32, 0.05f, 500.0f}, {7, 5, 8, 16, 0.1f, 30.0f}};
    long long pixels_checked = 0;
    int empty_tiles = 0;
    for (const auto& c : cases) {
        const glm::vec2 planes = planes_uniform(c.n, c.f);
        std::vector<float> depth(size_t(c.stride) * size_t(c.h), -7.0f);  // padding: never read
        std::vector<std::uint8_t> normal(depth.size() * 4, 0);
        const int tx = (c.w + c.tile - 1) / c.tile, ty = (c.h + c.tile - 1) / c.tile;
        for (int y = 0; y < c.h; ++y)
            for (int x = 0; x < c.w; ++x) {
                const size_t i = size_t(y) * size_t(c.stride) + size_t(x);
                const bool background = (x / c.tile + y / c.tile) % 4 == 1 || uni(rng) < 0.2f;
                float d = uni(rng);
                d = d * d;  // more of them near the camera
                if (uni(rng) < 0.02f) d = 1.0f;
                if (uni(rng) < 0.02f) d = 0.0f;
                depth[i] = d;
                // A third of the normals about the test's edge (v = 2 byte - 255 near 51 in length).
                const bool edge = uni(rng) < 0.35f;
                for (int k = 0; k < 3; ++k)
                    normal[4 * i + k] = background ? 128 : std::uint8_t(edge ? 100 + 56 * uni(rng) : 255 * uni(rng));
                if (!background && uni(rng) < 0.02f) normal[4 * i] = normal[4 * i + 1] = normal[4 * i + 2] = 127;  // degenerate
            }
        const std::vector<DepthSpan> spans =
            spans_from_depth(GbufferReadback{depth.data(), normal.data(), c.stride}, c.w, c.h, c.tile, planes, c.f);
        ASSERT_EQ(spans.size(), size_t(tx) * size_t(ty));
        for (int t = 0; t < tx * ty; ++t) {
            const int x0 = (t % tx) * c.tile, y0 = (t / tx) * c.tile;
            float zmin = INFINITY, zmax = -INFINITY;
            for (int y = y0; y < std::min(c.h, y0 + c.tile); ++y)
                for (int x = x0; x < std::min(c.w, x0 + c.tile); ++x) {
                    const size_t i = size_t(y) * size_t(c.stride) + size_t(x);
                    if (!lit_in_float(normal[4 * i], normal[4 * i + 1], normal[4 * i + 2])) continue;
                    // The sampler's depth may differ from the read-back's in its last bit.
                    for (float d : {std::nextafter(depth[i], -1.0f), depth[i], std::nextafter(depth[i], 2.0f)}) {
                        const float z = eye_z_float(d, planes, c.f);
                        EXPECT_LE(spans[size_t(t)].lo, z) << "tile " << t << " pixel " << x << "," << y;
                        EXPECT_GE(spans[size_t(t)].hi, z) << "tile " << t << " pixel " << x << "," << y;
                    }
                    const float z = eye_z_float(depth[i], planes, c.f);
                    zmin = std::min(zmin, z);
                    zmax = std::max(zmax, z);
                    ++pixels_checked;
                }
            if (zmin > zmax) {
                EXPECT_GT(spans[size_t(t)].lo, spans[size_t(t)].hi) << "tile " << t << " has no lit pixel";
                ++empty_tiles;
                continue;
            }
            // Tight: widened by far less than the spans' use needs (a millionth and a few float steps).
            EXPECT_NEAR(spans[size_t(t)].lo, zmin, 1e-4 * std::abs(zmin) + 1e-6) << "tile " << t;
            EXPECT_NEAR(spans[size_t(t)].hi, zmax, 1e-4 * std::abs(zmax) + 1e-6) << "tile " << t;
        }
    }
    EXPECT_GT(pixels_checked, 4000);
    EXPECT_GT(empty_tiles, 0);
}
