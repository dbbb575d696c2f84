// The auto geometry's cost model (src/deferred/light_cost.h), pure: the choice against every
// assignment of paths to lights, the tiles' cover against a tile-by-tile check, the calibration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "deferred/light_cost.h"
#include "dsr_error.h"

namespace dsr {

namespace {

LightCostModel test_model() {
    LightCostModel m = default_light_costs(true);
    m.handoff_mpx_ms = 3;  // large enough that leaving volumes out is sometimes right
    m.handoff_pass_mpx_ms = 3.5;
    m.handoff_ambient_mpx_ms = 4, m.ambient_mpx_ms = 1.5;  // where the hand-off writes the ambient term: 2.5
    m.spans_mpx_ms = 8;
    return m;
}

// The hand-off's price by its definition (light_cost.h): the blit or pass, or where it writes the
// ambient term, that pass less the ambient pass, never below 0.
double handoff_of(const LightCostModel& m, double screen_px) {
    const double net = m.handoff_ambient_mpx_ms - m.ambient_mpx_ms;
    const double own = m.handoff_pass ? m.handoff_pass_mpx_ms : m.handoff_mpx_ms;
    return (m.handoff_writes_ambient ? (net > 0 ? net : 0) : own) * screen_px * 1e-6;
}

// test_model with trial's hand-off: a blit, a pass, one that writes the ambient term, or one whose
// pass costs less than the ambient pass it spares.
LightCostModel trial_model(int trial) {
    LightCostModel m = test_model();
    m.handoff_pass = trial % 4 == 1;
    m.handoff_writes_ambient = trial % 4 >= 2;
    if (trial % 4 == 3) m.ambient_mpx_ms = 5;
    return m;
}

// The total the model gives an assignment, computed from its definition; depth: the quads drawn
// against the scene's depth, each its quad price less its saving (`saving`, unscaled), the
// hand-off paid for them.
double total_of(const std::vector<LightFeature>& ls, const TileGrid& grid, double screen_px, const LightCostModel& m,
                const std::array<double, kLightPaths>& scale, const std::vector<int>& a, bool spans_paid,
                bool depth = false, const std::vector<double>& saving = {}) {
    double t = 0;
    bool used[3] = {false, false, false};
    for (size_t i = 0; i < ls.size(); ++i) {
        t += light_prices(ls[i], grid, m, scale)[size_t(a[i])];
        if (depth && a[i] == 0) t -= saving[i] * scale[0];
        used[a[i]] = true;
    }
    const bool volume = used[1], tiles = used[2];
    t += m.path_ms * (int(used[0]) + int(used[1]) + int(used[2]));
    if (volume || (depth && used[0])) t += handoff_of(m, screen_px);
    if (tiles && !spans_paid) t += m.spans_mpx_ms * screen_px * 1e-6;
    return t;
}

}  // namespace

// Over random frames of up to 7 lights, choose_light_paths' total is the least over all 3^n
// assignments (each light on any path it may take), per-frame costs included; where the quads may
// test the scene's depth (every other trial), the least over the assignments with the quads drawn
// either way.
TEST(LightCost, ChoiceIsTheCheapestAssignment) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    int depth_plans = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const LightCostModel m = trial_model(trial / 4);
        const int n = 1 + trial % 7;
        TileGrid grid;
        grid.tile_px = 256;
        grid.lights_per_pass = 4;
        grid.lights.assign(64, 0);
        std::vector<LightFeature> ls(static_cast<size_t>(n));
        for (LightFeature& l : ls) {
            l.rect_px = std::pow(10.0, 2 + 4 * u(rng));
            l.volume_ok = u(rng) > 0.2;
            l.tiles_ok = u(rng) > 0.1;
            for (int t = 0; t < 64; ++t)
                if (u(rng) < 0.3) {
                    l.tiles.push_back(t);
                    ++grid.lights[size_t(t)];
                }
        }
        const std::array<double, kLightPaths> scale = {0.5 + u(rng), 0.5 + u(rng), 0.5 + u(rng)};
        const bool spans_paid = trial % 2 == 0;
        const double screen = 65536 * (1 + 4 * u(rng));
        const bool may_test_depth = trial % 4 >= 2;
        std::vector<double> saving(size_t(n), 0.0);
        for (size_t i = 0; i < size_t(n); ++i)
            if (u(rng) > 0.2) saving[i] = 0.5 * u(rng) * m.quad_mpx_ms * ls[i].rect_px * 1e-6;
        const LightPathPlan p = choose_light_paths(price_lights(ls, grid, m), screen, m, scale, {true, true, true},
                                                   spans_paid, may_test_depth ? &saving : nullptr);
        double best = std::numeric_limits<double>::infinity();
        std::vector<int> a(size_t(n), 0);
        for (int code = 0; code < int(std::pow(3, n)); ++code) {
            int c = code;
            for (int i = 0; i < n; ++i, c /= 3) a[size_t(i)] = c % 3;
            for (const bool depth : {false, true})
                if (!depth || may_test_depth)
                    best = std::min(best, total_of(ls, grid, screen, m, scale, a, spans_paid, depth, saving));
        }
        std::vector<int> chosen;
        for (LightPath x : p.path) chosen.push_back(int(x));
        EXPECT_TRUE(may_test_depth || !p.quads_depth) << "trial " << trial;
        EXPECT_TRUE(!p.quads_depth || p.count[0] > 0) << "trial " << trial;
        const double got = total_of(ls, grid, screen, m, scale, chosen, spans_paid, p.quads_depth, saving);
        depth_plans += p.quads_depth;
        ASSERT_NEAR(got, best, 1e-9 * best) << "trial " << trial;
        EXPECT_NEAR(p.predicted_total_ms, got, 1e-9 * got) << "trial " << trial;
        int counted = 0;
        for (int k = 0; k < kLightPaths; ++k) counted += p.count[size_t(k)];
        EXPECT_EQ(counted, n);
    }
    EXPECT_GT(depth_plans, 10);  // the quads drawn against the depth were chosen, and not always
    EXPECT_LT(depth_plans, 140);
}

