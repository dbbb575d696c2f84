// The tiles geometry's plan (deferred/tile_plan.h) against brute force: every (tile, light) pair
// whose rectangle overlaps the tile (and, with depth culling, whose depth spans share a z) is shaded
// exactly once, no draw holds more than the pass's
// lights per tile, every draw's lights come from its own batch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>

#include "deferred/tile_plan.h"

using namespace dsr;

namespace {

// Brute force for the plans: the pair is shaded iff the light reaches the tile's box (sphere_meets_box
// has its own brute-force test below).
bool share_a_z(const TileDepth& d, int l, int tile) { return sphere_meets_box(d.lights[size_t(l)], d.tiles[size_t(tile)]); }

// Random culling data: per light a sphere in [-20, 20]^2 x [-50, -1] with radius [0, 6] (every 7th
// unbounded, as a directional light); per tile a box, every 5th empty (background only).
TileDepth random_depth(std::mt19937& rng, size_t lights, int tiles) {
    std::uniform_real_distribution<float> xy(-20.0f, 20.0f), z(-50.0f, -1.0f), r(0.0f, 6.0f), dz(0.0f, 10.0f);
    TileDepth d;
    for (size_t i = 0; i < lights; ++i)
        d.lights.push_back(i % 7 == 3 ? LightBound{} : LightBound{glm::vec3(xy(rng), xy(rng), z(rng)), r(rng)});
    for (int t = 0; t < tiles; ++t) {
        TileBox b;
        b.lo = glm::vec3(xy(rng), xy(rng), z(rng));
        b.hi = b.lo + glm::vec3(dz(rng), dz(rng), dz(rng));
        b.empty = t % 5 == 2;
        d.tiles.push_back(b);
    }
    return d;
}

// The batches' cuts with shadowed lights (cut_batches): in the plan's order without them, no batch
// holding more than k shadowed lights, and a batch cut only where it is full or where its next
// light would be its (k+1)-th shadowed one.
void check_shadow_cuts(const std::vector<std::vector<int>>& batches, const std::vector<std::vector<int>>& unlimited,
                       const std::vector<bool>& shadowed, int b, int k) {
    std::vector<int> order, want;
    for (const auto& batch : unlimited) want.insert(want.end(), batch.begin(), batch.end());
    for (size_t j = 0; j < batches.size(); ++j) {
        const auto& batch = batches[j];
        int in_batch = 0;
        for (int l : batch) in_batch += shadowed[size_t(l)];
        EXPECT_LE(in_batch, k) << "batch " << j;
        if (j + 1 < batches.size()) {
            const bool next_shadowed = shadowed[size_t(batches[j + 1][0])];
            EXPECT_TRUE(int(batch.size()) == b || (next_shadowed && in_batch == k)) << "batch " << j << " cut early";
        }
        order.insert(order.end(), batch.begin(), batch.end());
    }
    EXPECT_EQ(order, want);
}

void check_plan(const std::vector<ScissorRect>& rects, int w, int h, int ts, int n, int b,
                const TileDepth* depth = nullptr, const std::vector<bool>* shadowed = nullptr, int k = 0) {
    const TilePlan plan = plan_tiles(rects, w, h, ts, n, b, depth, shadowed, k);
    if (shadowed) check_shadow_cuts(plan.batches, plan_tiles(rects, w, h, ts, n, b, depth).batches, *shadowed, b, k);
    // Batches: each non-empty (on screen) light exactly once, at most b lights each.
    std::multiset<int> in_batches;
    for (const auto& batch : plan.batches) {
        EXPECT_LE(int(batch.size()), b);
        EXPECT_FALSE(batch.empty());
        in_batches.insert(batch.begin(), batch.end());
    }
    std::map<std::pair<int, int>, std::multiset<int>> shaded;  // tile -> lights
    long long pairs = 0;
    for (const TileDraw& d : plan.draws) {
        ASSERT_LT(d.batch, int(plan.batches.size()));
        const auto& batch = plan.batches[size_t(d.batch)];
        std::set<std::pair<int, int>> tiles_of_draw;
        for (const TileQuad& q : d.quads) {
            EXPECT_LE(int(q.slots.size()), n);
            EXPECT_FALSE(q.slots.empty());
            // Whole tiles (merged neighbours with the same lights; the last row and column may end
            // at the screen's edge).
            EXPECT_EQ(q.x0 % ts, 0);
            EXPECT_EQ(q.y0 % ts, 0);
            EXPECT_GT(q.x1, q.x0);
            EXPECT_GT(q.y1, q.y0);
            EXPECT_TRUE(q.x1 == w || (q.x1 % ts == 0 && q.x1 < w)) << q.x1;
            EXPECT_TRUE(q.y1 == h || (q.y1 % ts == 0 && q.y1 < h)) << q.y1;
            for (int ty = q.y0 / ts; ty * ts < q.y1; ++ty)
                for (int tx = q.x0 / ts; tx * ts < q.x1; ++tx) {
                    EXPECT_TRUE(tiles_of_draw.insert({tx, ty}).second) << "a tile twice in one draw";
                    for (int s : q.slots) {
                        ASSERT_GE(s, 0);
                        ASSERT_LT(s, int(batch.size()));
                        shaded[{tx, ty}].insert(batch[size_t(s)]);
                        ++pairs;
                    }
                }
        }
    }
    EXPECT_EQ(pairs, plan.tile_light_pairs);
    std::multiset<int> on_screen;
    for (int y = 0; y * ts < h; ++y)
        for (int x = 0; x * ts < w; ++x) {
            std::multiset<int> want;
            for (int i = 0; i < int(rects.size()); ++i) {
                const ScissorRect& r = rects[size_t(i)];
                const int x0 = std::max(r.x0, x * ts), x1 = std::min({r.x1, (x + 1) * ts, w});
                const int y0 = std::max(r.y0, y * ts), y1 = std::min({r.y1, (y + 1) * ts, h});
                const int tiles_x = (w + ts - 1) / ts;
                if (x1 > x0 && y1 > y0 &&
                    (!depth || share_a_z(*depth, i, y * tiles_x + x))) {
                    want.insert(i);
                    on_screen.insert(i);
                }
            }
            EXPECT_EQ(shaded[std::make_pair(x, y)], want) << "tile " << x << "," << y;
        }
    EXPECT_EQ(std::set<int>(in_batches.begin(), in_batches.end()), std::set<int>(on_screen.begin(), on_screen.end()));
    EXPECT_EQ(in_batches.size(), std::set<int>(in_batches.begin(), in_batches.end()).size());
}

// n rectangles at random places and sizes (positions in [lo, hi], sides in [0, side]): some off
// the screen, some empty.
std::vector<ScissorRect> random_rects(std::mt19937& rng, size_t n, int lo = -40, int hi = 300, int side = 160) {
    std::uniform_int_distribution<int> pos(lo, hi), size(0, side);
    std::vector<ScissorRect> rects(n);
    for (ScissorRect& r : rects) {
        r.x0 = pos(rng), r.y0 = pos(rng);
        r.x1 = r.x0 + size(rng), r.y1 = r.y0 + size(rng);
    }
    return rects;
}

}  // namespace

