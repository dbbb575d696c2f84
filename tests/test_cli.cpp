// The `dsr` command line as a user meets it: exit codes, one clear error line, nothing
// half-written, and the --stats JSON keys later tools read.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "analysis/image_metrics.h"
#include "app/command_table.h"
#include "app/help_text.h"
#include "cli_fixture.h"
#include "deferred/option_table.h"
#include "dsr_error.h"
#include "gl/cap_names.h"
#include "gl/check.h"
#include "gl/state.h"
#include "platform/resources.h"
#include "scene/image.h"

using namespace dsr::test;
using dsr::Image;

namespace {
void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// How help writes a flag's head: "-o, --output FILE", "--bloom, --no-bloom", "--depth auto|...".
std::string head(const dsr::Flag& f) {
    std::string s;
    for (const std::string& n : f.names) s += (s.empty() ? "" : ", ") + n;
    return f.arg.empty() ? s : s + " " + f.arg;
}
std::string head(const dsr::RenderOption& o) {
    return o.kind == dsr::OptionKind::toggle ? "--" + o.name + ", --no-" + o.name : "--" + o.name + " " + dsr::option_arg(o);
}

// A value a flag takes, from how its table writes it: the first of a|b, the low end of lo..hi, a
// size, or a file with the extension its argument names.
std::string good_value(const dsr::Flag& f) {
    static const std::map<std::string, std::string> by_arg = {
        {"WxH", "64x48"}, {"NxN", "64x64"},        {"FILE", "a.png"},     {"FILE.json", "a.json"},
        {"FILE.md", "a.md"}, {"FILE.png", "a.png"}, {"DIR", "d"},          {"TEXT", "depth"},
        {"NAME", "osmesa"},  {"LIST", "no-mrt"},    {"SPEC", "32-overlap"}, {"SIDE", "back"},
        {"R,G,B", "0.1,0.2,0.3"}, {"Q,V,T", "1,1000,1"}};
    if (f.arg.find('|') != std::string::npos) return f.arg.substr(0, f.arg.find('|'));  // auto|N: auto
    if (f.names.front() == "--lights" && f.arg == "LIST") return "own,32";  // bench's
    if (f.range.find("(comma-separated)") != std::string::npos) return f.range.substr(0, f.range.find(','));
    const auto it = by_arg.find(f.arg);
    if (it != by_arg.end()) return it->second;
    if (f.range.find("..") != std::string::npos && isdigit(f.range[0])) return f.range.substr(0, f.range.find(".."));
    return "";
}

// `s` with every run of white space one space: help wraps its text anywhere between words.
std::string flat(const std::string& s) {
    std::string out;
    for (char ch : s)
        if (!isspace(static_cast<unsigned char>(ch))) out += ch;
        else if (!out.empty() && out.back() != ' ') out += ' ';
    return out;
}

// True when `help` has a line that starts with `head` (its text after it, or on the next line).
bool lists(const std::string& help, const std::string& head) {
    return help.find("\n  " + head + " ") != std::string::npos || help.find("\n  " + head + "\n") != std::string::npos;
}

// Parses `argv` by a fresh copy of command `name`'s table; the error's text, or "" when it parsed.
std::string parse(const std::string& name, const std::vector<std::string>& argv) {
    try {
        dsr::RenderSettings render;
        dsr::FiguresSettings figures;
        dsr::BenchSettings bench;
        dsr::StressSettings stress;
        dsr::InfoSettings info;
        dsr::GenTexturesSettings gen;
        dsr::GenModelSettings gen_model;
        dsr::CompareSettings compare;
        dsr::ViewerConfig view;
        dsr::HdrSettings hdr;
        const dsr::Command c = name == "render"    ? dsr::render_command(render)
                               : name == "figures" ? dsr::figures_command(figures)
                               : name == "bench"   ? dsr::bench_command(bench)
                               : name == "stress"  ? dsr::stress_command(stress)
                               : name == "info"    ? dsr::info_command(info)
                               : name == "compare" ? dsr::compare_command(compare)
                               : name == "view"    ? dsr::view_command(view)
                               : name == "gen-model" ? dsr::gen_model_command(gen_model)
                               : name == "hdr"     ? dsr::hdr_command(hdr)
                                                   : dsr::gen_textures_command(gen);
        dsr::parse_command_line(c, argv);
        return "";
    } catch (const dsr::Error& e) {
        return e.what();
    }
}
}  // namespace