TEST(LightCost, PathsNotAllowedAreNotChosen) {
    const LightCostModel m = test_model();
    TileGrid grid;
    grid.lights.assign(4, 1);
    LightFeature big;
    big.rect_px = 1e6;
    big.tiles = {0, 1, 2, 3};
    const LightPathPlan all = choose_light_paths({big}, grid, 1e6, m, {1, 1, 1}, {true, true, true}, true);
    EXPECT_NE(all.path[0], LightPath::quad);  // a million-pixel rectangle through the shader: the dearest
    const LightPathPlan quads = choose_light_paths({big}, grid, 1e6, m, {1, 1, 1}, {true, false, false}, true);
    EXPECT_EQ(quads.path[0], LightPath::quad);
    LightFeature no_volume = big;
    no_volume.volume_ok = no_volume.tiles_ok = false;
    EXPECT_EQ(choose_light_paths({no_volume}, grid, 1e6, m, {1, 1, 1}, {true, true, true}, true).path[0], LightPath::quad);
}

// Where the hand-off's pass writes the ambient term, the volumes and the quads drawn against the
// depth pay only what it costs beyond the ambient pass it spares the frame. On the GPU's constants
// the default scene's three lights (about 1 Mpx of rectangle each at 1920x1080) go by quads where
// the hand-off is charged as a blit; where it is charged its pass less the ambient pass, by volumes,
// or where the quads may test the depth, by quads drawn so (an H100, where the hand-off wrote the
// ambient term: the volumes' frame 1.71 ms, the plain quads' 1.77; docs/gpu.md).
TEST(LightCost, HandoffWritingTheAmbientCostsItsPassLessTheAmbientPass) {
    LightCostModel m = default_light_costs(false);
    const double screen = 1920.0 * 1080.0;
    std::vector<LightFeature> ls(3);
    for (LightFeature& l : ls) {
        l.rect_px = 1.05e6;
        l.tiles_ok = false;
    }
    const auto paths = [&] {
        return choose_light_paths(ls, TileGrid{}, screen, m, {1, 1, 1}, {true, true, false}, true).count;
    };
    const auto with_depth = [&] {
        const std::vector<double> saving = quad_depth_savings(ls, m);
        return choose_light_paths(price_lights(ls, TileGrid{}, m), screen, m, {1, 1, 1}, {true, true, false}, true,
                                  &saving);
    };
    EXPECT_NEAR(handoff_ms(m, screen), m.handoff_mpx_ms * screen * 1e-6, 1e-12);
    EXPECT_EQ(paths()[int(LightPath::quad)], 3);
    m.handoff_pass = true;
    EXPECT_NEAR(handoff_ms(m, screen), m.handoff_pass_mpx_ms * screen * 1e-6, 1e-12);
    m.handoff_writes_ambient = true;
    EXPECT_EQ(handoff_ms(m, screen), 0.0);  // its pass cost less than the ambient pass it spares
    EXPECT_EQ(paths()[int(LightPath::volume)], 3);
    const LightPathPlan d = with_depth();
    EXPECT_EQ(d.count[int(LightPath::quad)], 3);
    EXPECT_TRUE(d.quads_depth);
    m.handoff_writes_ambient = false;
    EXPECT_FALSE(with_depth().quads_depth);  // a pass hand-off, 0.27 ms, to save 3 Mpx of quads 0.063
    m.handoff_writes_ambient = true;
    m.handoff_ambient_mpx_ms = m.ambient_mpx_ms + 0.05;
    EXPECT_NEAR(handoff_ms(m, screen), 0.05 * screen * 1e-6, 1e-12);
}

