// The auto geometry's rules from frame to frame (src/deferred/auto_policy.h), pure: each rule as
// the header states it, checked over every case or a table, the expected decisions written here
// from the rule, not from the code.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "deferred/auto_policy.h"

namespace dsr {

namespace {

using Counts = std::array<int, kLightPaths>;

// How many frames in a row keep a priced frame's choice, frames of `lights` lights (keep_frame()
// spent on each), at most 100.
int frames_kept(AutoPolicy& policy, size_t lights, bool tiles_cull) {
    int n = 0;
    while (n < 100 && policy.keeps(lights, tiles_cull)) {
        policy.keep_frame();
        ++n;
    }
    return n;
}

}  // namespace

// keep: every split of n lights over the three paths, explored or not: a choice with every light
// on quads or every light on the tiles, not explored, is kept for the next 7 frames with as many
// lights (8 frames: one priced, seven kept); any other split is kept for none. A frame with another
// count of lights keeps nothing, nor do kept tiles where the tiles do not cull by spans.
TEST(AutoPolicy, AnAllQuadsOrAllTilesChoiceIsKeptSevenFrames) {
    for (int n = 0; n <= 4; ++n)
        for (int q = 0; q <= n; ++q)
            for (int v = 0; q + v <= n; ++v)
                for (const bool explored : {false, true}) {
                    const int t = n - q - v;
                    const Counts count = {q, v, t};
                    const bool all_quads = n > 0 && q == n, all_tiles = n > 0 && t == n;
                    const bool kept = !explored && (all_quads || all_tiles);
                    const std::string what = "split " + std::to_string(q) + "/" + std::to_string(v) + "/" +
                                             std::to_string(t) + (explored ? " explored" : "");
                    {
                        AutoPolicy p(PathClock::wall);
                        const std::optional<LightPath> path = p.priced(count, size_t(n), explored);
                        EXPECT_EQ(path.has_value(), kept) << what;
                        if (kept) {
                            EXPECT_EQ(*path, all_quads ? LightPath::quad : LightPath::tiles) << what;
                            EXPECT_EQ(p.kept_path(), path) << what;
                        }
                        EXPECT_FALSE(p.keeps(size_t(n) + 1, true)) << what << ": another count of lights";
                        EXPECT_EQ(frames_kept(p, size_t(n), true), kept ? 7 : 0) << what;
                        EXPECT_FALSE(p.keeps(size_t(n), true)) << what << ": kept past its frames";
                    }
                    AutoPolicy p(PathClock::wall);
                    p.priced(count, size_t(n), explored);
                    EXPECT_EQ(frames_kept(p, size_t(n), false), kept && all_quads ? 7 : 0) << what << " without spans";
                }
}

// keep: a new priced frame replaces the choice, and a split one ends the keeping.
TEST(AutoPolicy, APricedFrameReplacesTheKeptChoice) {
    AutoPolicy p(PathClock::gpu_stamps);
    p.priced({5, 0, 0}, 5, false);
    EXPECT_EQ(frames_kept(p, 5, true), 7);
    p.priced({0, 0, 6}, 6, false);
    EXPECT_EQ(p.kept_path(), LightPath::tiles);
    ASSERT_TRUE(p.keeps(6, true));
    p.keep_frame();
    p.priced({3, 3, 0}, 6, false);
    EXPECT_FALSE(p.kept_path().has_value());
    EXPECT_FALSE(p.keeps(6, true));
}

// explore: repeating frames that explore the first path the policy allows, every path not
// measured that the frame can draw is explored, each in exactly 4 frames; a measured path or one
// the frame cannot draw never. Over every set of measured and drawable paths.
TEST(AutoPolicy, ExplorationVisitsEveryCandidateFourFramesAtMost) {
    for (int measured_bits = 0; measured_bits < 8; ++measured_bits)
        for (int drawable_bits = 0; drawable_bits < 8; ++drawable_bits) {
            std::array<bool, kLightPaths> measured{}, drawable{};
            for (int i = 0; i < kLightPaths; ++i) {
                measured[size_t(i)] = (measured_bits >> i) & 1;
                drawable[size_t(i)] = (drawable_bits >> i) & 1;
            }
            AutoPolicy p(PathClock::wall);
            std::array<int, kLightPaths> frames{};
            for (int frame = 0; frame < 40; ++frame) {
                const std::array<bool, kLightPaths> e = p.may_explore(measured, drawable);
                for (int i = 0; i < kLightPaths; ++i)
                    if (e[size_t(i)]) {
                        p.explored(LightPath(i));
                        ++frames[size_t(i)];
                        break;
                    }
            }
            for (int i = 0; i < kLightPaths; ++i)
                EXPECT_EQ(frames[size_t(i)], !measured[size_t(i)] && drawable[size_t(i)] ? 4 : 0)
                    << "path " << i << ", measured " << measured_bits << ", drawable " << drawable_bits;
        }
}

// rest: spans the policy rests are not measured in the next 8 frames that would measure them,
// then are; an exploring frame that measured them wakes them at once.
TEST(AutoPolicy, TheSpansRestEightFrames) {
    AutoPolicy p(PathClock::wall);
    EXPECT_TRUE(p.spans_awake());
    EXPECT_TRUE(p.measure_spans());
    p.rest_spans();
    std::vector<bool> measured;
    for (int frame = 0; frame < 10; ++frame) {
        measured.push_back(p.measure_spans());
        if (frame < 7) EXPECT_FALSE(p.spans_awake()) << "frame " << frame;
    }
    EXPECT_EQ(measured, (std::vector<bool>{false, false, false, false, false, false, false, false, true, true}));
    p.rest_spans();
    EXPECT_FALSE(p.measure_spans());
    p.wake_spans();
    EXPECT_TRUE(p.spans_awake());
    EXPECT_TRUE(p.measure_spans());
}

// time, on the wall clock, a path's draws in a table: the first never (it compiles); of its priced
// draws one in 4, the second first (draws 1, 5, 9); an exploring draw after the first, always; an
// unpriced draw never, and not counted.
TEST(AutoPolicy, OnTheWallClockOnePricedDrawInFourIsTimed) {
    struct Draw {
        bool priced, exploring, timed;
    };
    const std::vector<Draw> table = {
        {true, false, false},   // priced draw 0: the first, compiling
        {true, false, true},    // 1
        {true, false, false},   // 2
        {false, false, false},  // unpriced, not counted
        {true, false, false},   // 3
        {true, true, true},     // 4, exploring
        {true, false, true},    // 5
        {false, true, false},   // unpriced though exploring
        {true, false, false},   // 6
        {true, false, false},   // 7
        {true, false, false},   // 8
        {true, false, true},    // 9
    };
    for (const LightPath path : kAllLightPaths) {
        AutoPolicy p(PathClock::wall);
        for (size_t i = 0; i < table.size(); ++i)
            EXPECT_EQ(p.time_draw(path, table[i].priced, table[i].exploring), table[i].timed)
                << light_path_name(path) << " draw " << i;
    }
    AutoPolicy p(PathClock::wall);
    EXPECT_FALSE(p.time_draw(LightPath::tiles, true, true)) << "an exploring path's first draw compiles";
    EXPECT_TRUE(p.time_draw(LightPath::tiles, true, true));
}

// time, brute force: random sequences of draws of the three paths interleaved. Each path counts
// its own draws: on the wall clock its priced, not exploring draws are timed exactly at the
// priced draws numbered 1, 5, 9, ... of that path; on GPU stamps every draw but each path's
// first; with no clock none.
TEST(AutoPolicy, EachPathCountsItsOwnDrawsAgainstBruteForce) {
    std::mt19937 rng(7);
    for (int run = 0; run < 200; ++run) {
        AutoPolicy wall(PathClock::wall), gpu(PathClock::gpu_stamps), none(PathClock::none);
        std::array<int, kLightPaths> priced_seen{}, drawn{};
        for (int d = 0; d < 60; ++d) {
            const LightPath path = LightPath(rng() % kLightPaths);
            const bool priced = rng() % 4 != 0, exploring = rng() % 5 == 0;
            const int k = priced_seen[at(path)];
            const bool first = drawn[at(path)] == 0;
            const bool expect_wall = !first && priced && (exploring || k % 4 == 1);
            EXPECT_EQ(wall.time_draw(path, priced, exploring), expect_wall) << "run " << run << " draw " << d;
            EXPECT_EQ(gpu.time_draw(path, priced, exploring), !first) << "run " << run << " draw " << d;
            EXPECT_FALSE(none.time_draw(path, priced, exploring));
            priced_seen[at(path)] += priced;
            ++drawn[at(path)];
        }
    }
}

// paths_measured: a path is measured once it has kExploreSamples measurements; given scales count as measured.
TEST(AutoPolicy, APathIsMeasuredAfterItsSamples) {
    LightCostCalibration c;
    EXPECT_EQ(paths_measured(c), (std::array<bool, kLightPaths>{false, false, false}));
    for (int i = 0; i < LightCostCalibration::kExploreSamples; ++i) {
        EXPECT_FALSE(paths_measured(c)[at(LightPath::volume)]);
        c.add(LightPath::volume, 2, 1);
    }
    EXPECT_EQ(paths_measured(c), (std::array<bool, kLightPaths>{false, true, false}));
    EXPECT_EQ(paths_measured(LightCostCalibration({1, 1, 1})), (std::array<bool, kLightPaths>{true, true, true}));
}

}  // namespace dsr