// `dsr COMMAND --help` (and -h): that command's usage on stdout, exit 0, nothing run; it is the
// command's table printed (help_text.h), so it lists every flag of the table, and for `render`
// and `view` every renderer option.
TEST(Cli, EveryCommandHasHelpListingItsTable) {
    ASSERT_EQ(dsr::command_table().size(), 10u);
    for (const dsr::Command& c : dsr::command_table()) {
        RunResult r = run(c.name + " --help");
        EXPECT_EQ(r.status, 0) << c.name << ": " << r.output;
        EXPECT_EQ(r.output, dsr::command_help(c)) << c.name << ": the binary prints its table";
        EXPECT_EQ(r.output.rfind("usage: dsr " + c.name + " ", 0), 0u) << c.name << ": " << r.output;
        EXPECT_NE(r.output.find("\noptions:\n"), std::string::npos) << c.name << ": " << r.output;
        if (c.name != "view" && c.name != "compare" && c.name != "gen-textures" &&
            c.name != "gen-model") {
            EXPECT_NE(r.output.find("--context NAME"), std::string::npos) << c.name << ": " << r.output;
        }
        for (const dsr::Flag& f : c.flags) {
            EXPECT_TRUE(lists(r.output, head(f))) << c.name << ": " << head(f);
            if (!f.def.empty()) {
                EXPECT_NE(flat(r.output).find("default " + flat(f.def)), std::string::npos) << c.name << ": " << head(f);
            }
            for (const auto& item : f.items) EXPECT_NE(r.output.find("\n    " + item.first + " "), std::string::npos) << item.first;
        }
        for (const dsr::Operand& o : c.operands) EXPECT_TRUE(lists(r.output, o.name)) << o.name;
        const bool takes_renderer = c.name == "render" || c.name == "view";
        EXPECT_EQ(c.renderer != nullptr, takes_renderer) << c.name;
        EXPECT_EQ(r.output.find("\nrenderer options") != std::string::npos, takes_renderer) << c.name;
        for (const dsr::RenderOption& o : dsr::render_options()) {
            if (takes_renderer) {
                EXPECT_TRUE(lists(r.output, head(o))) << c.name << ": " << head(o);
            }
            EXPECT_FALSE(o.help.empty()) << o.name;
        }
    }
    RunResult render = run("render --size 32x32 -h");  // -h too, anywhere among the flags
    EXPECT_EQ(render.status, 0);
    EXPECT_EQ(render.output.rfind("usage: dsr render ", 0), 0u) << render.output;
    for (const char* k : {"--gl-state-cache on|off", "--debug-gl", "--context NAME"})
        EXPECT_NE(render.output.find(k), std::string::npos) << k;
    // The --caps names come from gl/cap_names.h: every one in the help of each command taking --caps.
    for (const char* c : {"render", "info", "view"}) {
        const std::string help = run(std::string(c) + " --help").output;
        for (const dsr::CapName& n : dsr::cap_names()) EXPECT_NE(help.find(n.name), std::string::npos) << c << ": " << n.name;
    }
    RunResult top = run("--help");
    EXPECT_EQ(top.status, 0);
    EXPECT_EQ(top.output, dsr::top_help());
    for (const dsr::Command& c : dsr::command_table()) EXPECT_NE(top.output.find("\n  " + c.name + " "), std::string::npos) << c.name;
}

