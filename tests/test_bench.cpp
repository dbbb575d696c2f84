// `dsr bench` and its parts: the ideal fragment count against brute force, positions rebuilt
// from depth, the generated N-light scenes, the plot, the rows' JSON, tables and goals (called
// directly on hand-made rows, src/analysis/bench_report.h), and the command end to end.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "analysis/analytic_reference.h"
#include "analysis/bench_floor.h"
#include "analysis/bench_report.h"
#include "analysis/terminal_text.h"
#include "analysis/bench_run.h"
#include "analysis/bench_scenes.h"
#include "analysis/frame_ideal.h"
#include "analysis/ideal_fragments.h"
#include "analysis/plot.h"
#include "cli_fixture.h"
#include "deferred/scissor.h"
#include "render_fixture.h"
#include "deferred/reconstruct.h"
#include "platform/resources.h"
#include "scene/scene.h"

using namespace dsr;
using namespace dsr::test;

namespace {

// Positions of a w x h frame: a sloped floor in eye space with holes of background.
Image random_positions(int w, int h, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    Image img;
    img.width = w;
    img.height = h;
    img.rgba.assign(size_t(w) * h * 4, 0.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (u(rng) < 0.1f) continue;  // background
            float* p = img.at(x, y);
            const float z = -2.0f - 8.0f * float(y) / float(h) + 0.3f * u(rng);
            p[0] = (float(x) / float(w) - 0.5f) * -z;
            p[1] = -1.0f + 0.2f * u(rng);
            p[2] = z;
            p[3] = 1.0f;
        }
    return img;
}

// Hand-made rows: what the runner would measure for one scene and light count.
bench::Row forward_row(const std::string& scene, int lights, bench::Renderer kind, double ms) {
    bench::Row r;
    r.scene = scene;
    r.renderer = kind;
    r.lights = lights;
    r.w = r.h = 64;
    r.frames = 3;
    r.ms_median = ms, r.ms_min = ms * 0.9, r.ms_max = ms * 1.2;
    r.passes = kind == bench::Renderer::forward_multi ? lights : 1;
    r.err.psnr_db = INFINITY;  // the reference itself
    r.err.pixels = 64 * 64;
    return r;
}

// The skips with one turned off.
SkipOptions without(bool SkipOptions::*off) {
    SkipOptions s;
    s.*off = false;
    return s;
}

bench::Row deferred_row(const std::string& scene, int lights, double ms, long long frags, long long ideal,
                        SkipOptions skip = {}) {
    bench::Row r = forward_row(scene, lights, bench::Renderer::deferred, ms);
    r.passes.reset();
    r.depth = DepthPath::texture;
    r.gbuffer_half = false;
    r.scissor = true;
    r.skip = skip;
    r.frame.emplace();  // the counted frame: the row's light counts (bench_run.h light_fragments)
    r.frame->lights.fragments = frags, r.frame->lights.fragments_counted = true;
    r.frame->lights.scissor_pixels = 3 * frags;
    r.frame->lights.drawn = lights;
    r.ideal_fragments = ideal;
    r.err.max_abs = 3.0 / 255.0, r.err.mean_abs = 0.5 / 255.0, r.err.psnr_db = 55.26;
    return r;
}

// A hand-made deferred row's light counts: its counted frame's.
LightCounts& counts(bench::Row& r) {
    if (!r.frame) r.frame.emplace();
    return r.frame->lights;
}

// auto's choice in a hand-made row's counted frame: lights by quads, volumes and the tiles.
void auto_chose(bench::Row& r, int quad, int volume, int tiles) {
    if (!r.frame) r.frame.emplace();
    r.frame->auto_geometry.on = true;
    r.frame->auto_geometry.lights[at(LightPath::quad)] = quad;
    r.frame->auto_geometry.lights[at(LightPath::volume)] = volume;
    r.frame->auto_geometry.lights[at(LightPath::tiles)] = tiles;
}

}  // namespace

// The tiled count skips (light, tile) pairs by bounding boxes; it must never skip a pixel the
// definition counts. Odd sizes leave partial tiles at the right and top edges.
// The `nth` result of goal `id` among judge_goals' (a per-count goal: 0 at the scene's own count,
// 1 at kManyLights); null where there is none.
const bench::GoalResult* result(const std::vector<bench::GoalResult>& results, const std::string& id, size_t nth = 0) {
    for (const bench::GoalResult& r : results)
        if (r.goal->id == id && nth-- == 0) return &r;
    return nullptr;
}

// A goal's verdict and the figure it was judged on (value / scale), as judge_goals found them.
void expect_judged(const std::vector<bench::Row>& rows, const std::string& id, size_t nth, bench::Verdict verdict,
                   double value, double scale = 1) {
    const std::vector<bench::GoalResult> results = bench::judge_goals(rows, "default", 3);
    const bench::GoalResult* r = result(results, id, nth);
    ASSERT_NE(r, nullptr) << id;
    EXPECT_EQ(int(r->verdict), int(verdict)) << id << ": " << r->line;
    ASSERT_TRUE(r->figure.judged) << id << ": " << r->line;
    EXPECT_NEAR(r->figure.value, value, 1e-9) << id << ": " << r->line;
    EXPECT_NEAR(r->figure.scale, scale, 1e-9) << id << ": " << r->line;
}

// Text as one line per paragraph: continuation lines (a newline, then four spaces or more: wrap_lines'
// indent) joined by one space.
std::string unwrapped(std::string t) {
    for (size_t at = t.find("\n    "); at != std::string::npos; at = t.find("\n    ", at)) {
        size_t end = t.find_first_not_of(' ', at + 1);
        t.replace(at, end - at, " ");
    }
    return t;
}

TEST(Bench, IdealFragmentsMatchBruteForce) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (auto [w, h] : {std::pair{37, 29}, std::pair{128, 96}}) {
        Image pos = random_positions(w, h, rng);
        std::vector<glm::vec4> lights;
        for (int i = 0; i < 200; ++i)
            lights.emplace_back(8 * u(rng) - 4, 2 * u(rng) - 1.5f, -12 * u(rng), 3 * u(rng) * u(rng));
        lights.emplace_back(0, -1, -5, 0.0f);   // radius 0: nothing
        lights.emplace_back(0, -1, -5, 100.0f);  // covers every surface pixel
        const long long fast = ideal_fragments(pos, lights);
        const long long brute = ideal_fragments_brute(pos, lights);
        EXPECT_EQ(fast, brute) << w << "x" << h;
        EXPECT_GT(brute, 0);
        long long surface = 0;
        for (int i = 0; i < w * h; ++i) surface += pos.rgba[size_t(i) * 4 + 3] > 0.5f;
        EXPECT_EQ(ideal_fragments(pos, {{0, -1, -5, 100.0f}}), surface);
        EXPECT_EQ(ideal_fragments(pos, {}), 0);
    }
}

// A count worked by hand: a flat 5x5 patch of points one unit apart at z = -3; a light of radius
// 1.5 centred on the middle point holds the middle, its 4 edge neighbours and 4 diagonals (sqrt 2)
// but not the points 2 away.
TEST(Bench, IdealFragmentsByHand) {
    Image pos;
    pos.width = pos.height = 5;
    pos.rgba.assign(100, 0.0f);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 5; ++x) {
            float* p = pos.at(x, y);
            p[0] = float(x), p[1] = float(y), p[2] = -3.0f, p[3] = 1.0f;
        }
    EXPECT_EQ(ideal_fragments(pos, {{2, 2, -3, 1.5f}}), 9);
    EXPECT_EQ(ideal_fragments(pos, {{2, 2, -3, 1.0f}}), 1);  // strictly inside: the edge neighbours are on it
    EXPECT_EQ(ideal_fragments(pos, {{2, 2, -3, 1.5f}, {0, 0, -3, 1.01f}}), 9 + 3);
    pos.at(2, 2)[3] = 0.0f;  // background is never counted
    EXPECT_EQ(ideal_fragments(pos, {{2, 2, -3, 1.5f}}), 8);
}

// Depth written for known eye-space points along each pixel's centre ray comes back as those
// points; a cleared depth of 1 is background.
TEST(Bench, PositionsFromDepthInvertDepth) {
    const int w = 24, h = 16;
    const float n = 0.1f, f = 40.0f, p00 = 1.2f, p11 = 1.8f;
    Image depth;
    depth.width = w;
    depth.height = h;
    depth.rgba.assign(size_t(w) * h * 4, 1.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if ((x + y) % 5) depth.at(x, y)[0] = depth_from_eye_z(-0.5f - 0.7f * float(x + y), n, f);
    Image pos = positions_from_depth(depth, planes_uniform(n, f), p00, p11);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float* p = pos.at(x, y);
            if ((x + y) % 5 == 0) {
                EXPECT_EQ(p[3], 0.0f);
                continue;
            }
            const float z = -0.5f - 0.7f * float(x + y);
            const glm::vec3 ray = view_ray(x + 0.5f, y + 0.5f, w, h, p00, p11);
            EXPECT_EQ(p[3], 1.0f);
            EXPECT_NEAR(p[2], z, 2e-3f * -z);
            EXPECT_NEAR(p[0], ray.x / ray.z * z, 2e-3f * -z);
            EXPECT_NEAR(p[1], ray.y / ray.z * z, 2e-3f * -z);
        }
}

TEST(Bench, GeneratedLightsAreDeterministicAndTouchTheFloor) {
    Scene s = load_scene(resource_dir("data") + "/default.scene");
    Scene a = with_generated_lights(s, 256), b = with_generated_lights(s, 256);
    ASSERT_EQ(a.lights.size(), 256u);
    ASSERT_EQ(a.objects.size(), s.objects.size());
    float lo_y = 1e9f, lo_x = 1e9f, hi_x = -1e9f;
    for (const Object& o : s.objects)
        for (const Vertex& v : s.meshes[o.mesh].vertices) {
            const glm::vec3 p(o.model * glm::dvec4(glm::dvec3(v.pos), 1.0));
            lo_y = std::min(lo_y, p.y), lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
        }
    int off = 0;
    for (size_t i = 0; i < a.lights.size(); ++i) {
        EXPECT_EQ(a.lights[i].pos, b.lights[i].pos);
        EXPECT_EQ(a.lights[i].color, b.lights[i].color);
        EXPECT_GE(a.lights[i].pos.x, lo_x);
        EXPECT_LE(a.lights[i].pos.x, hi_x);
        EXPECT_LT(a.lights[i].pos.y - lo_y, a.lights[i].radius);  // the sphere cuts the floor
        off += a.lights[i].color == glm::vec3(0.0f);
    }
    EXPECT_EQ(off, 32);  // every 8th light is switched off
    EXPECT_NE(with_generated_lights(s, 32).lights[0].radius, a.lights[0].radius);
    EXPECT_TRUE(with_generated_lights(s, 0).lights.empty());
}

TEST(Bench, PlotDrawsPointsInTheirColour) {
    PlotPanel p;
    p.title = "test";
    PlotSeries s;
    s.label = "points";
    s.color = {1, 0, 0};
    s.points = {{2.0, 0.5, 4, ""}, {300.0, 5.0, 4, ""}, {10.0, 0.0, 4, ""}};
    p.series = {s};
    Image img = scatter_plot({p, p}, 300, 200);
    ASSERT_EQ(img.width, 600);
    ASSERT_EQ(img.height, 200);
    long long red = 0, black = 0;
    for (size_t i = 0; i < img.rgba.size(); i += 4) {
        red += img.rgba[i] == 1.0f && img.rgba[i + 1] == 0.0f && img.rgba[i + 2] == 0.0f;
        black += img.rgba[i] == 0.0f && img.rgba[i + 1] == 0.0f && img.rgba[i + 2] == 0.0f;
    }
    EXPECT_GT(red, 2 * 2 * 30);  // the markers (and legend swatch) of both panels
    EXPECT_GT(black, 500);       // axes, ticks, text
    Image t;
    t.width = 40;
    t.height = 10;
    t.rgba.assign(size_t(40) * 10 * 4, 1.0f);
    EXPECT_EQ(draw_text(t, 0, 0, "10", {0, 0, 0}), 11);
}