// The tiles each light keeps, against a tile-by-tile check of its rectangle and its sphere
// against each tile's box; and each tile's count of lights.
TEST(LightCost, TileCoverMatchesTileByTile) {
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> px(-20, 150);
    std::uniform_real_distribution<float> u(0, 1);
    const int w = 120, h = 90, ts = 16, tx = (w + ts - 1) / ts, ty = (h + ts - 1) / ts;
    TileDepth depth;
    for (int t = 0; t < tx * ty; ++t) {
        TileBox b;
        b.empty = u(rng) < 0.15;
        b.lo = {u(rng) * 4 - 2, u(rng) * 4 - 2, -8 + 2 * u(rng)};
        b.hi = b.lo + glm::vec3(u(rng), u(rng), 3 * u(rng));
        depth.tiles.push_back(b);
    }
    std::vector<ScissorRect> rects;
    for (int i = 0; i < 40; ++i) {
        ScissorRect r{px(rng), px(rng), 0, 0};
        r.x1 = r.x0 + px(rng) / 2, r.y1 = r.y0 + px(rng) / 2;
        rects.push_back(r);
        depth.lights.push_back(LightBound{{u(rng) * 4 - 2, u(rng) * 4 - 2, -9 + 8 * u(rng)}, i % 9 == 0 ? -1 : 2 * u(rng)});
    }
    for (const TileDepth* cull : {static_cast<const TileDepth*>(nullptr), static_cast<const TileDepth*>(&depth)}) {
        std::vector<LightFeature> ls;
        TileGrid grid;
        tile_cover(rects, w, h, ts, cull, ls, grid);
        ASSERT_EQ(ls.size(), rects.size());
        std::vector<int> count(size_t(tx * ty), 0);
        for (size_t i = 0; i < rects.size(); ++i) {
            std::vector<int> want;
            for (int t = 0; t < tx * ty; ++t) {
                const int x0 = (t % tx) * ts, y0 = (t / tx) * ts;
                const ScissorRect& r = rects[i];
                const bool overlaps = r.x0 < std::min(w, x0 + ts) && x0 < r.x1 && r.y0 < std::min(h, y0 + ts) && y0 < r.y1 &&
                                      r.x1 > r.x0 && r.y1 > r.y0;
                bool kept = overlaps;
                if (kept && cull) {
                    const TileBox& b = depth.tiles[size_t(t)];
                    kept = !b.empty && (depth.lights[i].radius < 0 || sphere_meets_box(depth.lights[i], b));
                }
                if (kept) want.push_back(t), ++count[size_t(t)];
            }
            EXPECT_EQ(ls[i].tiles, want) << "light " << i << (cull ? " culled" : "") << " rect " << rects[i].x0 << " "
                                         << rects[i].y0 << " " << rects[i].x1 << " " << rects[i].y1;
        }
        EXPECT_EQ(grid.lights, count);
        EXPECT_EQ(grid.tile_px, ts * ts);
    }
}