// Every flag of every table parses a value of the kind its table says it takes, and every
// renderer option parses each of its values through both commands that take them; a flag with a
// choice or a range refuses another value with one error line that names the flag and what it
// accepts.
TEST(Cli, EveryTableFlagParsesAndRefusesInOneLine) {
    const bool debug = dsr::debug_gl(), cache = dsr::gl_state().cache();  // --debug-gl, --gl-state-cache set them here
    for (const dsr::Command& c : dsr::command_table()) {
        for (const dsr::Flag& f : c.flags) {
            const std::string name = f.names.back();
            std::vector<std::string> argv = {name};
            if (!f.arg.empty()) argv.push_back(good_value(f));
            ASSERT_FALSE(!f.arg.empty() && argv[1].empty()) << c.name << " " << name << ": no sample for " << f.arg;
            EXPECT_EQ(parse(c.name, argv), "") << c.name << " " << name << " " << (argv.size() > 1 ? argv[1] : "");
            const bool checked = f.arg.find('|') != std::string::npos || !f.range.empty();
            if (f.arg.empty() || !checked) continue;
            const std::string err = parse(c.name, {name, "bogus"});
            EXPECT_EQ(err.rfind("dsr " + c.name + ": " + name + ": expected ", 0), 0u) << c.name << " " << name << ": " << err;
            EXPECT_EQ(err.find('\n'), std::string::npos) << err;
            std::stringstream alternatives(f.arg);  // each word of a|b|N the error names (N: the range below)
            for (std::string w; std::getline(alternatives, w, '|');)
                if (islower(static_cast<unsigned char>(w[0]))) {
                    EXPECT_NE(err.find(w), std::string::npos) << w << ": " << err;
                }
            if (f.range.find("..") != std::string::npos && isdigit(f.range[0])) {
                const std::string lo = f.range.substr(0, f.range.find("..")), hi = f.range.substr(f.range.find("..") + 2);
                EXPECT_NE(err.find("[" + lo + ", " + hi.substr(0, hi.find_first_not_of("0123456789")) + "]"),
                          std::string::npos) << err;
            }
            EXPECT_NE(parse(c.name, {name}).find(name + ": expected a value, got nothing"), std::string::npos) << name;
        }
        for (const dsr::Operand& o : c.operands) EXPECT_FALSE(o.help.empty()) << c.name << " " << o.name;
        EXPECT_NE(parse(c.name, {"--frobnicate"}).find("unknown option '--frobnicate'"), std::string::npos) << c.name;
    }
    dsr::set_debug_gl(debug);
    dsr::gl_state().set_cache(cache);
    for (const char* command : {"render", "view"})
        for (const dsr::RenderOption& o : dsr::render_options()) {
            std::vector<std::vector<std::string>> lines;
            if (o.kind == dsr::OptionKind::toggle) lines = {{"--" + o.name}, {"--no-" + o.name}};
            else if (o.kind == dsr::OptionKind::number || o.kind == dsr::OptionKind::integer)
                lines = {{"--" + o.name, dsr::option_range(o).substr(0, dsr::option_range(o).find(".."))}};
            else
                for (const std::string& v : o.values) lines.push_back({"--" + o.name, v});
            for (const auto& argv : lines) EXPECT_EQ(parse(command, argv), "") << command << " " << argv[0];
            if (o.kind == dsr::OptionKind::toggle) continue;
            const std::string err = parse(command, {"--" + o.name, "bogus"});
            EXPECT_EQ(err.rfind(std::string("dsr ") + command + ": --" + o.name + ": expected ", 0), 0u) << err;
            EXPECT_EQ(err.find('\n'), std::string::npos) << err;
        }
    // What a parse stores: the table's default where no flag is given, the value where one is.
    dsr::RenderSettings r;
    dsr::parse_command_line(dsr::render_command(r), {"s.scene", "--tile-size", "24", "--no-bloom", "--lights", "64-overlap"});
    EXPECT_EQ(r.scene, "s.scene");
    EXPECT_EQ(r.options.shader.tile_size, 24);
    EXPECT_EQ(r.options.bloom, 0);
    ASSERT_TRUE(r.lights.has_value());
    EXPECT_EQ(r.lights->count, 64);
    EXPECT_EQ(r.output(), "out/s.png") << "-o's default: out/ and the scene's stem";
    EXPECT_EQ(r.width, 512);
    dsr::BenchSettings b;
    dsr::parse_command_line(dsr::bench_command(b), {"--tile-size", "32", "--tile-plan", "groups", "--light-geometry", "tiles,quad"});
    EXPECT_EQ(b.tiles.shader.tile_size, 32);
    EXPECT_EQ(b.tiles.shader.tile_lights, 0) << "auto, as render's default";
    EXPECT_EQ(b.tiles.shader.tile_plan, dsr::TileGrouping::groups);
    EXPECT_EQ(b.geometries, (std::vector<std::string>{"tiles", "quad"}));
    dsr::ViewerConfig v;  // `view --lights`, as render takes it
    dsr::parse_command_line(dsr::view_command(v), {"--lights", "32-large", "--size", "640x360"});
    ASSERT_TRUE(v.lights.has_value());
    EXPECT_EQ(v.lights->set, dsr::LightSet::large);
    EXPECT_EQ(v.width, 640);
}