TEST(TilePlan, EveryOverlapShadedOnceAgainstBruteForce) {
    std::mt19937 rng(12);
    for (int trial = 0; trial < 40; ++trial) {
        const int w = 97 + trial * 7, h = 61 + trial * 5;
        std::vector<ScissorRect> rects = random_rects(rng, size_t(1 + trial * 9));
        const int ts = 8 << (trial % 3), n = 1 + trial % 9, b = 1 + (trial * 13) % 70;
        SCOPED_TRACE(testing::Message() << "trial " << trial << " " << w << "x" << h << " ts " << ts << " n " << n << " b " << b);
        check_plan(rects, w, h, ts, n, b);
        const TileDepth depth = random_depth(rng, rects.size(), ((w + ts - 1) / ts) * ((h + ts - 1) / ts));
        check_plan(rects, w, h, ts, n, b, &depth);
    }
}

// A batch holds at most k shadowed lights (the shader's shadow map units, shadow.glsl
// SHADOW_SLOTS): the plans cut a batch where a (k+1)-th would enter it, and only there or where it
// is full; every pair is still shaded exactly once (check_plan's brute force).
TEST(TilePlan, NoBatchHoldsMoreShadowedLightsThanItsMaps) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 30; ++trial) {
        const int w = 120 + trial * 5, h = 90 + trial * 3;
        std::vector<ScissorRect> rects = random_rects(rng, size_t(2 + trial * 7));
        const float share = float(trial % 5) / 4.0f;  // none, a quarter, ... every light shadowed
        std::vector<bool> shadowed;
        for (size_t i = 0; i < rects.size(); ++i) shadowed.push_back(unit(rng) < share);
        const int ts = 8 << (trial % 3), n = 1 + trial % 9, b = 1 + (trial * 13) % 40, k = 1 + trial % 8;
        SCOPED_TRACE(testing::Message() << "trial " << trial << " ts " << ts << " n " << n << " b " << b << " k " << k);
        check_plan(rects, w, h, ts, n, b, nullptr, &shadowed, k);
        const TileDepth depth = random_depth(rng, rects.size(), ((w + ts - 1) / ts) * ((h + ts - 1) / ts));
        check_plan(rects, w, h, ts, n, b, &depth, &shadowed, k);
        // The groups: the same cuts, at lights_per_pass lights a group.
        const TilePlan groups = plan_tile_groups(rects, w, h, ts, n, &depth, &shadowed, k);
        check_shadow_cuts(groups.batches, plan_tile_groups(rects, w, h, ts, n, &depth).batches, shadowed, n, k);
        ASSERT_EQ(groups.draws.size(), groups.batches.size());
        for (size_t g = 0; g < groups.batches.size(); ++g)
            for (const TileQuad& q : groups.draws[g].quads) EXPECT_EQ(q.slots.size(), groups.batches[g].size());
    }
    const std::vector<bool> one{true};  // a shadowed light and no slot for it: a caller's bug
    EXPECT_THROW(cut_batches({0}, 1, &one, 0), std::logic_error);
}

