// The `dsr` command line as a user meets it: exit codes, one clear error line, nothing
// half-written, and the --stats JSON keys later tools read.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "analysis/image_metrics.h"
#include "deferred/option_table.h"
#include "cli_fixture.h"
#include "scene/image.h"

using namespace dsr::test;
using dsr::Image;

namespace {
void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// The flags a usage text lists in its options section: the first word of each item of an
// option line ("  -o, --output FILE  ..." gives -o and --output).
std::set<std::string> usage_flags(const std::string& usage) {
    std::set<std::string> out;
    std::stringstream ss(usage.substr(usage.find("\noptions:\n")));
    for (std::string line; std::getline(ss, line);) {
        if (line.rfind("  -", 0) != 0) continue;
        std::string head = line.substr(2, line.find("  ", 2) - 2);
        std::stringstream items(head);
        for (std::string item; std::getline(items, item, ',');) {
            item = item.substr(item.find_first_not_of(' '));
            out.insert(item.substr(0, item.find(' ')));
        }
    }
    return out;
}

// The flags a command file's parser compares against (`a == "--flag"`).
std::set<std::string> parsed_flags(const std::string& source_file) {
    std::ifstream in(std::string(DSR_SOURCE_DIR) + "/src/app/" + source_file);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string src = ss.str();
    std::set<std::string> out;
    const std::regex flag("a == \"(-[^\"]*)\"");
    for (auto it = std::sregex_iterator(src.begin(), src.end(), flag); it != std::sregex_iterator(); ++it)
        out.insert((*it)[1]);
    return out;
}

std::string joined(const std::set<std::string>& s) {
    std::string out;
    for (const std::string& x : s) out += x + " ";
    return out;
}
}  // namespace

// `dsr COMMAND --help` (and -h): that command's usage on stdout, exit 0, nothing run; the
// usage lists exactly the flags its command file parses (`a == "--flag"` in src/app/).
TEST(Cli, EveryCommandHasHelpListingItsFlags) {
    const std::pair<const char*, const char*> files[] = {
        {"render", "render_command.cpp"}, {"figures", "figures_command.cpp"}, {"bench", "bench_command.cpp"},
        {"stress", "stress_command.cpp"}, {"info", "info_command.cpp"},       {"gen-textures", nullptr},
        {"compare", nullptr},             {"view", "viewer_main.cpp"},     {"gen-model", nullptr}};
    for (auto [c, file] : files) {
        RunResult r = run(std::string(c) + " --help");
        EXPECT_EQ(r.status, 0) << c << ": " << r.output;
        EXPECT_EQ(r.output.rfind(std::string("usage: dsr ") + c + " ", 0), 0u) << c << ": " << r.output;
        EXPECT_NE(r.output.find("\noptions:\n"), std::string::npos) << c << ": " << r.output;
        if (!file) continue;
        const bool windowed = std::string(c) == "view";  // the viewer's context is its window
        if (!windowed) {
            EXPECT_NE(r.output.find("--context NAME"), std::string::npos) << c << ": " << r.output;
        }
        std::set<std::string> parsed = parsed_flags(file);
        const std::set<std::string> listed = usage_flags(r.output);
        // render and view take the option table's flags too (parse_render_flag).
        if (std::string(c) == "render" || windowed) {
            for (const std::string& f : dsr::render_option_flags()) parsed.insert(f);
        }
        EXPECT_GT(parsed.size(), 0u) << file;
        EXPECT_EQ(parsed, listed) << c << ": parsed " << joined(parsed) << "\nlisted " << joined(listed);
    }
    RunResult render = run("render --size 32x32 -h");  // -h too, anywhere among the flags
    EXPECT_EQ(render.status, 0);
    EXPECT_EQ(render.output.rfind("usage: dsr render ", 0), 0u) << render.output;
    for (const char* k : {"--gl-state-cache on|off", "--debug-gl", "--context NAME"})
        EXPECT_NE(render.output.find(k), std::string::npos) << k;
    // compare takes no GL context; its flags are still exactly the usage's.
    RunResult cmp = run("compare --help");
    EXPECT_EQ(parsed_flags("compare_command.cpp"), usage_flags(cmp.output)) << cmp.output;
    RunResult top = run("--help");
    EXPECT_EQ(top.status, 0);
    for (auto [c, file] : files) EXPECT_NE(top.output.find(std::string("\n  ") + c + " "), std::string::npos) << c;
}