// docs/cli.md is the tables printed as markdown (`make docs-cli` writes it): it fails here when a
// flag, value, default or help changed and the file was not regenerated, or the file was edited.
TEST(CliDocs, DocsCliMdIsTheTablesPrinted) {
    const std::string path = std::string(DSR_SOURCE_DIR) + "/docs/cli.md";
    std::ifstream in(path);
    ASSERT_TRUE(in) << path << " is missing: make docs-cli writes it";
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string file = ss.str(), tables = dsr::cli_markdown();
    if (file == tables) return;
    std::stringstream a(file), b(tables);
    std::string la, lb;
    for (int line = 1;; ++line) {
        const bool more_a = bool(std::getline(a, la)), more_b = bool(std::getline(b, lb));
        if (!more_a && !more_b) break;
        if (!more_a || !more_b || la != lb) {
            ADD_FAILURE() << path << ":" << line << " differs from the tables (make docs-cli rewrites it):\n  file:   "
                          << (more_a ? la : "(end of file)") << "\n  tables: " << (more_b ? lb : "(end)");
            return;
        }
    }
    ADD_FAILURE() << path << " differs from the tables (make docs-cli rewrites it)";
}

// The --caps table is the one list: an unknown name's error names every entry, and `info` hides
// every entry it is given.
TEST(Cli, CapsNamesComeFromOneTable) {
    std::string all;
    for (const dsr::CapName& n : dsr::cap_names()) all += (all.empty() ? "" : ",") + std::string(n.name);
    const std::string err = dsr::check_cap_names({"no-mrt", "no-such"});
    EXPECT_EQ(err.rfind("unknown capability 'no-such' (expected no-mrt, ", 0), 0u) << err;
    for (const dsr::CapName& n : dsr::cap_names()) EXPECT_NE(err.find(n.name), std::string::npos) << n.name;
    EXPECT_EQ(dsr::check_cap_names(dsr::split_caps(all)), "");
    RunResult info = run("info --caps " + all);
    ASSERT_EQ(info.status, 0) << info.output;
    std::string forced = "forced off:";
    for (const dsr::CapName& n : dsr::cap_names()) forced += " " + std::string(n.name);
    // info wraps a line past the terminal's width (analysis/terminal_text.h): its continuation lines
    // joined, the forced line is whole.
    std::string joined = info.output;
    for (size_t at = joined.find("\n    "); at != std::string::npos; at = joined.find("\n    ", at))
        joined.replace(at, joined.find_first_not_of(' ', at + 1) - at, " ");
    EXPECT_NE(joined.find(forced + "\n"), std::string::npos) << info.output;
    RunResult bad = run("info --caps no-mrt,no-such");
    EXPECT_EQ(bad.status, 1);
    EXPECT_EQ(bad.output, "dsr info: --caps: " + err + "\n");
}

// An unknown command is one line on stderr and exit 2; an unknown option one line and exit 1.
TEST(Cli, UnknownCommandOrOptionIsOneLine) {
    RunResult r = run("frobnicate");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.output, "dsr: unknown command 'frobnicate' (expected render, figures, bench, stress, info, "
                        "gen-textures, gen-model, compare, view, hdr; dsr --help lists them)\n");
    for (const char* c : {"render --frobnicate", "stress --frobnicate"}) {
        RunResult o = run(c);
        EXPECT_EQ(o.status, 1) << c;
        EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << c << ": " << o.output;
        EXPECT_NE(o.output.find("unknown option '--frobnicate'"), std::string::npos) << c << ": " << o.output;
    }
}