// The planner given tiles_kept's lists (auto's culling, done once to price the lights) plans
// exactly what it plans when it culls itself: the same batches, quads and slots, draw by draw.
TEST(TilePlan, KeptTilesPlanAsTheCullingDoes) {
    std::mt19937 rng(31);
    for (int trial = 0; trial < 24; ++trial) {
        const int w = 131 + trial * 11, h = 77 + trial * 7;
        std::vector<ScissorRect> rects = random_rects(rng, size_t(2 + trial * 11));
        const int ts = 8 << (trial % 3), n = 1 + trial % 9, b = 1 + (trial * 13) % 70;
        SCOPED_TRACE(testing::Message() << "trial " << trial);
        const TileDepth depth = random_depth(rng, rects.size(), ((w + ts - 1) / ts) * ((h + ts - 1) / ts));
        for (const TileDepth* d : {static_cast<const TileDepth*>(nullptr), &depth}) {
            const std::vector<std::vector<int>> kept = tiles_kept(rects, w, h, ts, d);
            TilePlanner culling(rects, w, h, ts, n, b, d), given(rects, w, h, ts, n, b, nullptr, &kept);
            ASSERT_EQ(culling.batches(), given.batches());
            for (int k = 0; k < int(culling.batches().size()); ++k) {
                std::vector<TileDraw> a, g;
                EXPECT_EQ(culling.plan_batch(k, a), given.plan_batch(k, g));
                ASSERT_EQ(a.size(), g.size());
                for (size_t i = 0; i < a.size(); ++i) {
                    ASSERT_EQ(a[i].quads.size(), g[i].quads.size());
                    for (size_t q = 0; q < a[i].quads.size(); ++q) {
                        const TileQuad &x = a[i].quads[q], &y = g[i].quads[q];
                        EXPECT_TRUE(x.x0 == y.x0 && x.y0 == y.y0 && x.x1 == y.x1 && x.y1 == y.y1);
                        EXPECT_TRUE(std::equal(x.slots.begin(), x.slots.end(), y.slots.begin(), y.slots.end()));
                    }
                }
            }
        }
    }
}