// An unknown command is one line on stderr and exit 2; an unknown option one line and exit 1.
TEST(Cli, UnknownCommandOrOptionIsOneLine) {
    RunResult r = run("frobnicate");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.output, "dsr: unknown command 'frobnicate' (expected render, figures, bench, stress, info, "
                        "gen-textures, gen-model, compare, view; dsr --help lists them)\n");
    for (const char* c : {"render --frobnicate", "stress --frobnicate"}) {
        RunResult o = run(c);
        EXPECT_EQ(o.status, 1) << c;
        EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << c << ": " << o.output;
        EXPECT_NE(o.output.find("unknown option '--frobnicate'"), std::string::npos) << c << ": " << o.output;
    }
}

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

// --lights: the bench's generated light sets on the scene (bench_scenes.h), so a bench row's scene
// can be rendered and looked at; 32-large replaces the scene too (its 9 boxes, its camera).
TEST(Cli, RenderWithTheBenchLights) {
    std::string d = temp_dir();
    for (const char* spec : {"16", "64-overlap", "32-large"}) {
        RunResult r = run(std::string("render --size 64x64 --lights ") + spec + " -o " + d + "/a.png --stats " + d + "/s.json");
        ASSERT_EQ(r.status, 0) << spec << ": " << r.output;
        std::ifstream in(d + "/s.json");
        const nlohmann::json j = nlohmann::json::parse(in);
        EXPECT_EQ(j["lights_total"].get<int>(), std::atoi(spec)) << spec;
    }
}

TEST(Cli, ExrOutputAndPackedPath) {
    std::string d = temp_dir();
    RunResult r = run("render --size 32x32 --depth packed -o " + d + "/a.exr --stats " + d + "/s.json");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(exists(d + "/a.exr"));
    std::ifstream in(d + "/s.json");
    EXPECT_EQ(nlohmann::json::parse(in)["depth_path"], "packed");
    // Read back: the same frame as the 8-bit PNG, to half-float precision (2^-11 of 1, well under
    // 1 LSB) plus the PNG's rounding (half an LSB); an image with content, alpha 1.
    ASSERT_EQ(run("render --size 32x32 --depth packed -o " + d + "/a.png").status, 0);
    const Image exr = dsr::load_image(d + "/a.exr"), png = dsr::load_image(d + "/a.png");
    ASSERT_EQ(exr.width, 32);
    ASSERT_EQ(exr.height, 32);
    const dsr::ImageDiff diff = dsr::compare_images(exr, png, 0.75 / 255);
    std::printf("[ exr      ] against the PNG: max %.3f LSB, mean %.4f LSB\n", diff.max_lsb(), diff.mean_lsb());
    EXPECT_LE(diff.max_lsb(), 0.75);
    EXPECT_GT(diff.max_abs, 0.0) << "the EXR holds more than 8 bits";
    float lo = 1, hi = 0;
    for (size_t i = 0; i < exr.rgba.size(); i += 4) {
        lo = std::min(lo, exr.rgba[i + 1]), hi = std::max(hi, exr.rgba[i + 1]);
        EXPECT_EQ(exr.rgba[i + 3], 1.0f);
    }
    EXPECT_GT(hi - lo, 0.2f) << "a lit scene, not a flat image";
}