// What later checks read: `bench --quick` (here even smaller) writes the JSON with every required
// key, null fragment counts for forward rows, the reference's own error 0, and a report with a plot.
TEST(Bench, QuickRunWritesJsonAndReport) {
    std::string d = temp_dir();
    RunResult r = run("bench --quick --size 64x64 --lights own,32 --json " + d + "/b.json --report " + d + "/r.md");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("goals"), std::string::npos);
    ASSERT_TRUE(exists(d + "/r.md"));
    ASSERT_TRUE(exists(d + "/r_plot.png"));
    {  // the full table is the report's
        std::ifstream md(d + "/r.md");
        const std::string report((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
        EXPECT_NE(report.find("light frags"), std::string::npos);
        EXPECT_NE(report.find("## Goals"), std::string::npos);
    }
    std::ifstream in(d + "/b.json");
    nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_TRUE(j["machine"].is_string());
    EXPECT_TRUE(j["gl_renderer"].is_string());
    ASSERT_TRUE(j["rows"].is_array());
    EXPECT_GE(j["rows"].size(), 2u * 2u * 12u);  // 2 scenes x 2 light counts x at least 12 configurations
    int deferred = 0, forward = 0, analytic = 0;
    std::map<std::string, double> output_ms;
    std::map<std::string, int> alone;  // rows with their frames again back to back, by variant
    std::map<std::string, std::array<int, 2>> goal_rounds;  // goal auto's own rounds: auto rows, fixed rows
    for (auto& row : j["rows"]) {
        // dsr's default row of each variant, alone: auto with every skip on (the CPU goal's).
        if (!row["cpu_alone_ms_median"].is_null()) {
            ++alone[row["scene"].get<std::string>() + " " + row["lights_label"].get<std::string>()];
            EXPECT_EQ(row["light_geometry"], "auto") << row.dump();
            EXPECT_TRUE(row["skips_off"].empty()) << row.dump();
            // What auto chose: every drawn light by one of its three paths.
            ASSERT_TRUE(row["frame"].contains("auto")) << row.dump();
            const auto& c = row["frame"]["auto"]["lights"];
            ASSERT_TRUE(c.is_object()) << row.dump();
            EXPECT_EQ(c["quad"].get<int>() + c["volume"].get<int>() + c["tiles"].get<int>(),
                      row["frame"]["lights_drawn"].get<int>())
                << row.dump();
            EXPECT_EQ(row["cpu_alone_frames_ms"].size(), size_t(row["frames"].get<int>()));
            EXPECT_GT(row["cpu_alone_ms_median"].get<double>(), 0.0);
        } else {
            EXPECT_TRUE(row["cpu_alone_frames_ms"].empty()) << row.dump();
        }
        // Goal `auto`'s own rounds: auto's row and fixed geometries' rows on the default
        // configuration, 3x the frames each; no other row.
        const std::string variant_name = row["scene"].get<std::string>() + " " + row["lights_label"].get<std::string>();
        if (!row["goal_rounds_ms_median"].is_null()) {
            const std::string geometry = row["light_geometry"];
            EXPECT_TRUE(geometry == "auto" || geometry == "quad" || geometry == "volume" || geometry == "stencil" ||
                        geometry == "tiles")
                << row.dump();
            EXPECT_TRUE(row["skips_off"].empty()) << row.dump();
            EXPECT_FALSE(row["linear_law"].get<bool>()) << row.dump();
            EXPECT_EQ(row["goal_rounds_frames_ms"].size(), size_t(3 * row["frames"].get<int>())) << row.dump();
            EXPECT_EQ(row["goal_rounds_lights_frames_ms"].size(), row["goal_rounds_frames_ms"].size()) << row.dump();
            ++goal_rounds[variant_name][geometry == "auto" ? 0 : 1];
        } else {
            EXPECT_TRUE(row["goal_rounds_frames_ms"].empty()) << row.dump();
        }
        for (const char* k : {"renderer", "depth", "scissor", "lights", "size", "ms_median", "ms_min", "ms_max",
                              "frame", "ideal_fragments", "max_lsb", "mean_lsb", "psnr_db"})
            ASSERT_TRUE(row.contains(k)) << k;
        EXPECT_EQ(row["size"], nlohmann::json::array({64, 64}));
        EXPECT_TRUE(row["scissor"].is_boolean());
        EXPECT_LE(row["ms_min"].get<double>(), row["ms_median"].get<double>());
        EXPECT_LE(row["ms_median"].get<double>(), row["ms_max"].get<double>());
        // One thread's CPU time: positive, and no more than the frame's wall time.
        EXPECT_GT(row["cpu_ms_median"].get<double>(), 0.0);
        EXPECT_LE(row["cpu_ms_median"].get<double>(), row["ms_max"].get<double>() + 0.5);
        // The timed frames round by round, and no warm-up frame among the light stages.
        EXPECT_EQ(row["frames_ms"].size(), size_t(row["frames"].get<int>()));
        EXPECT_EQ(row["cpu_frames_ms"].size(), row["frames_ms"].size());
        EXPECT_EQ(row["warmup_frames_ms"].size(), size_t(row["warmup_frames"].get<int>()));
        EXPECT_GE(row["warmup_frames"].get<int>(), 1);  // --quick: one warm-up frame at least
        const std::string kind = row["renderer"];
        if (kind == "deferred") {
            ++deferred;
            EXPECT_EQ(row["lights_frames_ms"].size(), row["frames_ms"].size());
            // Each frame's CPU parts lie within its whole, so their medians within the largest whole.
            const std::vector<double> cpu = row["cpu_frames_ms"];
            const double most = *std::max_element(cpu.begin(), cpu.end());
            EXPECT_GE(row["cpu_make_frame_ms"].get<double>(), 0.0);
            EXPECT_LE(row["cpu_make_frame_ms"].get<double>(), most);
            EXPECT_GT(row["cpu_lights_ms"].get<double>(), 0.0);
            EXPECT_LE(row["cpu_lights_ms"].get<double>(), most);
            EXPECT_TRUE(row["depth"] == "texture" || row["depth"] == "packed" || row["depth"] == "position16" ||
                        row["depth"] == "position32");
            for (const char* k : {"light_fragments", "light_invocations", "light_evaluations", "scissor_pixels",
                                  "lights_drawn", "light_passes"})
                ASSERT_TRUE(row["frame"].contains(k)) << k;
            const long long frags = row["frame"]["light_fragments"], ideal = row["ideal_fragments"];
            EXPECT_GT(ideal, 0);
            // With the depth texture nothing inside a sphere is rejected (scissor rectangles and the
            // light depth test are conservative), so the ideal count exceeds what was shaded only by
            // the pixels where exact surface points (the analytic trace's shapes, or depth decoded in
            // double) and the shader's float reconstruction fall on different sides of a sphere.
            // (tiles: one fragment per pixel and group of lights, not per light: fewer.)
            // (screen: one fragment per pixel and batch of lights, whatever reaches it.)
            // (auto: its tiles' lights likewise.)
            if (row["depth"] == "texture" && row["light_geometry"] != "tiles" && row["light_geometry"] != "screen" &&
                row["light_geometry"] != "auto") {
                EXPECT_GE(frags, ideal - ideal / 100) << row.dump();
            }
            // Every fragment that passed entered the shader first; the floor is measured on every row.
            EXPECT_GE(row["frame"]["light_invocations"].get<long long>(), frags) << row.dump();
            EXPECT_GT(row["floor_ms"].get<double>(), 0.0) << row.dump();
            EXPECT_DOUBLE_EQ(row["floor_ratio"].get<double>(),
                             row["ms_median"].get<double>() / row["floor_ms"].get<double>());
            EXPECT_EQ(row["floor_post_ms"].get<double>(), 0.0);  // post off in every row
            // (d) is the output target's clear: one measurement per scene variant (scene and light
            // count) whatever the G-buffer layout.
            const std::string variant = row["scene"].get<std::string>() + " " + row["lights_label"].get<std::string>();
            if (!output_ms.count(variant)) output_ms[variant] = row["floor_output_ms"].get<double>();
            EXPECT_EQ(row["floor_output_ms"].get<double>(), output_ms[variant]) << row.dump();
            EXPECT_NEAR(row["floor_ms"].get<double>(),
                        row["floor_fill_ms"].get<double>() + row["floor_output_ms"].get<double>() +
                            row["ideal_fragments"].get<double>() * row["floor_light_ns"].get<double>() * 1e-6,
                        1e-9)
                << row.dump();
            // A metallic-roughness row (analytic-metal-rough) takes its variant's ideal count: the same geometry.
            const bool analytic = row["scene"] == "analytic" || row["scene"] == bench::metal_rough_name("analytic");
            EXPECT_EQ(row["ideal_source"], analytic ? "analytic" : "depth24") << row.dump();
        } else {
            ++forward;
            EXPECT_TRUE(kind == "forward-single" || kind == "forward-multi") << kind;
            EXPECT_TRUE(row["accum"] == "float" || row["accum"] == "rgba8") << row.dump();
            EXPECT_TRUE(row["frame"].is_null());  // no light passes: no light_invocations, light_fragments
            EXPECT_TRUE(row["invocations_ratio"].is_null());
            EXPECT_TRUE(row["cpu_lights_ms"].is_null());
            EXPECT_TRUE(row["floor_ratio"].is_null());
            EXPECT_TRUE(row["fragments_ratio"].is_null());
            EXPECT_TRUE(row["ideal_fragments"].is_null());
            if (kind == "forward-single" && row["accum"] == "float") {
                EXPECT_EQ(row["max_lsb"].get<double>(), 0.0);  // it is the reference
            }
        }
        if (row["scene"] == "analytic") {
            ++analytic;
            EXPECT_TRUE(row["max_lsb_analytic"].is_number());
        }
    }
    EXPECT_EQ(forward, 2 * 2 * 4);  // single and multi-pass, each with float and RGBA8 accumulation
    EXPECT_GE(deferred, 2 * 2 * 10);
    EXPECT_EQ(alone.size(), 2u * 2u);  // one row of each scene and light count
    for (const auto& [variant, n] : alone) EXPECT_EQ(n, 1) << variant;
    EXPECT_EQ(goal_rounds.size(), 2u * 2u);  // every variant: its auto row and at least the fastest fixed one
    for (const auto& [variant, n] : goal_rounds) {
        EXPECT_EQ(n[0], 1) << variant;
        EXPECT_GE(n[1], 1) << variant;
    }
    EXPECT_GT(analytic, 0);
}

// What `dsr bench` prints on stdout: what the run shows first, then every goal of the table as its
// plain sentence with a verdict, the rows in words with each time's spread and image error, where
// the report went and what the exit status means; every line within the terminal's width.
TEST(Bench, QuickRunPrintsTheSummaryFirst) {
    const std::string d = temp_dir();
    RunResult r = run_stdout("bench --quick --size 48x48 --lights own --frames 3 --light-geometry quad --report " + d +
                             "/s.md");
    ASSERT_EQ(r.status, 0) << r.output;
    ASSERT_TRUE(exists(d + "/s.md"));
    EXPECT_EQ(r.output.rfind("dsr bench --quick: ", 0), 0u) << r.output;
    const size_t shows = r.output.find("\nWhat this run shows:\n"), goals = r.output.find("\nGoals, on the default scene:\n"),
                 table = r.output.find("\nThe default scene at 48x48");
    EXPECT_LT(shows, goals) << r.output;
    EXPECT_LT(goals, table) << r.output;
    EXPECT_NE(table, std::string::npos) << r.output;
    EXPECT_EQ(lines_over(r.output), std::vector<std::string>{}) << r.output;
    const std::string text = unwrapped(r.output);
    EXPECT_NE(text.find(d + "/s.md"), std::string::npos) << r.output;
    EXPECT_NE(text.find("Exit status 0"), std::string::npos) << r.output;
    EXPECT_EQ(text.find("light frags"), std::string::npos) << "the fragment counts belong in the report: " << r.output;
    EXPECT_NE(text.find("\ndeferred, no scissor "), std::string::npos) << "rows in words: " << r.output;
    for (const bench::Goal& g : bench::goal_table()) {
        if (g.retired) continue;
        const std::string plain = g.plain;
        const std::string head = plain.substr(0, plain.find('{'));  // the words before the first figure
        EXPECT_NE(text.find(head), std::string::npos) << g.id << ": " << r.output;
    }
    // Each goal's line carries exactly one verdict.
    int verdicts = 0;
    std::stringstream ss(r.output);
    for (std::string l; std::getline(ss, l);)
        verdicts += l.rfind("  met ", 0) == 0 || l.rfind("  NOT met ", 0) == 0 || l.rfind("  not judged ", 0) == 0;
    EXPECT_EQ(verdicts, int(bench::judge_goals({}, "default", 3).size())) << r.output;
}

// What the summary's first lines are made of, from rows made by hand: dsr's default against the
// faster forward rows at the judged scene's largest count, the fastest fixed geometry, the largest
// image errors, the goals' count and the frames' spread.
TEST(Bench, ConclusionsComeFromTheRows) {
    std::vector<bench::Row> rows = {forward_row("default", 3, bench::Renderer::forward_single, 2.0),
                                    forward_row("default", 256, bench::Renderer::forward_single, 6.0),
                                    forward_row("default", 256, bench::Renderer::forward_multi, 30.0),
                                    deferred_row("default", 3, 1.0, 100, 100), deferred_row("default", 256, 3.0, 100, 100)};
    bench::Row fm8 = forward_row("default", 256, bench::Renderer::forward_multi, 25.0);
    fm8.float_accum = false;
    bench::Row tiles = deferred_row("default", 256, 2.0, 100, 100);
    tiles.light_geometry = LightGeometry::tiles;
    bench::Row packed = deferred_row("default", 256, 2.5, 100, 100);
    packed.depth = DepthPath::packed, packed.encoding = DepthEncoding::literal;
    packed.err.max_abs = 9 / 255.0;
    rows[4].err.max_abs = 2 / 255.0;
    rows[4].frames_ms = {2.0, 2.5, 3.0, 3.5, 4.0};  // quartiles 2.5 and 3.5 around 3.0: ±1/6
    rows.insert(rows.end(), {fm8, tiles, packed});
    const std::vector<bench::GoalResult> goals = bench::judge_goals(rows, "default", 3);
    bench::Conclusions c = bench::conclusions(rows, "default", goals);
    EXPECT_EQ(c.lights, 256);
    EXPECT_EQ(c.default_row, &rows[4]);  // quad: the run has no auto row
    EXPECT_EQ(c.forward_single, &rows[1]);
    EXPECT_EQ(c.forward_multi, &rows[5]);  // the faster of the two forms
    EXPECT_EQ(c.fastest_geometry, &rows[6]);
    EXPECT_DOUBLE_EQ(c.default_max_lsb, 3);  // the 3-light row's 3 LSB, the 256-light one's 2
    EXPECT_DOUBLE_EQ(c.deferred_max_lsb, 9);
    EXPECT_EQ(c.worst_deferred, &rows[7]);
    EXPECT_NEAR(bench::time_spread(rows[4]), 1.0 / 6.0, 1e-12);
    EXPECT_EQ(bench::time_text(rows[4]), "3.00 ±17%");
    ASSERT_GE(c.lines.size(), 4u);
    EXPECT_NE(c.lines[0].find("3.00 ms"), std::string::npos) << c.lines[0];
    EXPECT_NE(c.lines[0].find("25.00 ms"), std::string::npos) << c.lines[0];
    // An auto row is dsr's default where the run has one.
    bench::Row a = deferred_row("default", 256, 2.2, 100, 100);
    a.light_geometry = LightGeometry::automatic;
    rows.push_back(a);
    EXPECT_EQ(bench::conclusions(rows, "default", goals).default_row, &rows.back());
    EXPECT_EQ(bench::conclusions({}, "default", {}).lines, std::vector<std::string>{});
}

// The summary on hand-made rows: every goal of judge_goals with its verdict, in its order, the
// report named; the retired goal left out.
TEST(Bench, SummarySaysEachGoalPlainly) {
    bench::Summary s;
    s.machine = "test";
    s.gl_renderer = "a GL", s.gl_version = "2.1";
    s.scenes = {"default"};
    s.notes = {"one note"};
    bench::Row d = deferred_row("default", 3, 1.0, 100, 100);
    counts(d).invocations = counts(d).evaluations = 120;
    bench::Row d1080 = deferred_row("default", 1024, 1.0, 100, 100);
    d1080.w = 1920, d1080.h = 1080;
    d1080.floor_ms = 0.5, d1080.floor_ratio = 2.0;
    s.rows = {d, d1080};
    s.goal_results = bench::judge_goals(s.rows, "default", 3);
    const std::string t = unwrapped(bench::text_summary(s, "r.md", "r.json"));
    size_t at = 0;
    for (const bench::GoalResult& g : s.goal_results) {
        const std::string verdict = g.verdict == bench::Verdict::met       ? "  met         "
                                    : g.verdict == bench::Verdict::not_met ? "  NOT met     "
                                                                           : "  not judged  ";
        const size_t found = t.find("\n" + verdict + g.plain + ": ", at);
        ASSERT_NE(found, std::string::npos) << g.goal->id << ": " << t;
        at = found + 1;
    }
    EXPECT_EQ(int(result(s.goal_results, "floor", 1)->verdict), int(bench::Verdict::not_met));
    EXPECT_EQ(t.find("retired"), std::string::npos) << t;
    EXPECT_NE(t.find("the note, every row"), std::string::npos) << t;
    EXPECT_NE(t.find(": r.md\n"), std::string::npos) << t;
    EXPECT_NE(t.find("JSON: r.json\n"), std::string::npos) << t;
}

TEST(Bench, BadFlagsAreOneClearError) {
    for (const char* args : {"bench --frobnicate", "bench --lights 3,x", "bench --json out.txt", "bench --size 0x3"}) {
        RunResult r = run(args);
        EXPECT_NE(r.status, 0) << args;
        EXPECT_EQ(r.output.rfind("dsr bench: ", 0), 0u) << args << ": " << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    }
}

TEST(Bench, ConfigTextNamesEveryChoice) {
    bench::Row r = deferred_row("default", 3, 1.0, 10, 10, without(&SkipOptions::empty_lights));
    EXPECT_EQ(bench::config_text(r), "deferred texture sc no-empty_lights");
    r.depth = DepthPath::packed, r.encoding = DepthEncoding::log, r.scissor = false, r.gbuffer_half = true, r.skip = {};
    EXPECT_EQ(bench::config_text(r), "deferred packed/log - half");
    EXPECT_EQ(bench::config_text(forward_row("default", 3, bench::Renderer::forward_multi, 1.0)), "forward-multi");
    r.light_geometry = LightGeometry::tiles, r.tile_size = 32, r.tile_lights = 8;  // the tiles settings as run (auto resolved)
    EXPECT_EQ(bench::config_text(r), "deferred packed/log - half tiles 32/8");
    r.linear_law = true;  // the twin of N-large with Equation 2's law
    EXPECT_EQ(bench::config_text(r), "deferred packed/log - half tiles 32/8 linear-law");
}

// The goals as the report states them, judged on rows made by hand: met, NOT met, not measured,
// and light_fragments / ideal (true by construction with the sphere test) as information only.
TEST(Bench, GoalsJudgeTheDefaultConfiguration) {
    auto with = [](bench::Row r, long long inv, double floor_ms) {
        counts(r).invocations = counts(r).evaluations = inv;  // one light a fragment, as quad's passes
        r.floor_ms = floor_ms;
        r.floor_ratio = r.ms_median / floor_ms;
        return r;
    };
    bench::Row multi_rgba8 = forward_row("default", 256, bench::Renderer::forward_multi, 30.0);
    multi_rgba8.float_accum = false;
    bench::Row multi_float = forward_row("default", 256, bench::Renderer::forward_multi, 40.0);
    multi_float.float_accum = true;
    std::vector<bench::Row> rows = {
        forward_row("default", 3, bench::Renderer::forward_multi, 5.0),
        with(deferred_row("default", 3, 1.0, 100, 100), 120, 0.8),  // 1.20 x ideal, floor ratio 1.25: met
        with(deferred_row("default", 3, 1.0, 150, 100, without(&SkipOptions::light_sphere_test)), 300, 0.8),
        multi_float,
        multi_rgba8,
        with(deferred_row("default", 256, 3.0, 200, 100), 500, 1.0),
    };
    // A non-default deferred row of the same count is never the one judged.
    bench::Row packed = with(deferred_row("default", 3, 1.0, 100, 100), 100, 1.0);
    packed.depth = DepthPath::packed, packed.encoding = DepthEncoding::corrected;
    rows.insert(rows.begin(), packed);
    const std::vector<std::string> g = bench::goals(rows, "default", 3);
    ASSERT_EQ(g.size(), 8u + 11u);  // + the light geometries' eleven, none measured here
    for (size_t i = 8; i < g.size(); ++i) EXPECT_NE(g[i].find("not measured in this run"), std::string::npos) << g[i];
    // The retired evaluations goal: its figure as information, never a verdict, and no goal of the summary.
    EXPECT_EQ(g[0].rfind("  (information, retired as a goal", 0), 0u) << g[0];
    EXPECT_NE(g[0].find(": 120 / 100 = 1.200 (quad)"), std::string::npos) << g[0];
    EXPECT_EQ(g[0].find("-> "), std::string::npos) << g[0];
    EXPECT_EQ(result(bench::judge_goals(rows, "default", 3), "invocations"), nullptr);
    EXPECT_EQ(g[1].rfind("  (information, not a goal: quad's light_fragments / ideal = 100 / 100 = 1.000;", 0), 0u) << g[1];
    EXPECT_EQ(g[1].find("met"), std::string::npos);  // never judged
    EXPECT_NE(g[2].find("--no-skip light-sphere-test: light_fragments / ideal = 150 / 100 = 1.500; light_invocations / "
                        "ideal = 300 / 100 = 3.000)"),
              std::string::npos)
        << g[2];
    // The floor is judged at 1920x1080 with 1024 lights (and on 32-large, below) only; elsewhere its figure is
    // information.
    {
        const std::vector<bench::GoalResult> judged = bench::judge_goals(rows, "default", 3);
        const bench::GoalResult* f = result(judged, "floor");
        ASSERT_NE(f, nullptr);
        EXPECT_EQ(int(f->verdict), int(bench::Verdict::not_judged));
        EXPECT_NE(f->figure.working.find("1.00 ms / 0.80 ms = 1.25"), std::string::npos) << f->line;
        EXPECT_NE(f->figure.working.find("this row is 64x64 with 3 lights"), std::string::npos) << f->line;
    }
    // ... and on 32-large at 1920x1080 (LearnOpenGL's demo); not on 32-large at another size.
    {
        bench::Row demo = deferred_row("large", 32, 3.0, 100, 100);
        demo.lights_label = "32-large", demo.w = 1920, demo.h = 1080;
        demo.floor_ms = 2.0, demo.floor_ratio = 1.5;
        const auto verdict = [](const bench::Row& r) {
            const std::vector<bench::Row> one = {r};
            const std::vector<bench::GoalResult> judged = bench::judge_goals(one, "large", 32);
            const bench::GoalResult* f = result(judged, "floor");
            EXPECT_NE(f, nullptr);
            if (f && f->verdict != bench::Verdict::not_judged)
                EXPECT_NE(f->figure.working.find(" ms / 2.00 ms = "), std::string::npos) << f->figure.working;
            return f ? int(f->verdict) : -1;
        };
        EXPECT_EQ(verdict(demo), int(bench::Verdict::met));
        demo.floor_ratio = 1.6;
        EXPECT_EQ(verdict(demo), int(bench::Verdict::not_met));
        demo.w = 800, demo.h = 600;
        EXPECT_EQ(verdict(demo), int(bench::Verdict::not_judged));
    }
    EXPECT_NE(g[4].find("default with 1024 lights: not measured in this run"), std::string::npos) << g[4];
    EXPECT_EQ(int(result(bench::judge_goals(rows, "default", 3), "floor", 1)->verdict), int(bench::Verdict::not_judged));
    EXPECT_EQ(result(bench::judge_goals(rows, "default", 3), "floor", 1)->figure.working, "not measured in this run");
    // Judged against the faster forward multi-pass row (RGBA8 here), not the float one.
    expect_judged(rows, "speed_256", 0, bench::Verdict::met, 30.0 / 3.0);  // the float row's would be 13.3
    EXPECT_EQ(int(result(bench::judge_goals(rows, "default", 3), "cpu")->verdict), int(bench::Verdict::not_judged));

    // NOT met: 1.26 x ideal at 1024 lights; at 256 only 8x the faster baseline. The floor ratio 1.4
    // at 1024 lights is information at 64x64.
    rows.push_back(with(deferred_row("default", 1024, 1.4, 100, 100), 126, 1.0));
    rows.push_back(with(deferred_row("default", 256, 3.75, 100, 100), 100, 1.0));
    rows.erase(rows.begin() + 6);  // the 3.0 ms row: the 3.75 ms one is judged
    const std::vector<std::string> h = bench::goals(rows, "default", 3);
    ASSERT_EQ(h.size(), 9u + 11u);
    EXPECT_NE(h[4].find("default with 1024 lights: 126 / 100 = 1.260 (quad)"), std::string::npos) << h[4];
    EXPECT_EQ(h[4].find("-> "), std::string::npos) << h[4];  // retired: information
    // Where the run has an auto row, dsr's default: its evaluations judged (tiles: a tile's every
    // light at each of its pixels, so more than its invocations), quad's invocations information.
    bench::Row a3 = with(deferred_row("default", 3, 0.8, 90, 100), 40, 0.8);
    a3.light_geometry = LightGeometry::automatic;
    counts(a3).evaluations = 110;
    auto_chose(a3, 0, 0, 3);
    rows.push_back(a3);
    const std::vector<std::string> a = bench::goals(rows, "default", 3);
    EXPECT_NE(a[0].find(": 110 / 100 = 1.100 (auto) (auto's lights: 0 by quads, 0 by volumes, 3 by the tiles)"),
              std::string::npos)
        << a[0];
    EXPECT_NE(a[1].find("--light-geometry quad: light_invocations / ideal = 120 / 100 = 1.200)"), std::string::npos) << a[1];
    // With rows of other geometries: each one's ratio, fewest first, whether or not it is auto's.
    std::vector<bench::Row> more = rows;
    bench::Row volume3 = with(deferred_row("default", 3, 0.9, 90, 100), 300, 0.8);
    volume3.light_geometry = LightGeometry::volume;
    bench::Row tiles3 = with(deferred_row("default", 3, 0.9, 90, 100), 40, 0.8);
    tiles3.light_geometry = LightGeometry::tiles;
    counts(tiles3).evaluations = 105;
    more.insert(more.end(), {volume3, tiles3});
    const std::vector<std::string> m = bench::goals(more, "default", 3);
    EXPECT_NE(m[1].find("fewest first: tiles 1.050, quad 1.200, volume 3.000)"), std::string::npos) << m[1];
    EXPECT_EQ(m[2], a[1]);
    rows.pop_back();
    EXPECT_NE(h[6].find("1.40 ms / 1.00 ms = 1.40 (information: judged at 1920x1080 with 1024 lights or on 32-large only; this row "
                        "is 64x64 with 1024 lights)"),
              std::string::npos)
        << h[6];
    expect_judged(rows, "speed_256", 0, bench::Verdict::not_met, 30.0 / 3.75);
    // At 1920x1080: 1.4 met, 1.6 NOT met.
    bench::Row& r1024 = rows[rows.size() - 2];
    r1024.w = 1920, r1024.h = 1080;
    expect_judged(rows, "floor", 1, bench::Verdict::met, 1.40);
    r1024 = with(r1024, 126, 0.8);
    expect_judged(rows, "floor", 1, bench::Verdict::not_met, 1.75);
    // dsr's default is judged where the run has it: the auto row, not the tutorial's quad.
    bench::Row a1024 = with(r1024, 126, 1.0);
    a1024.light_geometry = LightGeometry::automatic;
    rows.push_back(a1024);
    expect_judged(rows, "floor", 1, bench::Verdict::met, 1.40);  // auto's 1.40 ms / 1.00 ms, not quad's 1.75
    rows.pop_back();
    r1024.w = 1280;
    EXPECT_EQ(int(result(bench::judge_goals(rows, "default", 3), "floor", 1)->verdict),
              int(bench::Verdict::not_judged));  // another size: information

    // CPU ms a frame at 4096 lights, on dsr's default (auto; quad where there is no auto row).
    bench::Row q4096 = deferred_row("default", 4096, 5.0, 100, 100);
    q4096.cpu_ms = 0.4;
    rows.push_back(q4096);
    expect_judged(rows, "cpu", 0, bench::Verdict::met, 0.40);
    bench::Row a4096 = q4096;
    a4096.light_geometry = LightGeometry::automatic, a4096.cpu_ms = 0.6;
    rows.push_back(a4096);
    expect_judged(rows, "cpu", 0, bench::Verdict::not_met, 0.60);  // auto's, not quad's 0.40
    // With its frames run again back to back (bench_run's rows have them): judged on those.
    rows.back().cpu_alone_ms = 0.35;
    expect_judged(rows, "cpu", 0, bench::Verdict::met, 0.35);

    const std::vector<std::string> none = bench::goals({}, "default", 3);
    ASSERT_EQ(none.size(), 6u + 11u);
    for (const bench::GoalResult& r : bench::judge_goals({}, "default", 3)) {
        EXPECT_EQ(int(r.verdict), int(bench::Verdict::not_judged)) << r.line;
        EXPECT_FALSE(r.figure.judged) << r.line;
    }
    EXPECT_NE(none[4].find(": not measured in this run"), std::string::npos) << none[4];
}

// The light geometries' goals (docs/light_geometry.md) on hand-made rows: stencil invocations against the ideal, tiles against quad on
// 1024-overlap, dsr's default against the screen geometry (LearnOpenGL's demo) on 32-large with the
// withdrawn forward goal as information, images against quad, auto against the fastest fixed geometry.
TEST(Bench, GeometryGoalsJudgeTheirRows) {
    auto geo = [](bench::Row r, LightGeometry g, long long inv, double lsb_vs_quad) {
        r.light_geometry = g;
        counts(r).invocations = inv;
        ImageDiff d;
        d.max_abs = lsb_vs_quad / 255.0;
        r.err_quad = d;
        return r;
    };
    std::vector<bench::Row> rows = {
        geo(deferred_row("default", 3, 1.0, 100, 100), LightGeometry::quad, 300, 0),
        geo(deferred_row("default", 3, 1.0, 100, 100), LightGeometry::stencil, 110, 1),    // 1.10 x ideal: met
        geo(deferred_row("default", 1024, 9.0, 100, 100), LightGeometry::stencil, 200, 2),  // 2.00 x: NOT met; 2 LSB
        geo(deferred_row("default-overlap", 1024, 9.0, 100, 100), LightGeometry::quad, 900, 0),
        geo(deferred_row("default-overlap", 1024, 2.0, 100, 100), LightGeometry::tiles, 100, 0),  // 4.5x: met
    };
    rows[3].lights_label = rows[4].lights_label = "1024-overlap";
    const std::vector<std::string> g = bench::geometry_goals(rows, "default", 3);
    ASSERT_EQ(g.size(), 11u);
    EXPECT_EQ(g[0], "stencil light_invocations <= 1.25 x ideal, default with 3 lights: 110 / 100 = 1.100 -> met");
    EXPECT_EQ(g[1], "stencil light_invocations <= 1.25 x ideal, default with 1024 lights: 200 / 100 = 2.000 -> NOT met");
    EXPECT_EQ(g[2], "tiles >= 3x faster than quad on 1024-overlap: 9.00 ms / 2.00 ms = 4.50x -> met");
    {
        // With the rows' frames, round by round (frame i of each in round i): the ratio's range and
        // the rounds in which the goal held follow the verdict; a slower row's missing rounds are
        // left out, and so is a round whose denominator is 0.
        std::vector<bench::Row> timed = rows;
        timed[3].frames_ms = {9.0, 8.0, 9.0, 6.0};
        timed[4].frames_ms = {2.0, 4.0, 2.5, 0.0, 1.0};
        const std::string t = bench::geometry_goals(timed, "default", 3)[2];
        EXPECT_EQ(t, "tiles >= 3x faster than quad on 1024-overlap: 9.00 ms / 2.00 ms = 4.50x -> met; round by round "
                     "2.00-4.50, held in 2 of 3 rounds") << t;
    }
    {
        // With the scene's screen row and the light stages' ms, how far the goal could go follows:
        // the screen's 52.2 ms less 2 passes' floor (2 x 0.1 ms at 0.5 ns a pixel over 200000) over
        // 1024 x 200000 evaluations is 0.25 ns each (52.0 / 204.8 M); the tiles' frame outside its
        // light stage 0.5 ms, plus one pass's floor 0.1, plus 4 M ideal pairs at that cost (1.015625
        // ms) is 1.615625 ms, and quad's 9 ms is 5.57x that; the tiles' 1.5 ms is 1.34x 1.115625.
        std::vector<bench::Row> est = rows;
        bench::Row screen = geo(deferred_row("default-overlap", 1024, 60.0, 100, 100), LightGeometry::screen, 100, 0);
        screen.lights_label = "1024-overlap";
        screen.w = 500, screen.h = 400;
        screen.lights_ms = 52.2;
        screen.floor_light_ns = 0.5;
        counts(screen).passes = 2;
        est.push_back(screen);
        est[4].lights_ms = 1.5;
        est[4].ideal_fragments = 4000000;
        const std::vector<std::string> e = bench::geometry_goals(est, "default", 3);
        ASSERT_EQ(e.size(), 13u) << e[4];
        EXPECT_EQ(e[2], g[2]);
        EXPECT_EQ(e[3], "  (information: the screen row's light stage 52.20 ms less 2 x its per-pixel floor (0.50 ns a "
                        "pixel: 0.20 ms) over 1024 x 200000 evaluations is 0.25 ns each; the tiles row's frame outside "
                        "its light stage 0.50 ms plus one pass's floor (0.10 ms) plus 4000000 ideal pairs at that cost "
                        "(1.02 ms) is 1.62 ms, and quad 5.57x slower than that; the tiles row's light stage is 1.50 ms, "
                        "1.34x that ideal's 1.12 ms)");
        est[4].lights_ms.reset();  // without the tiles' light stage, no estimate
        EXPECT_EQ(bench::geometry_goals(est, "default", 3).size(), 12u);
    }
    EXPECT_EQ(g[3], "dsr's default >= 3x faster than screen (LearnOpenGL's lighting pass) on 32-large: not measured "
                    "in this run");
    EXPECT_NE(g[4].find("largest 2 LSB"), std::string::npos) << g[4];
    EXPECT_NE(g[4].find("-> NOT met"), std::string::npos) << g[4];
    EXPECT_EQ(g[5], "attenuation law's light stage <= 1.05 x the linear law's on the same pairs, 32-large: not "
                    "measured in this run");
    // auto: one line per bench scene, not judged without an auto row.
    EXPECT_EQ(g[6], "auto <= 1.1 x the fastest fixed geometry (quad, volume, stencil, tiles), default at --lights own: "
                    "not measured in this run (no auto row)");
    EXPECT_NE(g[9].find("default at --lights 1024-overlap: not measured"), std::string::npos) << g[9];
    EXPECT_NE(g[10].find("default at --lights 32-large: not measured"), std::string::npos) << g[10];

    // A GL whose invocation counter counts fragments the stencil rejects cannot judge the stencil
    // goal: neither met nor NOT met, with the occlusion-query ratio as information. A GL whose
    // counter counted none of the probe's rejected fragments is judged as before.
    counts(rows[1]).fragments = 105;
    InvocationProbe counts;
    counts.pixels = counts.invocations = 4096;
    const std::vector<std::string> c = bench::geometry_goals(rows, "default", 3, counts);
    EXPECT_EQ(c[0], "stencil light_invocations <= 1.25 x ideal, default with 3 lights: cannot be judged on this GL: its "
                    "fragment-shader invocation counter counts fragments the stencil test rejects (probe: 4096 "
                    "invocations for 4096 pixels that all fail the stencil test); invocations 110 / 100 = 1.100; "
                    "what passed the stencil (occlusion query) 105 / 100 = 1.050 (information)");
    EXPECT_EQ(c[1].find("-> "), std::string::npos) << c[1];
    InvocationProbe exact;
    exact.pixels = 4096;
    EXPECT_EQ(bench::geometry_goals(rows, "default", 3, exact)[0], g[0]);

    // 32-large at the demo's 800x600: without a screen row the demo goal is not judged, and the
    // withdrawn goal (the fastest deferred row against the faster forward single-pass) follows it
    // as information, with the scene without lights (0-large) where the run has it.
    auto large = [](bench::Row r, const char* label) {
        r.scene = "large";
        r.lights_label = label;
        r.w = 800, r.h = 600;
        return r;
    };
    bench::Row fwd = large(forward_row("large", 32, bench::Renderer::forward_single, 6.0), "32-large");
    fwd.float_accum = false;
    bench::Row slow = large(geo(deferred_row("large", 32, 9.0, 500, 500), LightGeometry::quad, 2000, 0), "32-large");
    bench::Row fast = large(geo(deferred_row("large", 32, 5.0, 500, 500), LightGeometry::tiles, 100, 0), "32-large");
    fast.tile_size = 16, fast.tile_lights = 32;
    rows.insert(rows.end(), {fwd, slow, fast});
    const std::vector<std::string> l = bench::geometry_goals(rows, "default", 3);
    ASSERT_EQ(l.size(), 12u);
    EXPECT_EQ(l[3], g[3]);
    const std::string bound =
        "  (information, withdrawn as a goal: best deferred against forward single-pass on 32-large: forward, a pass "
        "per object, 8-bit sums 6.00 ms / deferred, screen tiles of 16 px, 32 lights a pass 5.00 ms = 1.20x. Forward single-pass is the bound here on GL "
        "2.x, not a rival to beat by 1.5x: over 9 boxes it shades each pixel once, with every light in one shader, and "
        "the pixels lie inside most of the lights, so no light geometry leaves out any of its work and deferred adds "
        "the G-buffer";
    EXPECT_EQ(l[4], bound + ")");
    EXPECT_EQ(l[4].find("-> "), std::string::npos);  // never judged
    bench::Row fwd0 = large(forward_row("large", 0, bench::Renderer::forward_single, 0.5), "0-large");
    fwd0.float_accum = false;
    bench::Row fast0 = large(geo(deferred_row("large", 0, 1.5, 0, 0), LightGeometry::tiles, 0, 0), "0-large");
    fast0.tile_size = 16, fast0.tile_lights = 32;
    rows.insert(rows.end(), {fwd0, fast0});
    EXPECT_EQ(bench::geometry_goals(rows, "default", 3)[4],
              bound + "; without lights (0-large) 0.50 and 1.50 ms, so forward's light work takes 5.50 ms and 1.5x "
                      "would leave the deferred row 2.50 ms for 500 ideal pixel-light pairs)");

    // The screen row: 30 ms against quad's 9 (no auto row): met. Its image against quad's is
    // information, not the geometries' goal.
    bench::Row screen = large(geo(deferred_row("large", 32, 30.0, 500, 500), LightGeometry::screen, 480000, 4), "32-large");
    rows.push_back(screen);
    const std::vector<std::string> m = bench::geometry_goals(rows, "default", 3);
    EXPECT_EQ(m[3], "dsr's default >= 3x faster than screen (LearnOpenGL's lighting pass) on 32-large: screen 30.00 ms / "
                    "quad 9.00 ms = 3.33x (dsr's default geometry: quad, the run has no auto row; 800x600, the demo's "
                    "size) -> met");
    EXPECT_NE(m[5].find("largest 2 LSB"), std::string::npos) << m[5];
    EXPECT_EQ(m[6].rfind("  (information: the screen rows", 0), 0u) << m[6];
    EXPECT_NE(m[6].find("largest 4 LSB ("), std::string::npos) << m[6];
    EXPECT_NE(m[6].find("large at 32 lights, 1 rows))"), std::string::npos) << m[6];
    // With an auto row, dsr's default is auto: 30 / 12 = 2.5x, NOT met; at another size, said.
    bench::Row automatic = large(geo(deferred_row("large", 32, 12.0, 500, 500), LightGeometry::automatic, 600, 0), "32-large");
    rows.push_back(automatic);
    EXPECT_EQ(bench::geometry_goals(rows, "default", 3)[3],
              "dsr's default >= 3x faster than screen (LearnOpenGL's lighting pass) on 32-large: screen 30.00 ms / "
              "auto 12.00 ms = 2.50x (dsr's default geometry: auto; 800x600, the demo's size) -> NOT met");
    // With the light stages' ms and the floor's 1 ns a pixel, the estimate follows: the screen's
    // 28.8 ms less one pass's floor (0.48 ms) over 32 x 480000 evaluations is 1.84375 ns each;
    // auto's frame outside its light stage 2 ms, plus the floor 0.48, plus 3840000 ideal pairs at
    // that cost (7.08 ms) is 9.56 ms, 30 / 9.56 = 3.14x; auto's light stage 10 ms is 1.32x 7.56.
    rows[rows.size() - 2].lights_ms = 28.8;
    rows[rows.size() - 2].floor_light_ns = 1.0;
    rows.back().lights_ms = 10.0;
    rows.back().ideal_fragments = 3840000;
    const std::vector<std::string> e = bench::geometry_goals(rows, "default", 3);
    EXPECT_EQ(e[4], "  (information: the screen row's light stage 28.80 ms less 1 x its per-pixel floor (1.00 ns a "
                    "pixel: 0.48 ms) over 32 x 480000 evaluations is 1.84 ns each; the default row's frame outside its "
                    "light stage 2.00 ms plus one pass's floor (0.48 ms) plus 3840000 ideal pairs at that cost (7.08 "
                    "ms) is 9.56 ms, 3.14x faster than screen; the default row's light stage is 10.00 ms, 1.32x that "
                    "ideal's 7.56 ms)");
    EXPECT_EQ(e[5].rfind("  (information, withdrawn as a goal", 0), 0u) << e[5];
    rows.back().lights_ms.reset();
    rows[rows.size() - 2].w = 512, rows[rows.size() - 2].h = 512;
    EXPECT_NE(bench::geometry_goals(rows, "default", 3)[3].find("(dsr's default geometry: auto; 512x512, not the "
                                                                "demo's 800x600) -> NOT met"),
              std::string::npos);

    // auto against the fastest fixed geometry on each scene: own 1.05 / 1.00 met; 1024-overlap
    // 2.50 / tiles 2.00 = 1.25 NOT met; 32-large 12 / tiles 5 NOT met; 256 and 1024 without rows.
    bench::Row own_auto = geo(deferred_row("default", 3, 1.05, 100, 100), LightGeometry::automatic, 100, 0);
    bench::Row overlap_auto = geo(deferred_row("default-overlap", 1024, 2.5, 100, 100), LightGeometry::automatic, 100, 0);
    overlap_auto.lights_label = "1024-overlap";
    auto_chose(overlap_auto, 0, 0, 536);  // what it chose, said after the figure
    rows.insert(rows.end(), {own_auto, overlap_auto});
    const std::vector<std::string> a = bench::geometry_goals(rows, "default", 3);
    ASSERT_EQ(a.size(), 13u);
    EXPECT_EQ(a[7], "attenuation law's light stage <= 1.05 x the linear law's on the same pairs, 32-large: not "
                    "measured in this run (no linear-law row)");
    EXPECT_EQ(a[8], "auto <= 1.1 x the fastest fixed geometry (quad, volume, stencil, tiles), default at --lights own: "
                    "auto 1.05 ms / quad 1.00 ms = 1.05 -> met");
    EXPECT_NE(a[9].find("--lights 256: not measured in this run (no auto row)"), std::string::npos) << a[9];
    EXPECT_NE(a[10].find("--lights 1024: not measured in this run (no auto row)"), std::string::npos) << a[10];
    EXPECT_EQ(a[11], "auto <= 1.1 x the fastest fixed geometry (quad, volume, stencil, tiles), default at --lights "
                     "1024-overlap: auto 2.50 ms / tiles 2.00 ms = 1.25 (auto's lights: 0 by quads, 0 by volumes, "
                     "536 by the tiles) -> NOT met");
    EXPECT_EQ(a[12], "auto <= 1.1 x the fastest fixed geometry (quad, volume, stencil, tiles), default at --lights "
                     "32-large: auto 12.00 ms / tiles 5.00 ms = 2.40 -> NOT met");

    // With the rows' own rounds (Row::goal_rounds_ms) the goal is judged there, against the fastest
    // fixed row there (quad 1.90 here, though the tiles were faster in the rounds of every row), and
    // the rounds of every row's figure follows as information.
    std::vector<bench::Row> own = rows;
    bench::Row& oa = own[own.size() - 1];  // 1024-overlap's auto
    ASSERT_EQ(oa.light_geometry, LightGeometry::automatic);
    oa.goal_rounds_ms = 2.0, oa.goal_rounds_frames_ms = {2.0, 2.2, 1.9};
    own[3].goal_rounds_ms = 1.9, own[3].goal_rounds_frames_ms = {1.8, 2.0, 2.0};  // its quad
    own[4].goal_rounds_ms = 1.95, own[4].goal_rounds_frames_ms = {2.0, 1.9, 1.9};  // its tiles
    oa.frames_ms = {2.5, 2.4}, own[4].frames_ms = {2.0, 2.0};
    const std::vector<std::string> o = bench::geometry_goals(own, "default", 3);
    ASSERT_EQ(o.size(), 14u);
    EXPECT_EQ(o[11], "auto <= 1.1 x the fastest fixed geometry (quad, volume, stencil, tiles), default at --lights "
                     "1024-overlap: auto 2.00 ms / quad 1.90 ms = 1.05 (auto's lights: 0 by quads, 0 by volumes, "
                     "536 by the tiles), in 3 rounds of auto and the fixed geometries within 1.3x of the fastest alone "
                     "-> met; round by round 0.95-1.11, held in 2 of 3 rounds");
    EXPECT_EQ(o[12], "  (information: in the rounds of every row, auto 2.50 ms / tiles 2.00 ms = 1.25; round by round "
                     "1.20-1.25, held in 0 of 2 rounds)");
    // Slower there than in the rounds of every row: NOT met, as the figure of its own rounds says.
    own[3].goal_rounds_ms = 1.5;
    EXPECT_NE(bench::geometry_goals(own, "default", 3)[11].find("auto 2.00 ms / quad 1.50 ms = 1.33 (auto's"),
              std::string::npos);
    EXPECT_NE(bench::geometry_goals(own, "default", 3)[11].find("-> NOT met"), std::string::npos);
}

// The rows of the close goals' own rounds: auto's, then each fixed geometry's within 1.3x of the
// fastest fixed one's median, then dsr's default and its linear-law twin; none of goal auto's
// without an auto row or a fixed one; another scene's, another light count's and a row with a
// skip off never.
TEST(Bench, GoalRoundsTakeTheRowsTheCloseGoalsCompare) {
    auto row = [](LightGeometry g, double ms) {
        bench::Row r = deferred_row("default", 1024, ms, 100, 100);
        r.light_geometry = g;
        return r;
    };
    std::vector<bench::Row> rows = {row(LightGeometry::quad, 13.1), row(LightGeometry::volume, 12.9),
                                    row(LightGeometry::tiles, 10.0), row(LightGeometry::automatic, 30.0),
                                    row(LightGeometry::screen, 10.5), row(LightGeometry::stencil, 8.0)};
    rows.back().skip.empty_lights = false;  // not the default configuration: not a fixed row here
    rows.push_back(row(LightGeometry::volume, 5.0));
    rows.back().linear_law = true;
    rows.push_back(row(LightGeometry::quad, 5.0));
    rows.back().lights = 256;
    EXPECT_EQ(bench::goal_rounds_rows(rows, "default", 1024), (std::vector<size_t>{3, 1, 2}));  // 12.9 <= 13.0 < 13.1
    EXPECT_TRUE(bench::goal_rounds_rows(rows, "default", 256).empty());  // no auto row
    EXPECT_TRUE(bench::goal_rounds_rows(rows, "analytic", 1024).empty());
    const std::vector<bench::Row> only_auto = {row(LightGeometry::automatic, 1.0), row(LightGeometry::screen, 1.0)};
    EXPECT_TRUE(bench::goal_rounds_rows(only_auto, "default", 1024).empty());
    // Goal law's: dsr's default row and its linear-law twin join them, each row once.
    rows[6].light_geometry = LightGeometry::automatic;  // the linear-law row, now auto's twin
    EXPECT_EQ(bench::goal_rounds_rows(rows, "default", 1024), (std::vector<size_t>{3, 1, 2, 6}));
    // Without an auto row, quad is dsr's default: quad and its twin, though no goal auto runs.
    std::vector<bench::Row> quads = {row(LightGeometry::tiles, 1.0), row(LightGeometry::quad, 9.0),
                                     row(LightGeometry::quad, 8.0)};
    quads[2].linear_law = true;
    EXPECT_EQ(bench::goal_rounds_rows(quads, "default", 1024), (std::vector<size_t>{1, 2}));
}

// The law goal: dsr's default row on 32-large against its linear-law twin (the same lights with
// Equation 2's law at their radii), light stage against light stage; the linear-law rows are never
// dsr's default, and the other geometries' pairs follow as information.
TEST(Bench, LawGoalPricesTheAttenuationLawOnTheSamePairs) {
    auto large = [](LightGeometry g, double lights_ms, bool linear) {
        bench::Row r = deferred_row("large", 32, lights_ms + 2, 500, 500);
        r.lights_label = "32-large";
        r.light_geometry = g;
        r.lights_ms = lights_ms;
        r.linear_law = linear;
        return r;
    };
    const auto law_line = [](const std::vector<bench::Row>& rows) {
        for (const std::string& l : bench::geometry_goals(rows, "default", 3))
            if (l.rfind("attenuation law's", 0) == 0) return l;
        return std::string();
    };
    std::vector<bench::Row> rows = {large(LightGeometry::quad, 40, true), large(LightGeometry::quad, 42, false)};
    // The linear-law quad row comes first, yet dsr's default is the scene's own quad row.
    EXPECT_EQ(bench::find_default_row(rows, "large", 32), &rows[1]);
    EXPECT_EQ(bench::find_linear_law_row(rows, "large", 32, LightGeometry::quad), &rows[0]);
    EXPECT_EQ(law_line(rows), "attenuation law's light stage <= 1.05 x the linear law's on the same pairs, 32-large: "
                              "light stage, attenuation law / linear law, quad: 42.00 ms / 40.00 ms = 1.05 (500 ideal "
                              "pairs each) -> met");
    // With auto rows, auto's pair is judged (10.2 / 9.5 = 1.07: NOT met) and quad's is information.
    rows.push_back(large(LightGeometry::automatic, 10.2, false));
    EXPECT_EQ(law_line(rows), "attenuation law's light stage <= 1.05 x the linear law's on the same pairs, 32-large: "
                              "not measured in this run (no linear-law row)");
    rows.push_back(large(LightGeometry::automatic, 9.5, true));
    const std::vector<std::string> g = bench::geometry_goals(rows, "default", 3);
    const auto at = std::find(g.begin(), g.end(), law_line(rows));
    ASSERT_NE(at, g.end());
    EXPECT_EQ(*at, "attenuation law's light stage <= 1.05 x the linear law's on the same pairs, 32-large: light "
                   "stage, attenuation law / linear law, auto: 10.20 ms / 9.50 ms = 1.07 (500 ideal pairs each) -> NOT "
                   "met");
    ASSERT_NE(at + 1, g.end());
    EXPECT_EQ(*(at + 1), "  (information: the same for the other geometries: quad 42.00 ms / 40.00 ms = 1.05)");
    {
        // With the two rows' own rounds (Row::goal_rounds_lights_ms) the goal is judged there
        // (9.8 / 9.5 = 1.03: met) and the rounds of every row's figure is information.
        std::vector<bench::Row> own = rows;
        own[2].goal_rounds_lights_ms = 9.8, own[2].goal_rounds_lights_frames_ms = {9.8, 9.7, 10.5};
        own[3].goal_rounds_lights_ms = 9.5, own[3].goal_rounds_lights_frames_ms = {9.5, 9.5, 9.5};
        own[2].lights_frames_ms = {10.2, 10.0}, own[3].lights_frames_ms = {9.5, 9.5};
        const std::vector<std::string> o = bench::geometry_goals(own, "default", 3);
        const auto line = std::find(o.begin(), o.end(), law_line(own));
        ASSERT_NE(line, o.end());
        EXPECT_EQ(*line, "attenuation law's light stage <= 1.05 x the linear law's on the same pairs, 32-large: light "
                         "stage, attenuation law / linear law, auto: 9.80 ms / 9.50 ms = 1.03 (500 ideal pairs each), in "
                         "3 rounds of their own -> met; round by round 1.02-1.11, held in 2 of 3 rounds");
        ASSERT_NE(line + 1, o.end());
        EXPECT_EQ(*(line + 1), "  (information: in the rounds of every row, 10.20 ms / 9.50 ms = 1.07; round by round "
                               "1.05-1.07, held in 0 of 2 rounds)");
        // Only one of the two rows in them: the rounds of every row, as before.
        own[3].goal_rounds_lights_ms.reset();
        EXPECT_NE(law_line(own).find("10.20 ms / 9.50 ms = 1.07 (500 ideal pairs each) -> NOT met"), std::string::npos);
    }
    // The withdrawn goal's best deferred row is the scene's, not its faster linear-law twin (11.50 ms).
    bench::Row fwd = forward_row("large", 32, bench::Renderer::forward_single, 6.0);
    fwd.lights_label = "32-large";
    fwd.float_accum = false;
    rows.push_back(fwd);
    bool bound = false;
    for (const std::string& l : bench::geometry_goals(rows, "default", 3))
        if (l.rfind("  (information, withdrawn as a goal", 0) == 0) {
            bound = true;
            EXPECT_NE(l.find("deferred, auto light geometry 12.20 ms"), std::string::npos) << l;
            EXPECT_EQ(l.find("linear-law"), std::string::npos) << l;
        }
    EXPECT_TRUE(bound);
    rows.pop_back();
    // A linear-law row outside the default configuration is not the twin.
    rows.back().skip.depth_prepass = false;
    EXPECT_NE(law_line(rows).find("(no linear-law row)"), std::string::npos);
}

// Where the GL cannot count (no ARB_pipeline_statistics_query, no occlusion queries), the rows say
// null, the table "-", and the goal "not measured": never a 0 that reads as a perfect count.
TEST(Bench, MissingCountsAreNullNotZero) {
    bench::Row r = deferred_row("default", 3, 1.0, 100, 100);
    counts(r).fragments_counted = false;
    counts(r).invocations.reset();
    counts(r).evaluations.reset();
    const nlohmann::ordered_json j = bench::row_json(r);
    EXPECT_TRUE(j["frame"]["light_fragments"].is_null());
    EXPECT_TRUE(j["frame"]["light_invocations"].is_null());
    EXPECT_TRUE(j["fragments_ratio"].is_null());
    EXPECT_TRUE(j["invocations_ratio"].is_null());
    EXPECT_TRUE(j["frame"]["light_evaluations"].is_null());
    EXPECT_TRUE(j["evaluations_ratio"].is_null());
    EXPECT_TRUE(j["floor_ms"].is_null());
    EXPECT_EQ(j["ideal_fragments"], 100);
    r.gbuffer_bytes_per_pixel = 24;  // on every row, from the formats allocated
    EXPECT_EQ(bench::row_json(r)["gbuffer_bytes_per_pixel"], 24);
    const std::vector<std::string> c = bench::table_cells(r);
    EXPECT_EQ(c[6], "-");
    EXPECT_EQ(c[15], "-");
    EXPECT_EQ(c[16], "-");
    EXPECT_EQ(c[17], "-");
    const std::vector<std::string> g = bench::goals({r}, "default", 3);
    EXPECT_NE(g[0].find("default with 3 lights: not measured in this run (the GL lacks ARB_pipeline_statistics_query)"),
              std::string::npos)
        << g[0];
    EXPECT_EQ(g[1], "floor_ratio <= 1.5 at 1920x1080 with 1024 lights or on 32-large, default with 3 lights: not measured in this "
                    "run");  // no fragment line

    counts(r).invocations = 250;
    counts(r).evaluations = 500;
    const nlohmann::ordered_json k = bench::row_json(r);
    EXPECT_EQ(k["frame"]["light_invocations"], 250);
    EXPECT_DOUBLE_EQ(k["invocations_ratio"].get<double>(), 2.5);
    EXPECT_EQ(k["frame"]["light_evaluations"], 500);
    EXPECT_DOUBLE_EQ(k["evaluations_ratio"].get<double>(), 5.0);
    EXPECT_EQ(bench::table_cells(r)[15], "250");
    EXPECT_EQ(bench::table_cells(r)[16], "500");
    EXPECT_EQ(bench::table_cells(r)[17], "5.00");
    bench::Row f = forward_row("default", 3, bench::Renderer::forward_multi, 1.0);
    counts(f).invocations = 7;  // a forward row has no light passes: null whatever the frame holds
    EXPECT_TRUE(bench::row_json(f)["frame"].is_null());
    EXPECT_TRUE(bench::row_json(f)["invocations_ratio"].is_null());
    EXPECT_TRUE(bench::row_json(f)["accum"].is_null());
    f.float_accum = false;
    EXPECT_EQ(bench::row_json(f)["accum"], "rgba8");
    EXPECT_EQ(bench::config_text(f), "forward-multi rgba8");
}

// The floor's arithmetic on hand-made parts: floor_ms = (a) + ideal x (b) + (c) + (d).
TEST(Bench, FloorArithmetic) {
    bench::FloorParts p;
    p.fill_ms = 2.0;
    p.light_ns_per_fragment = 10.0;  // 100000 fragments: 1 ms
    p.post_ms = 0.5;
    p.output_ms = 0.25;
    ASSERT_TRUE(bench::floor_ms(p, 100000).has_value());
    EXPECT_DOUBLE_EQ(*bench::floor_ms(p, 100000), 3.75);
    EXPECT_DOUBLE_EQ(*bench::floor_ms(p, 0), 2.75);
    EXPECT_FALSE(bench::floor_ms(p, std::nullopt).has_value());
    EXPECT_DOUBLE_EQ(*bench::floor_ratio(7.0, 3.5), 2.0);
    EXPECT_FALSE(bench::floor_ratio(7.0, std::nullopt).has_value());
    EXPECT_FALSE(bench::floor_ratio(7.0, 0.0).has_value());
    // Post floor: off, 0; bloom at 1/2 with 7 taps on 64x64: 2 x (32x32 x 7) + 64x64 = 18432 reads;
    // anti-alias from the normal target: 64x64 x 18 = 73728; from both: 64x64 x 27.
    PostOptions post;
    EXPECT_EQ(bench::post_texel_reads(post, 64, 64), 0);
    EXPECT_EQ(bench::post_floor_ms(post, 64, 64, 10.0), 0.0);
    post.bloom = true;
    EXPECT_EQ(bench::post_texel_reads(post, 64, 64), 18432);
    EXPECT_DOUBLE_EQ(bench::post_floor_ms(post, 64, 64, 4.0), 18432e-6);  // a read costs (b) / 4 = 1 ns
    post.bloom = false, post.aa = true;
    EXPECT_EQ(bench::post_texel_reads(post, 64, 64), 64 * 64 * 18);
    post.aa_source = AaSource::both;
    EXPECT_EQ(bench::post_texel_reads(post, 64, 64), 64 * 64 * 27);
}

// The fair baseline: of the float and RGBA8 forms, the faster one.
TEST(Bench, FastestRowIsTheFasterForm) {
    bench::Row a = forward_row("default", 32, bench::Renderer::forward_multi, 9.0), b = forward_row("default", 32, bench::Renderer::forward_multi, 7.0);
    a.float_accum = true, b.float_accum = false;
    const std::vector<bench::Row> rows = {a, b, forward_row("default", 32, bench::Renderer::forward_single, 1.0)};
    ASSERT_NE(bench::fastest_row(rows, "default", 32, bench::Renderer::forward_multi), nullptr);
    EXPECT_EQ(bench::fastest_row(rows, "default", 32, bench::Renderer::forward_multi)->float_accum, false);  // rgba8
    EXPECT_EQ(bench::fastest_row(rows, "default", 256, bench::Renderer::forward_multi), nullptr);
}

// The JSON keys later tools read, with nulls where a value does not apply.
TEST(Bench, RowJsonHasEveryKeyAndNulls) {
    const nlohmann::ordered_json f = bench::row_json(forward_row("default", 3, bench::Renderer::forward_single, 2.0));
    const std::vector<std::string> keys = {
        "scene", "renderer", "accum", "depth", "encoding", "gbuffer", "gbuffer_bytes_per_pixel", "light_geometry", "tile_size", "tile_lights", "scissor", "skips_off", "linear_law",
        "lights", "lights_label", "size", "frames", "warmup_frames", "warmup_frames_ms", "ms_median", "ms_min", "ms_max", "frames_ms", "cpu_ms_median", "cpu_frames_ms",
        "cpu_alone_ms_median", "cpu_alone_frames_ms", "goal_rounds_ms_median", "goal_rounds_frames_ms", "goal_rounds_lights_ms_median",
        "goal_rounds_lights_frames_ms", "cpu_make_frame_ms", "cpu_lights_ms",
        "ideal_fragments", "fragments_ratio", "passes", "max_lsb", "mean_lsb",
        "psnr_db", "max_lsb_analytic", "mean_lsb_analytic", "psnr_db_analytic",
        "invocations_ratio", "evaluations_ratio", "ideal_source", "floor_fill_ms", "floor_light_ns",
        "floor_post_ms", "floor_output_ms", "floor_ms",
        "floor_ratio", "depth_copy_ms", "lights_ms", "lights_frames_ms", "max_lsb_vs_quad", "frame"};
    std::vector<std::string> got;
    for (auto it = f.begin(); it != f.end(); ++it) got.push_back(it.key());
    EXPECT_EQ(got, keys);
    EXPECT_TRUE(f["depth"].is_null());
    EXPECT_TRUE(f["fragments_ratio"].is_null());
    EXPECT_TRUE(f["ideal_fragments"].is_null());
    EXPECT_TRUE(f["psnr_db"].is_null());  // infinite: JSON has no inf
    EXPECT_TRUE(f["max_lsb_analytic"].is_null());
    EXPECT_TRUE(f["goal_rounds_ms_median"].is_null());
    EXPECT_TRUE(f["goal_rounds_lights_ms_median"].is_null());
    EXPECT_TRUE(f["frame"].is_null()) << "a forward row has no frame stats (FrameStatsJson tests the object)";
    EXPECT_EQ(f["passes"], 1);
    EXPECT_EQ(f["size"], nlohmann::ordered_json::array({64, 64}));

    bench::Row r = deferred_row("analytic", 2, 1.5, 120, 100);
    r.err_analytic = r.err;
    const nlohmann::ordered_json d = bench::row_json(r);
    EXPECT_EQ(d["depth"], "texture");
    EXPECT_TRUE(d["encoding"].is_null());
    EXPECT_EQ(d["frame"]["light_fragments"], 120);
    EXPECT_EQ(d["frame"]["scissor_pixels"], 360);
    EXPECT_EQ(d["frame"]["lights_drawn"], 2);
    EXPECT_DOUBLE_EQ(d["fragments_ratio"].get<double>(), 1.2);
    EXPECT_DOUBLE_EQ(d["max_lsb"].get<double>(), 3.0);
    EXPECT_DOUBLE_EQ(d["psnr_db_analytic"].get<double>(), 55.26);
    EXPECT_TRUE(d["passes"].is_null());
    EXPECT_FALSE(d["frame"].contains("auto"));  // not an auto row
    auto_chose(r, 3, 0, 536);
    EXPECT_EQ(bench::row_json(r)["frame"]["auto"]["lights"],
              nlohmann::ordered_json({{"quad", 3}, {"volume", 0}, {"tiles", 536}}));

    bench::Summary s;
    s.machine = "m";
    s.config.lights_text = "own";
    s.scenes = {"default"};
    s.rows = {r};
    std::vector<std::string> top;
    const nlohmann::ordered_json whole = bench::to_json(s);
    for (auto it = whole.begin(); it != whole.end(); ++it) top.push_back(it.key());
    EXPECT_EQ(top, (std::vector<std::string>{"machine", "gl_renderer", "gl_version", "config", "seconds", "goals",
                                             "invocation_probe", "notes", "skip_savings", "rows"}));
    EXPECT_TRUE(whole["invocation_probe"].is_null());  // not probed: null, never zeros
}

// The printed table: one column per header, "-" where a value does not apply, columns aligned.
TEST(Bench, TablesHaveOneCellPerColumn) {
    const std::vector<bench::Row> rows = {forward_row("default", 3, bench::Renderer::forward_single, 2.0),
                                          deferred_row("default", 3, 12.3456, 110, 100)};
    const std::vector<std::string> c = bench::table_cells(rows[1]);
    ASSERT_EQ(c.size(), bench::table_header().size());
    EXPECT_EQ(c[2], "deferred texture sc");
    EXPECT_EQ(c[4], "12.35");
    EXPECT_EQ(c[8], "1.10");
    EXPECT_EQ(c[9], "3");
    EXPECT_EQ(c[11], "55.3");
    EXPECT_EQ(c[12], "-");
    const std::vector<std::string> f = bench::table_cells(rows[0]);
    EXPECT_EQ(f[6], "-");
    EXPECT_EQ(f[11], "inf");
    EXPECT_EQ(bench::table_header().back(), "G-buf B/px");  // the G-buffer's bytes per pixel
    EXPECT_EQ(f.back(), "-");                                // forward rows have none

    const std::string md = bench::markdown_table(rows);
    EXPECT_EQ(md.rfind("| scene | lights | configuration | frames |", 0), 0u) << md;
    EXPECT_NE(md.find("\n| --- | ---: | --- |"), std::string::npos);
    EXPECT_NE(md.find("| default | 3 | deferred texture sc | 3 | 12.35 |"), std::string::npos) << md;
}

// The warm-up ends after `warmup` frames in a row that built no program and explored no path:
// auto's third frame may build the programs of a path it takes then, or it may explore a path first.
TEST(Bench, WarmUpLastsUntilFramesStopBuildingProgramsAndExploring) {
    auto run = [](std::vector<bench::WarmupFrame> seq, int warmup = 2, int extra = 4) {
        size_t i = 0;
        const int n = bench::warm_up(warmup, extra, [&] { return i < seq.size() ? seq[i++] : bench::WarmupFrame{}; });
        EXPECT_EQ(size_t(n), i);  // it ran as many as it says
        return n;
    };
    const bench::WarmupFrame b{true, false, false}, q{}, e{false, true, false}, slow{true, false, true};
    EXPECT_EQ(run({b, q, q}), 3);           // a fixed geometry: its programs in the first frame
    EXPECT_EQ(run({q, q}), 2);              // none to build: the minimum
    EXPECT_EQ(run({b, q, b, q, q}), 5);     // auto at 256 lights: two more in the third frame
    EXPECT_EQ(run({e, e, e, b, q, q}), 6);  // auto on 32-large: volumes explored, then the tiles built
    EXPECT_EQ(run({b, b, b, b, b, b, b}), 6);  // at most warmup + compile_warmup
    EXPECT_EQ(run({b, slow, q, q}), 2);     // a slow frame ends it
    EXPECT_EQ(run({b, q}, 1, 4), 2);        // --quick: one quiet frame
}

TEST(Bench, SlowFramesGetFewerTimedFrames) {
    EXPECT_EQ(bench::frames_for(10.0, 10), 10);
    EXPECT_EQ(bench::frames_for(2000.0, 10), 10);
    EXPECT_EQ(bench::frames_for(4000.0, 10), 5);   // 20 s of frames
    EXPECT_EQ(bench::frames_for(30000.0, 10), 3);  // at least 3
    EXPECT_EQ(bench::frames_for(4000.0, 4), 4);
}

// N-large's rows are timed with 3x the frames, unless --frames says how many; the other sets keep the sweep's.
TEST(Bench, LargeVariantsGetMoreFramesUnlessFramesIsGiven) {
    bench::Config cfg;
    cfg.lights = {-1, 32};
    cfg.light_sets = {LightSet::spread, LightSet::large};
    EXPECT_EQ(bench::variant_frames(cfg, LightSet::spread), 10);
    EXPECT_EQ(bench::variant_frames(cfg, LightSet::overlap), 10);
    EXPECT_EQ(bench::variant_frames(cfg, LightSet::large), 30);
    EXPECT_EQ(bench::large_frames_note(cfg), " (N-large 30)");
    cfg.frames = 7, cfg.frames_given = true;
    EXPECT_EQ(bench::variant_frames(cfg, LightSet::large), 7);
    EXPECT_EQ(bench::large_frames_note(cfg), "");
    cfg.frames_given = false, cfg.light_sets = {LightSet::spread, LightSet::spread};
    EXPECT_EQ(bench::large_frames_note(cfg), "") << "no N-large in the sweep";
}

// The independent ideal count, worked by hand. A 4x4 frame with p00 = p11 = 1 puts the pixel
// centres at x_ndc, y_ndc = +-0.25, +-0.75; a wall at eye depth 2 puts their points at x, y =
// +-0.5, +-1.5, z = -2. A light at (0, 0, -2): radius 1 holds the 4 points at |p|^2 = 0.5; radius
// 1.6 (2.56) also the 8 at 0.25 + 2.25 = 2.5; radius 2.2 (4.84) every point, corners (4.5) too.
TEST(Bench, IdealFromExactPointsByHand) {
    std::vector<double> depth(16, 2.0);
    depth[0] = 0.0;  // pixel (0, 0), the corner point (-1.5, -1.5): background
    const SurfacePoints s = surface_from_eye_depth(depth, 4, 4, {1.0, 1.0});
    EXPECT_EQ(s.p[5], glm::dvec3(-0.5, -0.5, -2.0));   // pixel (1, 1)
    EXPECT_EQ(s.p[15], glm::dvec3(1.5, 1.5, -2.0));    // pixel (3, 3)
    EXPECT_EQ(s.surface[0], 0);
    EXPECT_EQ(ideal_fragments(s, {{0, 0, -2, 1.0}}), 4);
    EXPECT_EQ(ideal_fragments(s, {{0, 0, -2, 1.6}}), 12);
    EXPECT_EQ(ideal_fragments(s, {{0, 0, -2, 2.2}}), 15);  // 16 less the background
    EXPECT_EQ(ideal_fragments(s, {{0, 0, -2, 1.6}, {0, 0, -2, 0.0}, {0, 0, -2, 1.0}}), 16);
    EXPECT_EQ(ideal_fragments(s, {{0, 0, -2, 2.2}}), ideal_fragments_brute(s, {{0, 0, -2, 2.2}}));

    // The same wall as 24-bit depth codes, near 1 and far 3: eye z -2 is window depth
    // (P22 z + P32) / -z * 0.5 + 0.5 with P22 = -2, P32 = -3: (4 - 3) / 2 * 0.5 + 0.5 = 0.75, code
    // round(0.75 x (2^24 - 1)) = 12582911 in the high 24 bits; 0xffffffff is the clear value.
    std::vector<uint32_t> codes(16, 12582911u << 8);
    codes[0] = 0xffffffffu;
    const SurfacePoints d = surface_from_depth_codes(codes, 4, 4, 1.0, 3.0, {1.0, 1.0});
    EXPECT_EQ(d.surface[0], 0);
    EXPECT_NEAR(d.p[5].z, -2.0, 1e-6);
    EXPECT_NEAR(d.p[5].x, -0.5, 1e-6);
    EXPECT_NEAR(d.p[15].y, 1.5, 1e-6);
    EXPECT_EQ(ideal_fragments(d, {{0, 0, -2, 1.6}}), 12);

    // Projection and lights in double: a 90-degree camera on a square frame has p00 = p11 = 1; a light
    // 2 in front of the camera is at eye (0, 0, -2); a light with no colour is left out.
    Scene scene;
    scene.camera.fov_deg = 90.0f;
    const glm::dvec2 p = projection_scale(scene.camera, 4, 4);
    EXPECT_NEAR(p.x, 1.0, 1e-12);
    EXPECT_NEAR(p.y, 1.0, 1e-12);
    EXPECT_NEAR(projection_scale(scene.camera, 8, 4).x, 0.5, 1e-12);
    scene.lights = {{{0, 0, 3}, {1, 1, 1}, 1.5f}, {{0, 0, 0}, {0, 0, 0}, 1.0f}};
    const std::vector<glm::dvec4> l = eye_lights(scene);
    ASSERT_EQ(l.size(), 1u);
    EXPECT_NEAR(l[0].z, -2.0, 1e-12);
    EXPECT_EQ(l[0].w, 1.5);
}

namespace {

// llvmpipe runs fragment shaders on 4x4 pixel blocks and counts every lane of a block a triangle
// touches (partly covered or scissored blocks included). The light quad (0,0)-(w,h) is drawn as
// GL_QUADS: two triangles split along the diagonal from (0, 0) to (w, h). Lanes counted inside
// rectangle r: 16 per (triangle, block) pair with a covered pixel in r. (For a square frame the
// tie rule on the diagonal changes nothing: every block on it holds pixels of both triangles.)
long long block_lanes(ScissorRect r, int w, int h) {
    std::set<std::pair<int, int>> below, above;
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
            const double side = (x + 0.5) * h - (y + 0.5) * w;
            (side >= 0 ? below : above).insert({x / 4, y / 4});
        }
    return 16 * (long long)(below.size() + above.size());
}

Scene floor_with_one_light(glm::vec3 light) {
    Scene s;
    s.camera.pos = {0, 4, 4};
    s.camera.target = {0, 0, 0};
    Material m;
    m.name = "m";
    s.materials.push_back(m);
    add_plane(s, 8.0f, {0, 0, 0}, 0);
    s.lights.push_back({light, {1, 1, 1}, 0.8f});
    return s;
}

}  // namespace