// tile_box holds every surface point of its pixels (pixel centres on their view rays, z in the
// span), computed as light.frag reconstructs it; an empty span gives an empty box.
TEST(TilePlan, TileBoxHoldsEverySurfacePointOfItsPixels) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    EXPECT_TRUE(tile_box(DepthSpan{1e30f, -1e30f}, 0, 0, 8, 8, glm::vec4(0.01f, 0.01f, -1, -1)).empty);
    // xy_slack widens x and y by that fraction of their magnitude, not z.
    const TileBox tight = tile_box(DepthSpan{-4, -2}, 0, 0, 8, 8, glm::vec4(0.01f, 0.01f, -1, -1));
    const TileBox slack = tile_box(DepthSpan{-4, -2}, 0, 0, 8, 8, glm::vec4(0.01f, 0.01f, -1, -1), 0.5f);
    EXPECT_FLOAT_EQ(slack.lo.x, tight.lo.x * 1.5f);  // lo.x = -4: the largest magnitude
    EXPECT_FLOAT_EQ(slack.hi.x, tight.hi.x + 0.5f * std::fabs(tight.lo.x));
    EXPECT_EQ(slack.lo.z, tight.lo.z);
    EXPECT_EQ(slack.hi.z, tight.hi.z);
    for (int trial = 0; trial < 300; ++trial) {
        const int w = 64 + trial, h = 48 + trial, ts = 8 << (trial % 3);
        const glm::vec4 map(2.0f * (0.2f + u(rng)) / float(w), 2.0f * (0.2f + u(rng)) / float(h), -(0.2f + u(rng)), -(0.2f + u(rng)));
        const int x0 = (trial * 7) % w / ts * ts, y0 = (trial * 5) % h / ts * ts;
        const int x1 = std::min(w, x0 + ts), y1 = std::min(h, y0 + ts);
        const float zlo = -std::pow(10.0f, 3.0f * u(rng)), zhi = zlo * u(rng);
        const TileBox b = tile_box(DepthSpan{zlo, zhi}, float(x0), float(y0), float(x1), float(y1), map);
        ASSERT_FALSE(b.empty);
        for (int k = 0; k < 200; ++k) {
            const float px = float(x0 + int(u(rng) * float(x1 - x0 - 1) + 0.5f)) + 0.5f;
            const float py = float(y0 + int(u(rng) * float(y1 - y0 - 1) + 0.5f)) + 0.5f;
            const float z = zlo + (zhi - zlo) * u(rng);
            const glm::vec3 ray(px * map.x + map.z, py * map.y + map.w, -1.0f);
            const glm::vec3 p(ray.x / ray.z * z, ray.y / ray.z * z, z);  // light.frag's pos
            const float e = 1e-5f * std::fabs(z) * 4.0f;  // the rounding sphere_meets_box's margin covers
            EXPECT_TRUE(p.x >= b.lo.x - e && p.x <= b.hi.x + e && p.y >= b.lo.y - e && p.y <= b.hi.y + e &&
                        p.z >= b.lo.z && p.z <= b.hi.z)
                << "trial " << trial << " point " << p.x << "," << p.y << "," << p.z;
        }
    }
}

