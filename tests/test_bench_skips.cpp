// What each skip saves (analysis/bench_skips.h): which rows pair up, the sign of a saving, and the
// report's table, on hand-made rows; and the order of the rows in the bench's rounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "analysis/bench_skips.h"

using namespace dsr;

namespace {

// A deferred row of the default configuration (depth texture, scissor, RGBA8 G-buffer), quad
// geometry unless given, every skip on unless one is turned off.
bench::Row row(const std::string& scene, const std::string& lights, double ms, bool SkipOptions::*off = nullptr,
               LightGeometry g = LightGeometry::quad) {
    bench::Row r;
    r.scene = scene;
    r.renderer = bench::Renderer::deferred;
    r.depth = DepthPath::texture;
    r.scissor = true;
    r.light_geometry = g;
    r.lights_label = lights;
    r.lights = lights == "own" ? 3 : std::stoi(lights);
    r.w = r.h = 64;
    r.ms_median = ms, r.ms_min = ms - 0.5, r.ms_max = ms + 1.0;
    r.lights_ms = ms / 2;
    if (off) r.skip.*off = false;
    return r;
}

}  // namespace

TEST(BenchSkips, EachSkipRowAgainstTheEverySkipQuadRowOfItsVariant) {
    std::vector<bench::Row> rows = {
        row("default", "own", 9.0, nullptr, LightGeometry::automatic),  // another geometry's every-skip row: not the base
        row("default", "own", 10.0),
        row("default", "own", 12.5, &SkipOptions::depth_prepass),
        row("default", "own", 9.25, &SkipOptions::final_pass),  // faster with the skip off: a negative saving
        row("default", "256", 20.0),
        row("default", "256", 23.0, &SkipOptions::depth_prepass),
        row("default", "1024", 31.0, &SkipOptions::empty_lights),  // no every-skip row in its variant: left out
    };
    bench::Row half = row("default", "own", 30.0, &SkipOptions::light_sphere_test);
    half.gbuffer_half = true;  // not the default configuration: left out
    rows.push_back(half);
    bench::Row ambient = row("default", "256", 26.0, &SkipOptions::ambient_pass);
    ambient.skip.ambient_target = false;  // the tutorial's ambient pass: both off
    rows.push_back(ambient);

    const std::vector<bench::SkipSaving> s = bench::skip_savings(rows);
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(s[0].lights_label, "own");
    EXPECT_EQ(s[0].skips_off, std::vector<std::string>{"depth-prepass"});
    EXPECT_DOUBLE_EQ(s[0].with_ms, 10.0);  // the quad row's, not auto's 9.0
    EXPECT_DOUBLE_EQ(s[0].saved_ms(), 2.5);
    EXPECT_DOUBLE_EQ(*s[0].without_lights_ms, 6.25);
    EXPECT_DOUBLE_EQ(s[1].saved_ms(), -0.75);
    EXPECT_EQ(s[2].lights_label, "256");
    EXPECT_DOUBLE_EQ(s[2].saved_ms(), 3.0);
    EXPECT_EQ(s[3].skips_off, (std::vector<std::string>{"ambient-target", "ambient"}));
    EXPECT_DOUBLE_EQ(s[3].saved_ms(), 6.0);

    const nlohmann::ordered_json j = bench::skip_savings_json(s);
    ASSERT_EQ(j.size(), 4u);
    EXPECT_EQ(j[1]["skips_off"], nlohmann::ordered_json::array({"final"}));
    EXPECT_DOUBLE_EQ(j[1]["saved_ms"].get<double>(), -0.75);
}

TEST(BenchSkips, TheTableHasAColumnPerSkipAndALinePerVariant) {
    const std::vector<bench::Row> rows = {
        row("default", "own", 10.0), row("default", "own", 12.5, &SkipOptions::depth_prepass),
        row("default", "own", 9.25, &SkipOptions::final_pass), row("default", "256", 20.0),
        row("default", "256", 23.0, &SkipOptions::depth_prepass)};
    const std::string md = bench::skip_savings_markdown(bench::skip_savings(rows));
    EXPECT_NE(md.find("| scene | lights | every skip on, ms (min-max) | depth-prepass | final |"), std::string::npos) << md;
    EXPECT_NE(md.find("| default | own | 10.00 (9.50-11.00) | +2.50 | -0.75 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| default | 256 | 20.00 (19.50-21.00) | +3.00 | - |"), std::string::npos) << md;
    EXPECT_NE(bench::skip_savings_markdown({}).find("no row with a skip turned off"), std::string::npos);
}

// The rounds take the rows in an order of their own: a permutation each round, the same in every
// run, so no row follows the same row every round (in one fixed order, the row after a long one
// paid for it in every frame).
TEST(BenchRounds, EachRoundAPermutationOfItsOwn) {
    const size_t n = 30;
    std::set<size_t> predecessors;  // of row 5, over the rounds
    std::set<std::vector<size_t>> orders;
    for (int round = 0; round < 10; ++round) {
        const std::vector<size_t> o = bench::round_order(n, round);
        EXPECT_EQ(o, bench::round_order(n, round));  // the same in every run
        std::vector<size_t> sorted = o;
        std::sort(sorted.begin(), sorted.end());
        for (size_t i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i);
        orders.insert(o);
        const size_t at = size_t(std::find(o.begin(), o.end(), size_t(5)) - o.begin());
        if (at > 0) predecessors.insert(o[at - 1]);
    }
    EXPECT_EQ(orders.size(), 10u);
    EXPECT_GE(predecessors.size(), 6u);
}