// light_invocations counts the fragments that entered the light shader, which a derivation can
// predict: with the scissor off and the light tests off, a 64x64 frame's light quad covers
// 256 blocks, and both triangles run the 16 blocks on its diagonal: 4096 + 256 lanes, while
// exactly 4096 samples pass. With the scissor and the sphere test on, the count is the lanes of
// the scissor rectangle, the sphere test's discards included (they entered the shader), while
// fewer samples pass than the rectangle holds. Without the extension (or the occlusion
// queries) the count is null, not 0.
TEST(Bench, LightInvocationsCountWhatEntersTheShader) {
    const int n = 64;
    const glm::vec3 light(1.2f, 0.3f, -1.0f);
    const Scene s = floor_with_one_light(light);
    ShaderOptions all_off;
    all_off.light_geometry = LightGeometry::quad;  // one pass per light, its scissor rectangle
    all_off.scissor = false;
    all_off.skip.light_depth_test = all_off.skip.light_sphere_test = false;
    const RenderResult a = render_scene(s, n, n, all_off);
    ASSERT_EQ(a.stats.lights.drawn, 1);
    ASSERT_TRUE(a.stats.lights.invocations.has_value()) << "this GL lacks ARB_pipeline_statistics_query";
    ASSERT_TRUE(a.stats.lights.counted_fragments().has_value());
    EXPECT_EQ(*a.stats.lights.counted_fragments(), n * n);
    EXPECT_EQ(block_lanes({0, 0, n, n}, n, n), n * n + 16 * 16);
    const bool llvmpipe = a.renderer.find("llvmpipe") != std::string::npos;
    if (llvmpipe) {
        EXPECT_EQ(*a.stats.lights.invocations, n * n + 16 * 16);
    } else {  // a GL that shades 2x2 quads or single pixels: between the pixels and the 4x4 lanes
        EXPECT_GE(*a.stats.lights.invocations, n * n);
        EXPECT_LE(*a.stats.lights.invocations, n * n + 16 * 16);
    }

    ShaderOptions defaults;  // scissor on, every skip on, the tutorial's quad
    defaults.light_geometry = LightGeometry::quad;
    const RenderResult b = render_scene(s, n, n, defaults);
    const glm::mat4 view = s.camera.view(), proj = s.camera.projection(1.0f);
    const ScissorRect r = light_scissor(glm::vec3(view * glm::vec4(light, 1.0f)), 0.8f, proj[0][0], proj[1][1],
                                        s.camera.near_plane, n, n);
    ASSERT_FALSE(r.empty());
    ASSERT_LT(r.area(), n * n / 4);  // a real rectangle, well inside the frame
    EXPECT_EQ(b.stats.lights.scissor_pixels, r.area());
    ASSERT_TRUE(b.stats.lights.invocations.has_value());
    if (llvmpipe) {
        EXPECT_EQ(*b.stats.lights.invocations, block_lanes(r, n, n)) << r.x0 << " " << r.y0 << " " << r.x1 << " " << r.y1;
    }
    EXPECT_GE(*b.stats.lights.invocations, r.area());
    EXPECT_GT(b.stats.lights.fragments, 0);
    EXPECT_LT(b.stats.lights.fragments, r.area());  // the sphere test discarded some of them
    std::printf("[ stats    ] rectangle %lld pixels, %lld invocations, %lld passed\n", r.area(),
                *b.stats.lights.invocations, b.stats.lights.fragments);

    const RenderResult c = render_scene(s, n, n, defaults, {"no-pipeline-stats"});
    EXPECT_FALSE(c.stats.lights.invocations.has_value());
    EXPECT_EQ(c.stats.lights.counted_fragments(), b.stats.lights.counted_fragments());
    const RenderResult d = render_scene(s, n, n, defaults, {"no-occlusion-query"});
    EXPECT_FALSE(d.stats.lights.counted_fragments().has_value());
    EXPECT_EQ(d.stats.lights.invocations, b.stats.lights.invocations);
}