// price_lights computes each tile's share once; its prices are light_prices' to the bit, over
// random frames with and without tiles, volumes refused and tiles refused.
TEST(LightCost, PriceLightsIsLightPrices) {
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> tile(0, 59), count(0, 40);
    std::uniform_real_distribution<double> u(0, 1);
    const LightCostModel m = test_model();
    for (int trial = 0; trial < 50; ++trial) {
        TileGrid grid;
        grid.tile_px = 256;
        grid.lights_per_pass = 1 + trial % 32;
        grid.lights.resize(60);
        for (int& k : grid.lights) k = count(rng);
        std::vector<LightFeature> ls(20);
        for (LightFeature& l : ls) {
            l.rect_px = 1e5 * u(rng);
            l.volume_ok = u(rng) < 0.8;
            l.tiles_ok = u(rng) < 0.8;
            for (int t = 0, n = count(rng); t < n; ++t) l.tiles.push_back(tile(rng));
        }
        const LightPrices p = price_lights(ls, grid, m);
        ASSERT_EQ(p.size(), ls.size());
        for (size_t i = 0; i < ls.size(); ++i) {
            const std::array<double, kLightPaths> want = light_prices(ls[i], grid, m, {1, 1, 1});
            for (int k = 0; k < kLightPaths; ++k) EXPECT_EQ(p[i][size_t(k)], want[size_t(k)]) << "trial " << trial << " light " << i;
        }
    }
}

// A tile's passes are shared among its lights: the same light is cheaper in tiles where more
// lights keep its tiles (one pass for up to lights_per_pass of them).
TEST(LightCost, TilesShareTheirPasses) {
    const LightCostModel m = test_model();
    LightFeature l;
    l.rect_px = 4096;
    l.tiles = {0, 1};
    TileGrid alone, shared;
    alone.lights = {1, 1};
    shared.lights = {16, 16};
    alone.lights_per_pass = shared.lights_per_pass = 32;
    const double a = light_prices(l, alone, m, {1, 1, 1})[2], s = light_prices(l, shared, m, {1, 1, 1})[2];
    EXPECT_LT(s, a);
    EXPECT_NEAR(a, 2 * 256 * (m.tile_pass_mpx_ms + m.tile_light_mpx_ms) * 1e-6, 1e-12);
    EXPECT_NEAR(s, 2 * 256 * (m.tile_pass_mpx_ms / 16 + m.tile_light_mpx_ms) * 1e-6, 1e-12);
}

