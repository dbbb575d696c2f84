// The bias sweep's cases (stress_cases.h, the shadow ones) and its report
// (stress_shadow_report.h): the grid, the choice of the defaults on hand-made results, the block.
// No GL, except the one `dsr stress` run at the end.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>

#include "analysis/stress_cases.h"
#include "analysis/stress_shadow_report.h"
#include "cli_fixture.h"
#include "dsr_error.h"

using namespace dsr;

namespace {
std::vector<StressCase> shadow_only(bool quick) {
    std::vector<StressCase> out;
    for (StressCase& c : stress_cases(quick))
        if (c.shadow) out.push_back(std::move(c));
    return out;
}

StressResult pair_result(const std::string& light, double bias, double slope, long long acne, double leak,
                         double edge, int maps = 1) {
    StressResult r;
    r.name = "shadow/" + light + "/x1/1024/b" + std::to_string(bias) + ",s" + std::to_string(slope) + "/texture";
    r.category = "shadow";
    r.shadow = true;
    r.shadow_light = light;
    r.shadow_range = 1;
    r.shadow_size = 1024;
    r.shadow_bias = bias;
    r.shadow_slope = slope;
    r.shadow_maps = maps;
    r.shadow_measure.acne.darker = acne;
    r.shadow_measure.leak.contact = 100;
    r.shadow_measure.leak.leaked = (long long)(leak * 100);
    r.shadow_measure.edge.max_px = edge;
    return r;
}
}  // namespace

TEST(StressShadow, TheGrid) {
    const ShadowSweep& sw = shadow_sweep();
    const std::vector<StressCase> quick = shadow_only(true), full = shadow_only(false);
    // Quick: the defaults, each light, both paths.
    ASSERT_EQ(quick.size(), 6u);
    const LightShadow defaults;
    for (const StressCase& c : quick) {
        ASSERT_EQ(c.scene.lights.size(), 1u) << c.name;
        const LightShadow& sh = c.scene.lights[0].shadow;
        EXPECT_TRUE(sh.on);
        EXPECT_EQ(sh.bias, defaults.bias);
        EXPECT_EQ(sh.slope, defaults.slope);
        EXPECT_EQ(sh.size, defaults.size);
        EXPECT_TRUE(c.opts.shadow_lights && c.opts.shadows.on) << c.name;
        EXPECT_EQ(c.caps_off.empty(), c.path == "texture") << c.name;
        EXPECT_EQ(c.opts.depth == DepthPath::packed, c.path == "packed") << c.name;
        // The receiver and occluder the measures name: the floor and the box.
        ASSERT_EQ(c.scene.objects.size(), 2u);
        EXPECT_EQ(c.scene.objects[size_t(c.shadow_receiver)].shape->kind, ShapeDesc::Kind::plane);
        EXPECT_EQ(c.scene.objects[size_t(c.shadow_occluder)].shape->kind, ShapeDesc::Kind::box);
    }
    // Full: every pair at every (range, size) setting on the depth texture, at range 1 and the
    // default size on the packed maps too.
    const size_t pairs = sw.biases.size() * sw.slopes.size(), settings = sw.ranges.size() + sw.sizes.size();
    EXPECT_EQ(full.size(), 3 * pairs * (settings + 1));
    std::set<std::string> names;
    for (const StressCase& c : full) names.insert(c.name);
    EXPECT_EQ(names.size(), full.size()) << "names are unique";
    EXPECT_TRUE(names.count("shadow/point/x100/1024/b0.0003,s4/texture"));
    EXPECT_TRUE(names.count("shadow/directional/x1/2048/b0,s0/texture"));
    EXPECT_TRUE(names.count("shadow/spot/x1/1024/b0.003,s1/packed"));
    // The range multiplies the spot's and point's radius, the directional scene's extent.
    LightShadow sh;
    EXPECT_FLOAT_EQ(shadow_case_scene("spot", 10, sh).lights[0].radius, 120.0f);
    EXPECT_FLOAT_EQ(shadow_case_scene("point", 100, sh).lights[0].radius, 900.0f);
    EXPECT_FLOAT_EQ(shadow_case_scene("directional", 10, sh).camera.far_plane, 300.0f);
    EXPECT_THROW(shadow_case_scene("area", 1, sh), Error);
}