// A bad value on the command line is echoed at most 60 characters (scene/user_file.h quote), as
// a scene file's token is: a 5000-character value gives an error line, not a 5000-character one.
TEST(Cli, LongBadValuesAreEchoedCut) {
    const std::string big(5000, 'x');
    for (const std::string& c : {"render --depth " + big, "render --" + big, "render --size " + big, "info --caps " + big,
                                "render --no-skip " + big, "compare --threshold " + big + " a b"}) {
        RunResult r = run(c);
        EXPECT_NE(r.status, 0) << c.substr(0, 40);
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << c.substr(0, 40);
        // (--caps's line names every capability it takes: about 400 characters)
        EXPECT_LT(r.output.size(), 500u) << c.substr(0, 40) << ": " << r.output.substr(0, 200);
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

// --stats' ideal count follows the depth path the renderer runs, not the one asked for: with
// `--depth auto` on a GL with depth textures it is the texture path's count, from the same
// depth codes (source depth24), equal to --depth texture's.
TEST(Cli, StatsIdealCountFollowsTheResolvedDepthPath) {
    std::string d = temp_dir();
    nlohmann::json j[2];
    const char* depth[2] = {"auto", "texture"};
    for (int k = 0; k < 2; ++k) {
        const std::string stats = d + "/" + depth[k] + ".json";
        RunResult r = run(std::string("render --size 64x48 --depth ") + depth[k] + " -o " + d + "/" + depth[k] +
                          ".png --stats " + stats);
        ASSERT_EQ(r.status, 0) << depth[k] << ": " << r.output;
        std::ifstream in(stats);
        j[k] = nlohmann::json::parse(in);
    }
    ASSERT_EQ(j[1]["depth_path"], "texture") << "this GL has no depth textures";
    EXPECT_EQ(j[0]["depth_path"], "texture");
    EXPECT_EQ(j[0]["ideal_source"], "depth24");
    ASSERT_TRUE(j[1]["ideal_fragments"].is_number()) << j[1].dump();
    EXPECT_GT(j[1]["ideal_fragments"].get<long long>(), 0);
    EXPECT_EQ(j[0]["ideal_fragments"], j[1]["ideal_fragments"]);
}

TEST(Cli, InfoNamesCapabilitiesAndPaths) {
    RunResult r = run("info");
    ASSERT_EQ(r.status, 0) << r.output;
    for (const char* k : {"GL_RENDERER", "ARB_draw_buffers", "ARB_depth_texture", "EXT_framebuffer_object",
                          "paths chosen", "depth"})
        EXPECT_NE(r.output.find(k), std::string::npos) << k;
    // The shader folder it compiles: this tree's, since the binary is build/dsr.
    EXPECT_NE(r.output.find("shaders        " + dsr::resource_dir("glsl120") + "\n"), std::string::npos) << r.output;
    // auto's calibration, as this GL times it: llvmpipe by glFinish and the wall clock.
    EXPECT_NE(r.output.find("took in the frames before (timed by glFinish and the wall clock):"), std::string::npos)
        << r.output;
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
    // Light beyond 1.0 (docs/hdr.md): the lights x4 in RGBA8 and in half floats with each operator.
    for (const char* f : {"hdr_rgba8", "hdr_half_none", "hdr_half_reinhard", "hdr_half_aces", "hdr_half_aces_srgb"})
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
    // Content: the 80x60 final image is the 64x48 frame scaled bilinearly (§3.6); the frame is
    // projected for the output's aspect (4:3, as 64x48's own: OutSizeKeepsProportions shows a
    // square buffer). The CPU model samples texel centres with clamp-to-edge as GL_LINEAR does;
    // the GPU's 8-bit weights and the PNG's rounding stay within a few LSB.
    ASSERT_EQ(run("render --size 64x48 --out-size 80x60 --aa -o " + d + "/final.png").status, 0);
    ASSERT_EQ(run("render --size 64x48 --aa -o " + d + "/small.png").status, 0);
    const Image small = dsr::load_image(d + "/small.png"), big = dsr::load_image(d + "/final.png");
    Image scaled = big;
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 80; ++x) {
            const float u = (x + 0.5f) * 64 / 80 - 0.5f, v = (y + 0.5f) * 48 / 60 - 0.5f;
            const int x0 = int(std::floor(u)), y0 = int(std::floor(v));
            const float fx = u - x0, fy = v - y0;
            auto at = [&](int xx, int yy, int c) {
                return small.at(std::clamp(xx, 0, 63), std::clamp(yy, 0, 47))[c];
            };
            for (int c = 0; c < 3; ++c)
                scaled.at(x, y)[c] = (1 - fy) * ((1 - fx) * at(x0, y0, c) + fx * at(x0 + 1, y0, c)) +
                                     fy * ((1 - fx) * at(x0, y0 + 1, c) + fx * at(x0 + 1, y0 + 1, c));
        }
    const dsr::ImageDiff sd = dsr::compare_images(big, scaled, 2.0 / 255);
    std::printf("[ out-size ] 80x60 against the 64x48 frame scaled on the CPU: max %.2f LSB, mean %.3f LSB\n",
                sd.max_lsb(), sd.mean_lsb());
    EXPECT_LE(sd.max_lsb(), 4.0);
    EXPECT_LE(sd.mean_lsb(), 0.5);
    EXPECT_NE(run("render --view albedo").output.find("--view: expected final|normal"), std::string::npos);
}

// §3.6: a 512x512 buffer shown on a 640x480 screen keeps its proportions, because the projection
// takes the output's aspect. A unit sphere on the view axis (its outline a circle) is measured in
// the scaled image by its silhouette's second moments (each pixel weighted by its coverage, so the
// buffer's pixel steps along the edge average out): a disc of diameter D has variance D²/16 along
// every axis. Width and height agree within a pixel, and match a render made at 640x480 directly.
TEST(Cli, OutSizeKeepsProportions) {
    const std::string d = temp_dir();
    write(d + "/sphere.scene",
          "camera pos 0 0 6 target 0 0 0 up 0 1 0 fov 40 near 0.1 far 20\n"
          "ambient 1 1 1\nbackground 0 0 0\n"
          "material white diffuse 1 1 1 specular 0 0 0 shininess 1\n"
          "sphere radius 1 at 0 0 0 material white\n");
    struct Outline {
        double width, height;  // 4 sqrt(variance) along x and y
        int box_w, box_h;      // the pixels at least half covered: their bounding box
    };
    auto outline = [](const Image& img) {
        double m = 0, sx = 0, sy = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                const double c = std::clamp(double(img.at(x, y)[1]), 0.0, 1.0);
                m += c, sx += c * x, sy += c * y;
            }
        const double cx = sx / m, cy = sy / m;
        double vx = 0, vy = 0;
        int x0 = img.width, x1 = -1, y0 = img.height, y1 = -1;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                const double c = std::clamp(double(img.at(x, y)[1]), 0.0, 1.0);
                vx += c * (x - cx) * (x - cx), vy += c * (y - cy) * (y - cy);
                if (c >= 0.5) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
        return Outline{4 * std::sqrt(vx / m), 4 * std::sqrt(vy / m), x1 - x0 + 1, y1 - y0 + 1};
    };
    ASSERT_EQ(run("render " + d + "/sphere.scene --no-bloom --size 512x512 --out-size 640x480 -o " + d + "/scaled.png").status, 0);
    ASSERT_EQ(run("render " + d + "/sphere.scene --no-bloom --size 640x480 -o " + d + "/native.png").status, 0);
    const Image scaled = dsr::load_image(d + "/scaled.png"), native = dsr::load_image(d + "/native.png");
    ASSERT_EQ(scaled.width, 640);
    ASSERT_EQ(scaled.height, 480);
    const Outline s = outline(scaled), n = outline(native);
    // The sphere's outline subtends 2 atan(1 / sqrt(35)) of the 40° field: 222.9 px of 480.
    std::printf("[ out-size ] sphere at 512x512 shown at 640x480: %.2f x %.2f px (box %dx%d); rendered at "
                "640x480: %.2f x %.2f px (box %dx%d); expected 222.9\n",
                s.width, s.height, s.box_w, s.box_h, n.width, n.height, n.box_w, n.box_h);
    ASSERT_GT(s.height, 100) << "the sphere is in view";
    EXPECT_NEAR(s.width, s.height, 1.0) << "round within a pixel";
    EXPECT_NEAR(s.width, n.width, 1.0);
    EXPECT_NEAR(s.height, n.height, 1.0);
    EXPECT_NEAR(n.width, n.height, 1.0);
}

