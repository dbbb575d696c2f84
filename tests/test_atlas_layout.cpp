// The batches' shadow atlas placement (deferred/atlas_layout.h), pure: every map gets a region of
// its own size at whole texels, inside a power-of-two atlas no larger than the GL's textures, and
// no two regions overlap; the maps that fit no such atlas are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "deferred/atlas_layout.h"

using dsr::AtlasLayout;
using dsr::AtlasRegion;

namespace {

bool pow2(int v) { return v > 0 && (v & (v - 1)) == 0; }

bool overlap(const AtlasRegion& a, const AtlasRegion& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

}  // namespace

// Random batches of up to 8 maps of the shadow stage's shapes (square spots and directionals, a
// point light's 3 x 2 faces), small and large.
TEST(AtlasLayout, RegionsAreTheMapsInsideAPowerOfTwoAtlasWithoutOverlap) {
    std::mt19937 rng(7);
    int refused = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const int n = 1 + int(rng() % 8);
        std::vector<AtlasRegion> sizes;
        long long area = 0;
        for (int k = 0; k < n; ++k) {
            const int face = 16 << (rng() % 8);  // 16 .. 2048
            const bool cube = rng() % 3 == 0;
            sizes.push_back(AtlasRegion{0, 0, cube ? 3 * face : face, cube ? 2 * face : face});
            area += (long long)sizes.back().width * sizes.back().height;
        }
        const int max_size = 4096 << (rng() % 3);
        const AtlasLayout l = dsr::place_atlas(sizes, max_size);
        if (!l.fits()) {
            ++refused;
            continue;
        }
        ASSERT_TRUE(pow2(l.width) && pow2(l.height));
        ASSERT_LE(l.width, max_size);
        ASSERT_LE(l.height, max_size);
        ASSERT_GE((long long)l.width * l.height, area);
        ASSERT_EQ(l.regions.size(), sizes.size());
        for (size_t k = 0; k < sizes.size(); ++k) {
            const AtlasRegion& r = l.regions[k];
            ASSERT_EQ(r.width, sizes[k].width);
            ASSERT_EQ(r.height, sizes[k].height);
            ASSERT_GE(r.x, 0);
            ASSERT_GE(r.y, 0);
            ASSERT_LE(r.x + r.width, l.width);
            ASSERT_LE(r.y + r.height, l.height);
            for (size_t j = 0; j < k; ++j) ASSERT_FALSE(overlap(r, l.regions[j])) << trial << ": " << j << " and " << k;
        }
    }
    EXPECT_GT(refused, 0);  // some batches of 2048-texel faces exceed a 4096 atlas
    EXPECT_LT(refused, 1000);
}

// Eight 1024-texel spot maps: 4096 x 2048 (the least area, then the squarer); larger than the GL's
// textures: refused (the batch then reads its maps through the if-chain).
TEST(AtlasLayout, SmallestAtlasOrNone) {
    const std::vector<AtlasRegion> spots(8, AtlasRegion{0, 0, 1024, 1024});
    const AtlasLayout l = dsr::place_atlas(spots, 16384);
    EXPECT_EQ(l.width * l.height, 8 * 1024 * 1024);
    EXPECT_EQ(std::max(l.width, l.height), 4096);
    EXPECT_FALSE(dsr::place_atlas(spots, 2048).fits());
    const AtlasLayout one = dsr::place_atlas({AtlasRegion{0, 0, 3072, 2048}}, 16384);
    EXPECT_EQ(one.width, 4096);
    EXPECT_EQ(one.height, 2048);
    EXPECT_FALSE(dsr::place_atlas({AtlasRegion{0, 0, 3072, 2048}}, 2048).fits());
}
