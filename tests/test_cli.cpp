// The `dsr` command line as a user meets it: exit codes, one clear error line, nothing
// half-written, and the --stats JSON keys later tools read.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_fixture.h"

using namespace dsr::test;

namespace {
void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }
}  // namespace

TEST(Cli, RenderWritesImageAndStats) {
    std::string d = temp_dir();
    RunResult r = run("render --size 96x64 --frames 3 -o " + d + "/a.png --stats " + d + "/s.json");
    ASSERT_EQ(r.status, 0) << r.output;
    ASSERT_TRUE(exists(d + "/a.png"));
    std::ifstream in(d + "/s.json");
    nlohmann::json j = nlohmann::json::parse(in);
    for (const char* k : {"depth_path", "scissor", "lights_total", "lights_culled", "lights_drawn",
                          "light_fragments", "scissor_pixels", "ms"})
        EXPECT_TRUE(j.contains(k)) << k;
    for (const char* k : {"geometry", "ambient", "lights", "final", "frame"}) EXPECT_TRUE(j["ms"].contains(k)) << k;
    EXPECT_EQ(j["depth_path"], "texture");
    EXPECT_EQ(j["scissor"], true);
    EXPECT_GE(j["lights_total"].get<int>(), 3);
    EXPECT_EQ(j["lights_total"].get<int>(), j["lights_culled"].get<int>() + j["lights_drawn"].get<int>());
    EXPECT_GT(j["light_fragments"].get<long long>(), 0);
    EXPECT_GT(j["ms"]["frame"].get<double>(), 0.0);
}

TEST(Cli, ExrOutputAndPackedPath) {
    std::string d = temp_dir();
    RunResult r = run("render --size 32x32 --depth packed -o " + d + "/a.exr --stats " + d + "/s.json");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(exists(d + "/a.exr"));
    std::ifstream in(d + "/s.json");
    EXPECT_EQ(nlohmann::json::parse(in)["depth_path"], "packed");
}

TEST(Cli, BadFlagsAreOneClearError) {
    struct Case {
        const char* args;
        const char* expect;
    } cases[] = {
        {"render --size 12", "--size: expected WIDTHxHEIGHT"},
        {"render --size 0x5", "--size: expected WIDTHxHEIGHT"},
        {"render --depth fast", "--depth: expected auto|texture|packed, got 'fast'"},
        {"render --scissor maybe", "--scissor: expected on|off"},
        {"render --frames -2", "--frames: expected an integer"},
        {"render --bogus", "unknown option '--bogus'"},
        {"render -o out.bmpx", "-o: expected a file ending"},
        {"render --caps no-such", "unknown capability 'no-such'"},
        {"frobnicate", "unknown command"},
    };
    for (const Case& c : cases) {
        RunResult r = run(c.args);
        EXPECT_NE(r.status, 0) << c.args;
        EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.args << " said: " << r.output;
    }
}

// A bad scene file: one error naming file:line, non-zero exit, no output file at all.
TEST(Cli, BadSceneWritesNothing) {
    std::string d = temp_dir();
    write(d + "/bad.scene", "camera pos 0 0 5 target 0 0 0 up 0 1 0 fov 60 near 0.1 far 100\nlight point pos 0 0 0\n");
    RunResult r = run("render " + d + "/bad.scene -o " + d + "/out.png --stats " + d + "/s.json");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find(d + "/bad.scene:2:"), std::string::npos) << r.output;
    EXPECT_FALSE(exists(d + "/out.png"));
    EXPECT_FALSE(exists(d + "/s.json"));
}

// Hiding ARB_depth_texture makes `auto` choose the packed path (the probe, not a flag, decides).
TEST(Cli, ForcedCapabilityChangesAutoPath) {
    std::string d = temp_dir();
    RunResult r = run("render --size 32x32 --caps no-depth-texture -o " + d + "/a.png --stats " + d + "/s.json");
    ASSERT_EQ(r.status, 0) << r.output;
    std::ifstream in(d + "/s.json");
    EXPECT_EQ(nlohmann::json::parse(in)["depth_path"], "packed");
    RunResult t = run("render --size 32x32 --caps no-depth-texture --depth texture -o " + d + "/b.png");
    EXPECT_NE(t.status, 0);
    EXPECT_NE(t.output.find("ARB_depth_texture"), std::string::npos) << t.output;
    EXPECT_FALSE(exists(d + "/b.png"));
}

