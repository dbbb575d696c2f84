// Every command's normal output fits kTerminalWidth columns (terminal_text.h), with no word lost
// on the way: the fitting functions on text made to be too wide, then the cheap commands as a
// user runs them (info, every help text, stress --quick) and the bench's summary on rows made by
// hand in every form the sweep makes.
#include <gtest/gtest.h>

#include <cstdio>

#include <algorithm>
#include <map>
#include <sstream>

#include "analysis/bench_report.h"
#include "analysis/terminal_text.h"
#include "app/command_table.h"
#include "cli_fixture.h"

using namespace dsr;
using namespace dsr::test;

namespace {

// The words of a text, counted: what fitting may move but never drop or add (a cut word aside).
std::map<std::string, int> words(const std::string& text) {
    std::map<std::string, int> w;
    std::istringstream in(text);
    for (std::string s; in >> s;) ++w[s];
    return w;
}

std::string over(const std::string& text) {
    std::string s;
    for (const std::string& l : lines_over(text)) s += l + "\n";
    return s;
}

}  // namespace

TEST(TerminalWidth, WrapKeepsEveryWordWithinTheWidth) {
    const std::string key = "  light geometry " + std::string(3, ' ');
    std::string value;
    for (int i = 0; i < 60; ++i) value += "word" + std::to_string(i) + " ";
    const std::string text = key + value + "\nshort line\n";
    const std::string wrapped = wrap_lines(text);
    EXPECT_EQ(over(wrapped), "");
    EXPECT_EQ(words(wrapped), words(text));
    // Continuation lines start under the value's column.
    std::istringstream in(wrapped);
    std::string first, second;
    std::getline(in, first), std::getline(in, second);
    EXPECT_EQ(second.find_first_not_of(' '), key.size()) << wrapped;
    EXPECT_EQ(wrapped.substr(wrapped.size() - 11), "short line\n");
    // A word longer than a line is cut at the width, its characters kept.
    const std::string word(300, 'x');
    const std::string cut = wrap_lines(word);
    EXPECT_EQ(over(cut), "");
    EXPECT_EQ(std::count(cut.begin(), cut.end(), 'x'), 300);
}

TEST(TerminalWidth, TablesStackHeadersAndSplitIntoParts) {
    std::vector<std::string> header = {"case"};
    std::vector<std::vector<std::string>> rows(3, std::vector<std::string>{});
    for (int r = 0; r < 3; ++r) rows[size_t(r)].push_back("case-" + std::to_string(r));
    for (int c = 0; c < 20; ++c) {
        header.push_back("a long column header " + std::to_string(c));
        for (int r = 0; r < 3; ++r) rows[size_t(r)].push_back("v" + std::to_string(1000 * c + r));
    }
    const std::string t = text_table(header, rows, {}, 120);
    EXPECT_EQ(over(t), "") << t;
    // Every cell is there; the first column is repeated in every part, so it is there more than once.
    const std::map<std::string, int> w = words(t);
    for (int c = 0; c < 20; ++c)
        for (int r = 0; r < 3; ++r) EXPECT_EQ(w.at("v" + std::to_string(1000 * c + r)), 1) << c << " " << r;
    EXPECT_GT(w.at("case-0"), 1);
    // A narrow table stays one part, headers on one line.
    const std::string small = text_table({"a", "b"}, {{"1", "2"}}, {false, true});
    EXPECT_EQ(small, "a  b\n1  2\n");
}

TEST(TerminalWidth, MarkdownTablesBecomeTextTables) {
    const std::string md = "Title line\n\n| path \\ far/near | 1e2 | 1e4 |\n|---|---:|---:|\n| texture | 1.5e-05 | **0.1** |\n";
    const std::string t = markdown_for_terminal(md);
    // Each column as wide as its widest cell or header word: the header stacks over two lines.
    EXPECT_EQ(t, "Title line\n\npath \\\nfar/near      1e2  1e4\ntexture   1.5e-05  0.1\n");
}