// One ideal count (ideal_fragments.h ideal_count) for `dsr bench`, `render --stats` and the
// viewer's panel, by each light's volume: on a floor lit by a point light and a narrow spot light,
// the three count the same pixels from the same depth codes; the count is the brute-force count
// over the volumes and agrees with light_volume.h's own membership test; and the spot counts only
// its cone, well below its sphere (the sphere-only count the render and viewer paths once made).
TEST(Bench, OneIdealCountForSpotLights) {
    const int w = 96, h = 72;
    Scene s = floor_with_one_light({1.2f, 0.3f, -1.0f});
    Light spot;
    spot.type = Light::Type::spot;
    spot.pos = {-1.0f, 1.5f, 0.5f};
    spot.dir = glm::normalize(glm::vec3(0.2f, -1.0f, -0.3f));
    spot.radius = 3.0f;
    spot.angle_deg = 25.0f;
    spot.color = {1.0f, 0.9f, 0.8f};
    s.lights.push_back(spot);
    Light dark = spot;  // no colour: no fragment
    dark.pos.x = 1.0f;
    dark.color = glm::vec3(0.0f);
    s.lights.push_back(dark);

    auto ctx = create_context(ContextDesc{"osmesa", w, h});
    const Caps caps = probe_caps({});
    DeferredShader ds(caps, w, h, ShaderOptions{}, resource_dir("glsl120"));
    ds.set_scene(s);
    ds.render(s, w, h);
    const std::vector<uint32_t> codes = ds.read_gbuffer_depth_codes();

    const FrameIdeal stats = frame_ideal_fragments(ds, s);                           // render --stats
    const bench::IdealCount bench_count = bench::ideal_from_depth_codes(s, w, h, codes);  // dsr bench, depth24
    const long long viewer = ideal_count_from_depth_codes(codes, w, h, s.camera, s.lights);  // the viewer's panel
    ASSERT_TRUE(stats.fragments.has_value());
    ASSERT_TRUE(bench_count.fragments.has_value());
    EXPECT_EQ(stats.source, "depth24");
    EXPECT_EQ(bench_count.source, std::string("depth24"));
    EXPECT_EQ(*stats.fragments, *bench_count.fragments);
    EXPECT_EQ(viewer, *stats.fragments);

    // The definition: every (light, pixel) pair tested, in eye space; and light_volume.h's
    // inside_volume on the same points taken back to world space (rounding of the inverse view
    // may move a pixel on a boundary).
    const SurfacePoints pts = surface_from_depth_codes(codes, w, h, s.camera.near_plane, s.camera.far_plane,
                                                       projection_scale(s.camera, w, h));
    EXPECT_EQ(viewer, ideal_fragments_brute(pts, eye_volumes(s)));
    const glm::dmat4 to_world = glm::inverse(s.camera.view_d());
    long long world = 0;
    for (size_t i = 0; i < pts.p.size(); ++i)
        for (const Light& l : s.lights)
            world += pts.surface[i] && l.color != glm::vec3(0.0f) &&
                     inside_volume(light_volume(l), glm::dvec3(to_world * glm::dvec4(pts.p[i], 1.0)));
    EXPECT_NEAR(double(world), double(viewer), 2.0);

    // The spot lights part of the floor, and only the part inside its cone.
    const long long spot_alone = ideal_count(pts, {spot}, s.camera.view_d());
    const long long spot_sphere = ideal_fragments(pts, {glm::dvec4(glm::dvec3(s.camera.to_eye(spot.pos)), 3.0)});
    const long long point_alone = ideal_count(pts, {s.lights[0]}, s.camera.view_d());
    std::printf("[ stats    ] ideal: %lld (point %lld + spot %lld; the spot's sphere would hold %lld)\n", viewer,
                point_alone, spot_alone, spot_sphere);
    EXPECT_GT(spot_alone, 50);
    EXPECT_LT(2 * spot_alone, spot_sphere);
    EXPECT_EQ(viewer, point_alone + spot_alone);

    // The bench's other source, exact eye depth from the analytic trace, counts the same volumes:
    // equal but for pixels whose 24-bit depth puts them on the other side of a boundary.
    const bench::IdealCount traced = bench::ideal_from_eye_depth(s, w, h, analytic_trace(s, w, h).eye_depth);
    ASSERT_TRUE(traced.fragments.has_value());
    EXPECT_EQ(traced.source, std::string("analytic"));
    EXPECT_NEAR(double(*traced.fragments), double(viewer), 2.0 + double(viewer) / 200.0);
}