// sphere_meets_box against sampling: true wherever a point of the box lies in the sphere, false
// where the box's nearest point is clearly outside it; an unbounded light meets every non-empty box.
TEST(TilePlan, SphereMeetsBoxAgainstSampling) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    TileBox box{glm::vec3(0), glm::vec3(1), false};
    EXPECT_TRUE(sphere_meets_box(LightBound{}, box));
    box.empty = true;
    EXPECT_FALSE(sphere_meets_box(LightBound{}, box));
    int met = 0, missed = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        TileBox b;
        b.lo = glm::vec3(u(rng), u(rng), u(rng)) * 10.0f - 5.0f;
        b.hi = b.lo + glm::vec3(u(rng), u(rng), u(rng)) * 3.0f;
        b.empty = false;
        const LightBound l{glm::vec3(u(rng), u(rng), u(rng)) * 14.0f - 7.0f, u(rng) * 6.0f};
        bool inside = false;  // a sampled point of the box (faces included) within the sphere
        for (int k = 0; k < 400 && !inside; ++k) {
            glm::vec3 t(u(rng), u(rng), u(rng));
            if (k % 4 == 0) t[k % 3] = float((k / 4) % 2);  // on a face
            const glm::vec3 p = b.lo + t * (b.hi - b.lo);
            inside = glm::length(p - l.centre) <= l.radius;
        }
        const glm::vec3 nearest = glm::clamp(l.centre, b.lo, b.hi);
        const bool clearly_out = glm::length(nearest - l.centre) > l.radius * 1.001f + 1e-3f;
        const bool meets = sphere_meets_box(l, b);
        if (inside) {
            EXPECT_TRUE(meets) << "trial " << trial;
        }
        if (clearly_out) {
            EXPECT_FALSE(meets) << "trial " << trial;
        }
        met += meets, missed += !meets;
    }
    EXPECT_GT(met, 300);  // both outcomes exercised
    EXPECT_GT(missed, 300);
}

// The culling's four-lane test (tiles_kept's, four tiles of a row at once) answers as
// sphere_meets_box in every lane, to the bit: random boxes and spheres, spheres grown or shrunk to
// within a few float steps of touching their box (where the margin and the rounding decide),
// empty boxes and unbounded lights.
TEST(TilePlan, FourLaneTestIsMeets) {
    std::mt19937 rng(41);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int met = 0, missed = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        std::array<TileBox, 4> boxes;
        for (TileBox& b : boxes) {
            b.lo = glm::vec3(u(rng), u(rng), u(rng)) * 40.0f - glm::vec3(20, 20, 60);
            b.hi = b.lo + glm::vec3(u(rng), u(rng), u(rng)) * 4.0f;
            b.empty = u(rng) < 0.1f;
        }
        LightBound l{glm::vec3(u(rng), u(rng), u(rng)) * 40.0f - glm::vec3(20, 20, 60), u(rng) * 8.0f};
        if (trial % 11 == 5) l.radius = -1;  // directional: unbounded
        if (trial % 3 == 1 && l.radius >= 0) {
            // Touching lane 0's box, give or take a few float steps.
            const glm::vec3 nearest = glm::clamp(l.centre, boxes[0].lo, boxes[0].hi);
            float r = glm::length(nearest - l.centre);
            for (int k = int(u(rng) * 16.0f) - 8; k != 0; k += k > 0 ? -1 : 1)
                r = std::nextafter(r, k > 0 ? INFINITY : 0.0f);
            l.radius = r;
        }
        for (int lane = 0; lane < 4; ++lane) {
            const bool want = sphere_meets_box(l, boxes[size_t(lane)]);
            EXPECT_EQ(meets_four_lanes(l, boxes, lane), want) << "trial " << trial << " lane " << lane;
            met += want, missed += !want;
        }
    }
    EXPECT_GT(met, 5000);  // both outcomes exercised
    EXPECT_GT(missed, 5000);
}

TEST(TilePlan, OneDrawPerLayerNotPerTile) {
    // 64 lights over the whole 256x256 screen, 8 per pass, one batch: 8 draws of 64 tiles each,
    // every tile with the same lights, so one quad a draw.
    std::vector<ScissorRect> rects(64, ScissorRect{0, 0, 256, 256});
    const TilePlan plan = plan_tiles(rects, 256, 256, 32, 8, 128);
    ASSERT_EQ(plan.batches.size(), 1u);
    ASSERT_EQ(plan.draws.size(), 8u);
    for (const TileDraw& d : plan.draws) {
        ASSERT_EQ(d.quads.size(), 1u);
        const TileQuad& q = d.quads[0];
        EXPECT_EQ(q.slots.size(), 8u);
        EXPECT_EQ(q.x0, 0);
        EXPECT_EQ(q.x1, 256);
        EXPECT_EQ(q.y0, 0);
        EXPECT_EQ(q.y1, 256);
    }
    EXPECT_EQ(plan.tile_light_pairs, 64 * 64);
}