TEST(Cli, BadFlagsAreOneClearError) {
    struct Case {
        const char* args;
        const char* expect;
    } cases[] = {
        {"render --size 12", "--size: expected WIDTHxHEIGHT"},
        {"render --size 0x5", "--size: expected WIDTHxHEIGHT"},
        {"render --depth fast", "--depth: expected auto|texture|packed|position16|position32, got 'fast'"},
        {"render --scissor maybe", "--scissor: expected on|off"},
        {"render --frames -2", "--frames: expected an integer"},
        {"render --bogus", "unknown option '--bogus'"},
        {"render -o out.bmpx", "-o: expected a file ending"},
        {"render --caps no-such", "unknown capability 'no-such'"},
        {"render --lights 12-over", "--lights: expected 'own', a count N"},
        {"render --tile-size 4", "--tile-size: expected auto or an integer in [8, 512], got '4'"},
        {"frobnicate", "unknown command"},
    };
    for (const Case& c : cases) {
        RunResult r = run(c.args);
        EXPECT_NE(r.status, 0) << c.args;
        EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.args << " said: " << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << c.args << " said: " << r.output;
        EXPECT_EQ(r.output.back(), '\n') << c.args;
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
                          "fig10c_composed_blur", "fig11_without_bloom", "fig11_with_bloom",
                          "ssao_without", "ssao_with", "ssao_buffer"})
        EXPECT_TRUE(exists(d + "/" + f + ".png")) << f;
    // Beside Figure 6, the windmill `dsr gen-model` writes, generated into a temporary folder
    // that is gone afterwards.
    for (const char* f : {"windmill_final", "windmill_normal", "windmill_specular"})
        EXPECT_TRUE(exists(d + "/" + f + ".png")) << f;
    EXPECT_EQ(r.output.find("skipped"), std::string::npos) << r.output;
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
        const Image img = dsr::load_image(d + "/" + v + ".png");
        EXPECT_EQ(img.width, 80) << v;
        EXPECT_EQ(img.height, 60) << v;
        float lo = 1, hi = 0;
        for (size_t i = 0; i < img.rgba.size(); i += 4)
            for (int c = 0; c < 3; ++c) lo = std::min(lo, img.rgba[i + c]), hi = std::max(hi, img.rgba[i + c]);
        EXPECT_GT(hi - lo, 0.1f) << v << ": the view has content";
    }
    // Content: the 80x60 final image is the 64x64 one scaled bilinearly (§3.6). The CPU model
    // samples texel centres with clamp-to-edge as GL_LINEAR does; the GPU's 8-bit weights and
    // the PNG's rounding stay within a few LSB.
    ASSERT_EQ(run("render --size 64x64 --aa -o " + d + "/small.png").status, 0);
    const Image small = dsr::load_image(d + "/small.png"), big = dsr::load_image(d + "/final.png");
    Image scaled = big;
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 80; ++x) {
            const float u = (x + 0.5f) * 64 / 80 - 0.5f, v = (y + 0.5f) * 64 / 60 - 0.5f;
            const int x0 = int(std::floor(u)), y0 = int(std::floor(v));
            const float fx = u - x0, fy = v - y0;
            auto at = [&](int xx, int yy, int c) {
                return small.at(std::clamp(xx, 0, 63), std::clamp(yy, 0, 63))[c];
            };
            for (int c = 0; c < 3; ++c)
                scaled.at(x, y)[c] = (1 - fy) * ((1 - fx) * at(x0, y0, c) + fx * at(x0 + 1, y0, c)) +
                                     fy * ((1 - fx) * at(x0, y0 + 1, c) + fx * at(x0 + 1, y0 + 1, c));
        }
    const dsr::ImageDiff sd = dsr::compare_images(big, scaled, 2.0 / 255);
    std::printf("[ out-size ] 80x60 against the 64x64 frame scaled on the CPU: max %.2f LSB, mean %.3f LSB\n",
                sd.max_lsb(), sd.mean_lsb());
    EXPECT_LE(sd.max_lsb(), 4.0);
    EXPECT_LE(sd.mean_lsb(), 0.5);
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