TEST(StressShadow, ChoiceIsTheLeastLeakWithoutAcne) {
    std::vector<StressResult> rs = {
        pair_result("spot", 0, 0, 40, 0.0, 9),        // acne: out
        pair_result("point", 0, 0, 0, 0.0, 1),
        pair_result("spot", 1e-4, 1, 0, 0.10, 1),     // clean, leaks 10%
        pair_result("point", 1e-4, 1, 0, 0.00, 1),
        pair_result("spot", 1e-3, 2, 0, 0.04, 1.2),   // clean, leaks 4% on average: chosen
        pair_result("point", 1e-3, 2, 0, 0.04, 1.2),
        pair_result("spot", 3e-4, 1, 0, 0.00, 1),     // would win, but one map was not drawn
        pair_result("point", 3e-4, 1, 0, 0.00, 1, 0),
    };
    const ShadowBiasChoice c = choose_shadow_bias(rs);
    ASSERT_TRUE(c.found) << c.why;
    EXPECT_FLOAT_EQ(float(c.bias), 1e-3f);
    EXPECT_FLOAT_EQ(float(c.slope), 2.0f);
    EXPECT_NE(c.why.find("2 of 4 pairs show acne in the fewest cases (0 of 2)"), std::string::npos) << c.why;
    const std::vector<ShadowPairSummary> s = shadow_pair_summaries(rs);
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(s[0].acne_cases, 1);  // (0, 0) sorts first
    EXPECT_EQ(s[0].most_acne, 40);
    // A tie on the leak goes to the smaller edge error, then the smaller bias.
    rs[4].shadow_measure.leak.leaked = rs[5].shadow_measure.leak.leaked = 5;
    rs[2].shadow_measure.leak.leaked = 0;
    EXPECT_FLOAT_EQ(float(choose_shadow_bias(rs).bias), 1e-4f);
    // Acne in a case every pair shows (too coarse a map) decides nothing; a pair with acne
    // elsewhere too is out.
    for (StressResult& r : rs)
        if (r.shadow_light == "point") r.shadow_measure.acne.darker = 3;
    EXPECT_FLOAT_EQ(float(choose_shadow_bias(rs).bias), 1e-4f);
    // Equal measures: the slope nearest the default's (2), not the smallest.
    std::vector<StressResult> tie = {pair_result("spot", 1e-4, 1, 0, 0.1, 1), pair_result("spot", 1e-4, 2, 0, 0.1, 1),
                                     pair_result("spot", 1e-4, 4, 0, 0.1, 1)};
    EXPECT_FLOAT_EQ(float(choose_shadow_bias(tie).slope), 2.0f);
    for (StressResult& r : rs) r.shadow_maps = 0;
    EXPECT_FALSE(choose_shadow_bias(rs).found);
    EXPECT_FALSE(choose_shadow_bias({}).found);

    const std::string tables = shadow_sweep_tables(rs);
    EXPECT_NE(tables.find("| 0.001 | 2 | 2 | 1 | 3 |"), std::string::npos) << tables;
    const std::string block = shadow_report_block(rs, "dsr stress --only shadow/", "llvmpipe");
    EXPECT_NE(block.find("No choice: no pair drew every map"), std::string::npos) << block;
    const std::string doc = "a\n<!-- BEGIN shadow sweep, generated by: dsr stress --report -->\nold\n<!-- END shadow sweep -->\nb\n";
    const std::string out = splice_shadow_report_block(doc, "x.md", block);
    EXPECT_EQ(out.find("\nold\n"), std::string::npos);
    EXPECT_EQ(out.rfind("a\n", 0), 0u);
    EXPECT_NE(out.find("-->\nb\n"), std::string::npos);
    EXPECT_THROW(check_shadow_report_block("no block", "x.md"), Error);
}

// `dsr stress` with shadow cases only rewrites the bias sweep's block and leaves the main one;
// a report file without that block is refused before the sweep.
TEST(StressShadow, ReportRewritesOnlyTheShadowBlock) {
    const std::string dir = dsr::test::temp_dir(), md = dir + "/acc.md";
    const std::string main_block = "<!-- BEGIN generated by: dsr stress --report -->\nmain\n<!-- END generated -->\n";
    {
        std::ofstream f(md);
        f << "x\n" << main_block << "y\n<!-- BEGIN shadow sweep, generated by: dsr stress --report -->\nold\n"
          << "<!-- END shadow sweep -->\nz\n";
    }
    const auto r = dsr::test::run("stress --quick --only shadow/spot/x1/1024/ --report " + md);
    ASSERT_EQ(r.status, 0) << r.output;
    std::ifstream in(md);
    const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(doc.find(main_block), std::string::npos) << doc;
    EXPECT_EQ(doc.find("\nold\n"), std::string::npos) << doc;
    EXPECT_NE(doc.find("| shadow/spot/x1/1024/"), std::string::npos) << doc;
    {
        std::ofstream f(md);
        f << main_block;
    }
    const auto bad = dsr::test::run("stress --quick --only shadow/spot/x1/1024/ --report " + md);
    EXPECT_NE(bad.status, 0);
    EXPECT_NE(bad.output.find("no '<!-- BEGIN shadow sweep"), std::string::npos) << bad.output;
}