TEST(TerminalWidth, InfoAndEveryHelpFit) {
    RunResult info = run("info");
    ASSERT_EQ(info.status, 0) << info.output;
    EXPECT_EQ(over(info.output), "");
    RunResult top = run("--help");
    ASSERT_EQ(top.status, 0) << top.output;
    EXPECT_EQ(over(top.output), "");
    for (const Command& c : command_table()) {
        RunResult r = run(c.name + " --help");
        ASSERT_EQ(r.status, 0) << c.name << ": " << r.output;
        EXPECT_EQ(over(r.output), "") << c.name;
    }
}

// render's and compare's lines, with an output path as long as a user's may be.
TEST(TerminalWidth, RenderAndCompareFit) {
    const std::string d = temp_dir() + "/" + std::string(60, 'd');
    ASSERT_EQ(mkdir(d.c_str(), 0755), 0);
    ASSERT_EQ(run("render --size 64x64 -o " + d + "/a.png").status, 0);
    RunResult r = run("render --size 64x64 --lights 32 -o " + d + "/b.png");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(over(r.output), "");
    EXPECT_NE(r.output.find("median of 1"), std::string::npos) << r.output;
    RunResult c = run("compare " + d + "/a.png " + d + "/b.png");
    EXPECT_EQ(over(c.output), "");
}

// A model's warnings name its path, however long: printed wrapped, every word kept.
TEST(TerminalWidth, ModelWarningsFit) {
    const std::string d = temp_dir() + "/" + std::string(90, 'm');
    ASSERT_EQ(mkdir(d.c_str(), 0755), 0);
    std::FILE* f = std::fopen((d + "/tri.obj").c_str(), "w");
    ASSERT_TRUE(f);
    std::fputs("v 0 0 0\nv 1 0 0\nv 0 1 0\nunknownstatement 1 2 3\nf 1 2 3\n", f);
    std::fclose(f);
    RunResult r = run("render --size 32x32 " + d + "/tri.obj -o " + d + "/tri.png");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(over(r.output), "");
    const size_t w = r.output.find("warning:");
    ASSERT_NE(w, std::string::npos) << r.output;
    EXPECT_NE(r.output.find("unknownstatement", w), std::string::npos) << "the warning's words kept: " << r.output;
}

TEST(TerminalWidth, StressQuickFits) {
    RunResult r = run("stress --quick");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(over(r.output), "");
    EXPECT_NE(r.output.find("far/near"), std::string::npos) << r.output;
}

// The summary on rows of every kind the sweep makes, the longest configuration names included, at
// six light counts on two scenes: the widest table the full sweep prints.
TEST(TerminalWidth, BenchSummaryFits) {
    bench::Summary s;
    s.machine = "a machine";
    s.gl_renderer = "llvmpipe (LLVM 15.0.6, 256 bits)", s.gl_version = "4.5 (Compatibility Profile) Mesa 22.3.6";
    s.scenes = {"default", "analytic"};
    s.notes = {"a note"};
    s.seconds = 500;
    for (const std::string& scene : s.scenes)
        for (int n : {3, 32, 256, 1024, 4096, 65536}) {
            bench::Row f;
            f.scene = scene, f.lights = n, f.w = f.h = 512;
            f.renderer = bench::Renderer::forward_multi, f.float_accum = false;
            f.ms_median = 12345.67, f.frames_ms = {12000, 12345.67, 13000};
            s.rows.push_back(f);
            bench::Row d = f;
            d.renderer = bench::Renderer::deferred, d.float_accum.reset();
            d.depth = DepthPath::packed, d.encoding = DepthEncoding::corrected, d.gbuffer_half = true;
            d.accum_format = AccumFormat::float32, d.light_geometry = LightGeometry::tiles, d.tile_size = 16, d.tile_lights = 16;
            d.skip.ambient_target = d.skip.ambient_pass = false;
            s.rows.push_back(d);
        }
    s.goal_results = bench::judge_goals(s.rows, "default", 3);
    const std::string t = bench::text_summary(s, "out/bench.md", "out/bench.json");
    EXPECT_EQ(over(t), "") << t;
    EXPECT_NE(t.find("12345.67"), std::string::npos) << t;
}
