// Shadow maps drawn through the main frame buffer (deferred/map_pieces.h), the pure part: the
// pieces cover every texel of the map exactly once and each fits the buffer; which depth path
// such maps take.
#include <gtest/gtest.h>

#include <vector>

#include "deferred/map_pieces.h"

using dsr::MapPiece;

// Brute force over maps and buffers of awkward sizes (smaller, equal, larger, not dividing).
TEST(MapPieces, CoverEveryTexelOnceAndFitTheBuffer) {
    for (int mw : {1, 64, 256, 768, 1000})
        for (int mh : {1, 64, 512, 333})
            for (int bw : {1, 7, 96, 320, 2048})
                for (int bh : {1, 90, 240, 512}) {
                    if (mw * mh > 200000 || (mw / bw) * (mh / bh) > 20000) continue;
                    const std::vector<MapPiece> ps = dsr::map_pieces(mw, mh, bw, bh);
                    std::vector<int> hits(size_t(mw) * size_t(mh), 0);
                    for (const MapPiece& p : ps) {
                        ASSERT_GT(p.width, 0);
                        ASSERT_GT(p.height, 0);
                        ASSERT_LE(p.width, bw);
                        ASSERT_LE(p.height, bh);
                        ASSERT_GE(p.x, 0);
                        ASSERT_GE(p.y, 0);
                        ASSERT_LE(p.x + p.width, mw);
                        ASSERT_LE(p.y + p.height, mh);
                        for (int y = p.y; y < p.y + p.height; ++y)
                            for (int x = p.x; x < p.x + p.width; ++x) ++hits[size_t(y) * size_t(mw) + size_t(x)];
                    }
                    for (int h : hits) ASSERT_EQ(h, 1) << mw << "x" << mh << " in " << bw << "x" << bh;
                    const size_t n = size_t((mw + bw - 1) / bw) * size_t((mh + bh - 1) / bh);
                    EXPECT_EQ(ps.size(), n) << mw << "x" << mh << " in " << bw << "x" << bh;
                }
}

TEST(MapPieces, OneWholePieceWhereTheMapFits) {
    EXPECT_EQ(dsr::map_pieces(1024, 1024, 1200, 1100), (std::vector<MapPiece>{{0, 0, 1024, 1024}}));
    EXPECT_EQ(dsr::map_pieces(256, 256, 256, 256), (std::vector<MapPiece>{{0, 0, 256, 256}}));
    EXPECT_EQ(dsr::map_pieces(256, 100, 96, 96),
              (std::vector<MapPiece>{{0, 0, 96, 96}, {96, 0, 96, 96}, {192, 0, 64, 96},
                                     {0, 96, 96, 4}, {96, 96, 96, 4}, {192, 96, 64, 4}}));
    EXPECT_TRUE(dsr::map_pieces(0, 256, 96, 96).empty());
    EXPECT_TRUE(dsr::map_pieces(256, 256, 0, 96).empty());
}

// A cube face's tile overlaps a piece only where they share texels (edges touching do not).
TEST(MapPieces, Overlap) {
    const MapPiece face{256, 0, 256, 256};
    EXPECT_TRUE(dsr::pieces_overlap(face, {200, 0, 96, 96}));
    EXPECT_FALSE(dsr::pieces_overlap(face, {160, 0, 96, 96}));  // ends at x = 256
    EXPECT_FALSE(dsr::pieces_overlap(face, {512, 0, 96, 96}));  // starts at x = 512
    EXPECT_FALSE(dsr::pieces_overlap(face, {300, 256, 96, 96}));
    EXPECT_TRUE(dsr::pieces_overlap(face, {300, 255, 96, 96}));
}

// Depth textures where the GL compares them (ARB_depth_texture and ARB_shadow) and, copied from the
// main frame buffer, where its depth keeps all 24 bits; packed otherwise.
TEST(MapPieces, PackedWhereDepthTexturesWouldLoseBits) {
    EXPECT_FALSE(dsr::maps_packed(true, true, false, 0));  // framebuffer objects: depth bits unasked
    EXPECT_FALSE(dsr::maps_packed(true, true, true, 24));
    EXPECT_FALSE(dsr::maps_packed(true, true, true, 32));
    EXPECT_TRUE(dsr::maps_packed(true, true, true, 16));
    EXPECT_TRUE(dsr::maps_packed(false, true, false, 24));
    EXPECT_TRUE(dsr::maps_packed(true, false, true, 24));
}