TEST(TilePlan, MortonOrderKeepsNeighboursTogether) {
    EXPECT_EQ(morton2(0, 0), 0u);
    EXPECT_EQ(morton2(1, 0), 1u);
    EXPECT_EQ(morton2(0, 1), 2u);
    EXPECT_EQ(morton2(3, 3), 15u);
    EXPECT_EQ(morton2(0xffff, 0xffff), 0xffffffffu);
    // Two clusters of small lights far apart, batch size = cluster size: each batch one cluster.
    std::vector<ScissorRect> rects;
    for (int i = 0; i < 16; ++i) {
        const int off = (i % 2) ? 400 : 0;  // interleaved in the input
        rects.push_back(ScissorRect{off + i, off + i, off + i + 8, off + i + 8});
    }
    const TilePlan plan = plan_tiles(rects, 512, 512, 32, 8, 8);
    ASSERT_EQ(plan.batches.size(), 2u);
    for (const auto& batch : plan.batches)
        for (int l : batch) EXPECT_EQ(l % 2, batch[0] % 2);
}

// The groups plan: every light in exactly one group of at most N; each group one draw whose quads
// are exactly the tiles its lights overlap, each carrying the whole group.
TEST(TilePlan, GroupsCoverTheUnionOfTheirLightsTiles) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 20; ++trial) {
        const int w = 150 + trial, h = 110 + 2 * trial, ts = 8 << (trial % 3), n = 1 + trial % 8;
        std::vector<ScissorRect> rects = random_rects(rng, size_t(3 + 7 * trial), -30, 200, 120);
        const int tiles_x = (w + ts - 1) / ts, tiles_y = (h + ts - 1) / ts;
        const TileDepth depth = random_depth(rng, rects.size(), tiles_x * tiles_y);
        const bool cull = trial % 2 == 1;  // odd trials with depth culling
        const TilePlan plan = plan_tile_groups(rects, w, h, ts, n, cull ? &depth : nullptr);
        auto meets = [&](int l, int x, int y) {
            return !cull || share_a_z(depth, l, y * tiles_x + x);
        };
        ASSERT_EQ(plan.draws.size(), plan.batches.size());
        std::set<int> seen;
        for (size_t g = 0; g < plan.batches.size(); ++g) {
            const auto& group = plan.batches[g];
            EXPECT_LE(int(group.size()), n);
            for (int l : group) EXPECT_TRUE(seen.insert(l).second) << "light " << l << " in two groups";
            std::set<std::pair<int, int>> want, got;
            for (int l : group) {
                const ScissorRect& r = rects[size_t(l)];
                for (int y = 0; y * ts < h; ++y)
                    for (int x = 0; x * ts < w; ++x)
                        if (std::max(r.x0, x * ts) < std::min({r.x1, (x + 1) * ts, w}) &&
                            std::max(r.y0, y * ts) < std::min({r.y1, (y + 1) * ts, h}) && meets(l, x, y))
                            want.insert({x, y});
            }
            for (const TileQuad& q : plan.draws[g].quads) {
                got.insert({q.x0 / ts, q.y0 / ts});
                EXPECT_EQ(q.slots.size(), group.size());
            }
            EXPECT_EQ(got, want) << "trial " << trial << " group " << g;
        }
        for (int i = 0; i < int(rects.size()); ++i) {
            const ScissorRect& r = rects[size_t(i)];
            bool reaches = false;  // some tile its rectangle overlaps and (culling) whose span it meets
            for (int y = 0; y < tiles_y; ++y)
                for (int x = 0; x < tiles_x; ++x)
                    reaches = reaches || (std::max(r.x0, x * ts) < std::min({r.x1, (x + 1) * ts, w}) &&
                                          std::max(r.y0, y * ts) < std::min({r.y1, (y + 1) * ts, h}) && meets(i, x, y));
            EXPECT_EQ(seen.count(i) == 1, reaches) << "light " << i;
        }
    }
}