// The quads against the scene's depth: on exactly where the frame costs less with it, the quads'
// pixels at the cheaper rate plus a hand-off no volume pays for, computed here light by light.
TEST(LightCost, QuadDepthWhereItPaysForTheHandoff) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double screen = 800.0 * 600.0;
    int on = 0, off = 0, free_handoff = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        LightCostModel m = default_light_costs(trial % 2 == 0);
        m.handoff_writes_ambient = trial % 3 == 0;
        m.handoff_pass = trial % 5 == 0;
        if (trial % 6 == 3) m.handoff_ambient_mpx_ms = m.ambient_mpx_ms + m.handoff_mpx_ms / 2;
        const double scale = 0.2 + 2 * u(rng);
        const int n = 1 + int(u(rng) * 40);
        std::vector<LightFeature> ls(static_cast<size_t>(n));
        LightPathPlan plan;
        for (int i = 0; i < n; ++i) {
            ls[size_t(i)].rect_px = std::pow(10.0, 2 + 3.5 * u(rng));
            ls[size_t(i)].shadowed = u(rng) < 0.2;
            const LightPath p = LightPath(int(u(rng) * 3));
            plan.path.push_back(p);
            ++plan.count[size_t(p)];
        }
        // The frame's quad pixels at each rate, light by light; the hand-off where no volume pays it.
        double plain = 0, tested = 0;
        for (int i = 0; i < n; ++i) {
            if (plan.path[size_t(i)] != LightPath::quad) continue;
            const double mpx = ls[size_t(i)].rect_px * 1e-6;
            plain += scale * m.quad_mpx_ms * mpx;
            tested += scale * (ls[size_t(i)].shadowed ? m.quad_mpx_ms : m.quad_depth_mpx_ms) * mpx;
        }
        const double handoff = plan.count[1] > 0 ? 0 : handoff_of(m, screen);
        const QuadDepthChoice c = choose_quad_depth(plan, ls, screen, m, scale);
        const bool pays = tested + handoff < plain - 1e-12;
        const bool tie = std::abs((tested + handoff) - plain) < 1e-9;
        if (!tie) {
            EXPECT_EQ(c.on, pays) << "trial " << trial;
        }
        if (c.on) {
            ++on;
            EXPECT_NEAR(plain - scale * c.raw_saving_ms, tested, 1e-9);
            EXPECT_DOUBLE_EQ(c.handoff_ms, handoff);
            free_handoff += plan.count[1] > 0;
        } else {
            ++off;
            EXPECT_EQ(c.raw_saving_ms, 0);
        }
    }
    EXPECT_GT(on, 100);  // both answers and the free hand-off were exercised
    EXPECT_GT(off, 100);
    EXPECT_GT(free_handoff, 50);
}

TEST(LightCost, CalibrationFollowsTheMeasuredRatio) {
    LightCostCalibration c;
    c.add(LightPath::tiles, 3.0, 1.0);
    EXPECT_EQ(c.scale()[2], 3.0);  // the first measurement replaces the guess
    c.add(LightPath::tiles, 1.0, 1.0);
    EXPECT_EQ(c.scale()[2], 2.0);  // later ones are averaged with it
    for (int i = 0; i < 20; ++i) c.add(LightPath::tiles, 3.0, 1.0);
    EXPECT_NEAR(c.scale()[2], 3.0, 1e-3);
    EXPECT_EQ(c.scale()[0], 1.0);  // paths not measured keep their scale
    EXPECT_EQ(c.samples(LightPath::tiles), 22);
    EXPECT_EQ(c.samples(LightPath::quad), 0);
    c.add(LightPath::quad, 100.0, 1.0);
    EXPECT_EQ(c.scale()[0], 10.0);  // clamped
    c.add(LightPath::volume, 1.0, 0.0);  // nothing predicted: no information
    EXPECT_EQ(c.scale()[1], 1.0);
    c.add(LightPath::volume, 4.0, 1.0);  // ... so this is the first measurement
    EXPECT_EQ(c.scale()[1], 4.0);
    // Starting scales given (DSR_LIGHT_COST_SCALE) are not a guess: averaged with from the first.
    LightCostCalibration given({1, 1000, 2});
    EXPECT_EQ(given.samples(LightPath::quad), LightCostCalibration::kExploreSamples);  // never explored
    given.add(LightPath::tiles, 4.0, 1.0);
    EXPECT_EQ(given.scale()[2], 3.0);
    given.add(LightPath::volume, 1.0, 1.0);
    EXPECT_EQ(given.scale()[1], 10.0);  // 500.5, clamped
}