TEST(Cli, InfoNamesCapabilitiesAndPaths) {
    RunResult r = run("info");
    ASSERT_EQ(r.status, 0) << r.output;
    for (const char* k : {"GL_RENDERER", "ARB_draw_buffers", "ARB_depth_texture", "EXT_framebuffer_object",
                          "paths chosen", "depth"})
        EXPECT_NE(r.output.find(k), std::string::npos) << k;
}

TEST(Cli, FiguresWritesEveryFile) {
    std::string d = temp_dir();
    RunResult r = run("figures --size 96x96 -o " + d);
    ASSERT_EQ(r.status, 0) << r.output;
    for (const char* f : {"fig4a_normal", "fig4b_diffuse", "fig4c_specular", "fig4d_depth", "fig6_final",
                          "fig8_blur_factor", "fig8_blur_factor_closeup", "fig9_closeup_without_aa",
                          "fig9_closeup_with_aa", "fig10a_horizontal_blur", "fig10b_vertical_blur",
                          "fig10c_composed_blur", "fig11_without_bloom", "fig11_with_bloom"})
        EXPECT_TRUE(exists(d + "/" + f + ".png")) << f;
}

// The final stage scales the deferred buffers to the output size (§3.6), and every view runs.
TEST(Cli, OutSizeAndViews) {
    std::string d = temp_dir();
    for (const char* v : {"final", "normal", "diffuse", "specular", "depth", "blur-factor", "bloom"}) {
        RunResult r = run(std::string("render --size 64x64 --out-size 80x60 --aa --view ") + v + " -o " + d + "/" +
                          v + ".png --stats " + d + "/s.json");
        ASSERT_EQ(r.status, 0) << v << ": " << r.output;
        std::ifstream in(d + "/s.json");
        auto j = nlohmann::json::parse(in);
        EXPECT_EQ(j["out_size"][0], 80);
        EXPECT_EQ(j["view"], v);
        EXPECT_TRUE(j["ms"].contains("bloom") && j["ms"].contains("aa"));
    }
    EXPECT_NE(run("render --view albedo").output.find("--view: expected final|normal"), std::string::npos);
}

// Mesa itself hides a capability: the probe must read the real GL, not only --caps.
TEST(Legacy, MesaHidesFramebufferObjects) {
    std::string d = temp_dir();
    RunResult r = run("render --size 64x48 -o " + d + "/copy.png --stats " + d + "/s.json",
                      "MESA_EXTENSION_OVERRIDE=-GL_EXT_framebuffer_object");
    ASSERT_EQ(r.status, 0) << r.output;
    std::ifstream in(d + "/s.json");
    auto j = nlohmann::json::parse(in);
    EXPECT_EQ(j["paths"]["render_target"], "copy");
    EXPECT_EQ(j["paths"]["gbuffer"], "per-target");
    EXPECT_TRUE(j["caps_forced_off"].empty());  // nothing was forced: Mesa said no
    RunResult info = run("info", "MESA_EXTENSION_OVERRIDE=-GL_EXT_framebuffer_object");
    EXPECT_NE(info.output.find("no  render to texture"), std::string::npos) << info.output;
}

TEST(Legacy, MesaAtOpenGL21AndGlsl120) {
    const char* env = "MESA_GL_VERSION_OVERRIDE=2.1 MESA_GLSL_VERSION_OVERRIDE=120";
    RunResult info = run("info", env);
    ASSERT_EQ(info.status, 0) << info.output;
    EXPECT_NE(info.output.find("GL_VERSION     2.1"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("GLSL           1.20"), std::string::npos) << info.output;
    std::string d = temp_dir();
    RunResult r = run("render --size 64x48 -o " + d + "/a.png", env);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(exists(d + "/a.png"));
}

// No fallback exists for GLSL: one clear line naming it, non-zero exit, no output.
TEST(Legacy, MissingGlslIsOneClearLine) {
    std::string d = temp_dir();
    RunResult r = run("render --size 32x32 --caps no-glsl -o " + d + "/a.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("GLSL 1.20 is required"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(exists(d + "/a.png"));
}
