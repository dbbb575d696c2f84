// `dsr bench` and its parts: the ideal fragment count against brute force, positions rebuilt
// from depth, the generated N-light scenes, the plot, and the command's JSON as later tools read it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "analysis/bench_scenes.h"
#include "analysis/ideal_fragments.h"
#include "analysis/plot.h"
#include "cli_fixture.h"
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

}  // namespace

// The tiled count skips (light, tile) pairs by bounding boxes; it must never skip a pixel the
// definition counts. Odd sizes leave partial tiles at the right and top edges.
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
    ASSERT_EQ(a.meshes.size(), s.meshes.size());
    float lo_y = 1e9f, lo_x = 1e9f, hi_x = -1e9f;
    for (const Mesh& m : s.meshes)
        for (const Vertex& v : m.vertices) lo_y = std::min(lo_y, v.pos.y), lo_x = std::min(lo_x, v.pos.x), hi_x = std::max(hi_x, v.pos.x);
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
    s.points = {{2.0, 0.5, 4}, {300.0, 5.0, 4}, {10.0, 0.0, 4}};
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
    EXPECT_NE(r.output.find("light frags"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("goals"), std::string::npos);
    ASSERT_TRUE(exists(d + "/r.md"));
    ASSERT_TRUE(exists(d + "/r_plot.png"));
    std::ifstream in(d + "/b.json");
    nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_TRUE(j["machine"].is_string());
    EXPECT_TRUE(j["gl_renderer"].is_string());
    ASSERT_TRUE(j["rows"].is_array());
    EXPECT_GE(j["rows"].size(), 2u * 2u * 12u);  // 2 scenes x 2 light counts x at least 12 configurations
    int deferred = 0, forward = 0, analytic = 0;
    for (auto& row : j["rows"]) {
        for (const char* k : {"renderer", "depth", "scissor", "lights", "size", "ms_median", "ms_min", "ms_max",
                              "light_fragments", "ideal_fragments", "max_lsb", "mean_lsb", "psnr_db"})
            ASSERT_TRUE(row.contains(k)) << k;
        EXPECT_EQ(row["size"], nlohmann::json::array({64, 64}));
        EXPECT_TRUE(row["scissor"].is_boolean());
        EXPECT_LE(row["ms_min"].get<double>(), row["ms_median"].get<double>());
        EXPECT_LE(row["ms_median"].get<double>(), row["ms_max"].get<double>());
        const std::string kind = row["renderer"];
        if (kind == "deferred") {
            ++deferred;
            EXPECT_TRUE(row["depth"] == "texture" || row["depth"] == "packed");
            const long long frags = row["light_fragments"], ideal = row["ideal_fragments"];
            EXPECT_GT(ideal, 0);
            // With the depth texture nothing inside a sphere is rejected (scissor rectangles and the
            // light depth test are conservative), so the ideal count cannot exceed what was shaded.
            if (row["depth"] == "texture") {
                EXPECT_GE(frags, ideal) << row.dump();
            }
        } else {
            ++forward;
            EXPECT_TRUE(kind == "forward-single" || kind == "forward-multi") << kind;
            EXPECT_TRUE(row["light_fragments"].is_null());
            EXPECT_TRUE(row["ideal_fragments"].is_null());
            if (kind == "forward-single") {
                EXPECT_EQ(row["max_lsb"].get<double>(), 0.0);  // it is the reference
            }
        }
        if (row["scene"] == "analytic") {
            ++analytic;
            EXPECT_TRUE(row["max_lsb_analytic"].is_number());
        }
    }
    EXPECT_EQ(forward, 2 * 2 * 2);
    EXPECT_GE(deferred, 2 * 2 * 10);
    EXPECT_GT(analytic, 0);
}

TEST(Bench, BadFlagsAreOneClearError) {
    for (const char* args : {"bench --frobnicate", "bench --lights 3,x", "bench --json out.txt", "bench --size 0x3"}) {
        RunResult r = run(args);
        EXPECT_NE(r.status, 0) << args;
        EXPECT_EQ(r.output.rfind("dsr bench: ", 0), 0u) << args << ": " << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    }
}