// exploration_plan against its definition, over random frames: of the paths to explore that the
// best plan does not draw, each light moved to the path where it can take it; the cheapest such
// plan, where within explore_within of the best, else none.
TEST(LightCost, ExplorationIsTheCheapestUnmeasuredPathWithinItsFactor) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    const double screen_px = 256.0 * 256.0;
    int explored = 0, declined = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const LightCostModel m = trial_model(trial / 2);
        const int n = 1 + trial % 9;
        LightPrices raw(static_cast<size_t>(n));
        for (auto& r : raw)
            for (int k = 0; k < kLightPaths; ++k) r[size_t(k)] = u(rng) < 0.15 ? std::numeric_limits<double>::infinity() : 3 * u(rng);
        const std::array<double, kLightPaths> scale{0.5 + u(rng), 0.5 + u(rng), 0.5 + u(rng)};
        const std::array<bool, kLightPaths> explore{u(rng) < 0.6, u(rng) < 0.6, u(rng) < 0.6};
        const LightPathPlan best = choose_light_paths(raw, screen_px, m, scale, {true, true, true}, trial % 2 == 0);
        if (!(best.predicted_total_ms < std::numeric_limits<double>::infinity())) continue;
        const std::optional<LightExploration> e = exploration_plan(raw, best, screen_px, m, scale, explore, trial % 2 == 0);
        // The definition, path by path.
        int want = -1;
        double want_total = 0;
        std::vector<LightPath> want_paths;
        for (int k = 0; k < kLightPaths; ++k) {
            if (!explore[size_t(k)] || best.count[size_t(k)] > 0) continue;
            std::vector<LightPath> paths = best.path;
            bool used[3] = {false, false, false}, any = false;
            double t = 0;
            for (size_t i = 0; i < raw.size(); ++i) {
                if (std::isfinite(raw[i][size_t(k)])) paths[i] = LightPath(k), any = true;
                t += raw[i][size_t(paths[i])] * scale[size_t(paths[i])];
                used[int(paths[i])] = true;
            }
            if (!any) continue;
            t += m.path_ms * (int(used[0]) + int(used[1]) + int(used[2]));
            if (used[1]) t += handoff_of(m, screen_px);
            if (used[2] && trial % 2 != 0) t += m.spans_mpx_ms * screen_px * 1e-6;
            if (t <= m.explore_within * best.predicted_total_ms * (1 + 1e-12) && (want < 0 || t < want_total))
                want = k, want_total = t, want_paths = paths;
        }
        if (want < 0) {
            EXPECT_FALSE(e.has_value()) << "trial " << trial;
            ++declined;
            continue;
        }
        ASSERT_TRUE(e.has_value()) << "trial " << trial;
        ++explored;
        EXPECT_EQ(int(e->path), want) << "trial " << trial;
        EXPECT_NEAR(e->plan.predicted_total_ms, want_total, 1e-9 * want_total) << "trial " << trial;
        EXPECT_EQ(e->plan.path, want_paths) << "trial " << trial;
        for (int k = 0; k < kLightPaths; ++k)
            EXPECT_EQ(e->plan.count[size_t(k)], std::count(want_paths.begin(), want_paths.end(), LightPath(k)));
    }
    EXPECT_GT(explored, 50);  // both answers exercised
    EXPECT_GT(declined, 50);
    // Nothing to explore, or a path the best plan draws already: none.
    const LightCostModel m = test_model();
    LightPrices raw{{1, 1, 1}};
    const LightPathPlan best = choose_light_paths(raw, screen_px, m, {1, 1, 1}, {true, true, true}, true);
    EXPECT_FALSE(exploration_plan(raw, best, screen_px, m, {1, 1, 1}, {false, false, false}, true).has_value());
    std::array<bool, kLightPaths> only_best{};
    only_best[int(best.path[0])] = true;
    EXPECT_FALSE(exploration_plan(raw, best, screen_px, m, {1, 1, 1}, only_best, true).has_value());
}

// DSR_LIGHT_COST_SCALE: three positive numbers or one clear error.
TEST(LightCost, StartingScalesParse) {
    EXPECT_EQ(parse_cost_scale("1,1000,0.5"), (std::array<double, kLightPaths>{1, 1000, 0.5}));
    for (const char* bad : {"", "1,2", "1,2,3,4", "a,b,c", "0,1,1", "1,-2,1", "1;2;3", "1,2,inf"}) {
        try {
            parse_cost_scale(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("expected three positive numbers"), std::string::npos) << e.what();
        }
    }
}

}  // namespace dsr