// Without -o, outputs go under out/ in the working folder, made when missing: render's image as
// out/<scene stem>.png, figures under out/figures/. A run that fails leaves no out/ behind.
TEST(Cli, DefaultOutputsGoUnderOut) {
    const std::string d = temp_dir();
    write(d + "/room.scene", "camera pos 0 0 5 target 0 0 0 up 0 1 0 fov 60 near 0.1 far 100\n"
                             "material m diffuse 1 1 1 specular 0 0 0 shininess 1\nsphere radius 1 at 0 0 0 material m\n"
                             "light point pos 0 2 2 color 1 1 1 radius 6\n");
    auto in_d = [&](const std::string& args) { return run(args, "--chdir=" + d); };
    RunResult bad = in_d("render room.scene --size 32x32 --stats nodir/s.json");
    EXPECT_NE(bad.status, 0);
    EXPECT_FALSE(exists(d + "/out")) << bad.output;
    RunResult r = in_d("render room.scene --size 32x32");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(exists(d + "/out/room.png"));
    EXPECT_NE(r.output.find("wrote out/room.png"), std::string::npos) << r.output;
    RunResult f = in_d("figures --size 64x64");
    ASSERT_EQ(f.status, 0) << f.output;
    EXPECT_TRUE(exists(d + "/out/figures/fig6_final.png"));
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
