// The one JSON form of a frame's stats (analysis/frame_stats_json.h): every field of every part
// reaches it, the bench's rows and `render --stats` write the same object, and a real
// `render --stats` file holds every key of it.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/bench_report.h"
#include "analysis/bench_run.h"
#include "analysis/frame_stats_json.h"
#include "cli_fixture.h"

using namespace dsr;
using json = nlohmann::ordered_json;

namespace {

// One change to each field of each part, away from its default.
std::vector<std::pair<std::string, std::function<void(FrameStats&)>>> field_changes() {
    using S = FrameStats&;
    return {
        {"lights.total", [](S s) { s.lights.total = 7; }},
        {"lights.culled", [](S s) { s.lights.culled = 2; }},
        {"lights.drawn", [](S s) { s.lights.drawn = 5; }},
        {"lights.fragments", [](S s) { s.lights.fragments = 1234, s.lights.fragments_counted = true; }},
        {"lights.fragments_counted", [](S s) { s.lights.fragments_counted = true; }},
        {"lights.invocations", [](S s) { s.lights.invocations = 4321; }},
        {"lights.evaluations", [](S s) { s.lights.evaluations = 9999; }},
        {"lights.scissor_pixels", [](S s) { s.lights.scissor_pixels = 640; }},
        {"lights.passes", [](S s) { s.lights.passes = 3; }},
        {"lights.as_quads", [](S s) { s.lights.as_quads = 1; }},
        {"tiles.light_pairs", [](S s) { s.tiles.light_pairs = 77; }},
        {"tiles.att_shared_batches", [](S s) { s.tiles.att_shared_batches = 4; }},
        {"tiles.vertex_batches", [](S s) { s.tiles.vertex_batches = 6; }},
        {"tiles.depth", [](S s) { s.tiles.depth = true; }},
        {"tiles.depth_ms", [](S s) { s.tiles.depth_ms = 0.5; }},
        {"tiles.plan_ms", [](S s) { s.tiles.plan_ms = 0.25; }},
        {"tiles.spans_cpu_ms", [](S s) { s.tiles.spans_cpu_ms = 0.125; }},
        {"tiles.wait_cpu_ms", [](S s) { s.tiles.wait_cpu_ms = 0.375; }},
        {"tiles.cull_cpu_ms", [](S s) { s.tiles.cull_cpu_ms = 0.0625; }},
        {"tiles.plan_cpu_ms", [](S s) { s.tiles.plan_cpu_ms = 0.1875; }},
        {"tiles.upload_cpu_ms", [](S s) { s.tiles.upload_cpu_ms = 0.3125; }},
        {"tiles.wait_ms", [](S s) { s.tiles.wait_ms = 0.75; }},
        {"tiles.gpu_spans_ms", [](S s) { s.tiles.gpu_spans_ms = 1.5; }},
        {"tiles.gpu_wait_ms", [](S s) { s.tiles.gpu_wait_ms = 2.5; }},
        {"tiles.gpu_shade_ms", [](S s) { s.tiles.gpu_shade_ms = 3.5; }},
        {"auto.lights[quad]", [](S s) { s.auto_geometry.lights[at(LightPath::quad)] = 1; }},
        {"auto.lights[volume]", [](S s) { s.auto_geometry.lights[at(LightPath::volume)] = 2; }},
        {"auto.lights[tiles]", [](S s) { s.auto_geometry.lights[at(LightPath::tiles)] = 3; }},
        {"auto.predicted_ms", [](S s) { s.auto_geometry.predicted_ms = 4.5; }},
        {"auto.handoff_ms", [](S s) { s.auto_geometry.handoff_ms = 0.125; }},
        {"auto.spans", [](S s) { s.auto_geometry.spans = true; }},
        {"auto.quad_depth", [](S s) { s.auto_geometry.quad_depth = true; }},
        {"auto.kept", [](S s) { s.auto_geometry.kept = true; }},
        {"auto.explored", [](S s) { s.auto_geometry.explored = LightPath::volume; }},
        {"auto.scale[quad]", [](S s) { s.auto_geometry.scale[at(LightPath::quad)] = 1.25; }},
        {"auto.scale[volume]", [](S s) { s.auto_geometry.scale[at(LightPath::volume)] = 0.75; }},
        {"auto.scale[tiles]", [](S s) { s.auto_geometry.scale[at(LightPath::tiles)] = 2.0; }},
        {"shadows.maps", [](S s) { s.shadows.maps = 6; }},
        {"shadows.triangles", [](S s) { s.shadows.triangles = 600; }},
        {"shadows.atlas_texels", [](S s) { s.shadows.atlas_texels = 4096; }},
        {"forward.light_markers", [](S s) { s.forward.light_markers = 2; }},
        {"forward.transparent_objects", [](S s) { s.forward.transparent_objects = 3; }},
        {"forward.transparent_passes", [](S s) { s.forward.transparent_passes = 4; }},
        {"passes.depth_prepass", [](S s) { s.passes.depth_prepass = false; }},
        {"passes.final", [](S s) { s.passes.final = false; }},
        {"passes.ambient", [](S s) { s.passes.ambient = AmbientWriter::light_fold; }},
        {"passes.depth_complexity", [](S s) { s.passes.depth_complexity = 1.75; }},
        {"timing", [](S s) { s.timing = TimingSource::gpu_timer; }},
        {"ms.geometry", [](S s) { s.ms.geometry = 1; }},
        {"ms.ambient", [](S s) { s.ms.ambient = 2; }},
        {"ms.lights", [](S s) { s.ms.lights = 3; }},
        {"ms.bloom", [](S s) { s.ms.bloom = 4; }},
        {"ms.aa", [](S s) { s.ms.aa = 5; }},
        {"ms.final", [](S s) { s.ms.final = 6; }},
        {"ms.frame", [](S s) { s.ms.frame = 7; }},
        {"ms.ssao", [](S s) { s.ms.ssao = 8; }},
        {"ms.depth_copy", [](S s) { s.ms.depth_copy = 9; }},
        {"ms.forward", [](S s) { s.ms.forward = 10; }},
        {"ms.shadows", [](S s) { s.ms.shadows = 11; }},
        {"ms.cpu", [](S s) { s.ms.cpu = 12; }},
        {"ms.cpu_make_frame", [](S s) { s.ms.cpu_make_frame = 13; }},
        {"ms.cpu_lights", [](S s) { s.ms.cpu_lights = 14; }},
    };
}

FrameStats with_tiles_and_auto() {
    FrameStats s;
    s.tiles.on = true;
    s.auto_geometry.on = true;
    return s;
}

FrameStats every_field_changed() {
    FrameStats s = with_tiles_and_auto();
    for (const auto& [name, change] : field_changes()) change(s);
    return s;
}

// Every key of `want`, at every depth, is in `got`.
void expect_keys(const json& want, const nlohmann::json& got, const std::string& where) {
    for (auto it = want.begin(); it != want.end(); ++it) {
        ASSERT_TRUE(got.contains(it.key())) << where << it.key() << " missing";
        if (it.value().is_object()) expect_keys(it.value(), got[it.key()], where + it.key() + ".");
    }
}

}  // namespace

// A field that a change does not show in the JSON was dropped from it.
TEST(FrameStatsJson, EveryFieldOfEveryPartReachesIt) {
    const json base = frame_stats_json(with_tiles_and_auto());
    for (const auto& [name, change] : field_changes()) {
        FrameStats s = with_tiles_and_auto();
        change(s);
        EXPECT_NE(frame_stats_json(s), base) << name << " is not in the JSON";
    }
    // `tiles` and `auto` are there exactly where the frame's geometry draws them.
    const json none = frame_stats_json(FrameStats{});
    EXPECT_FALSE(none.contains("tiles"));
    EXPECT_FALSE(none.contains("auto"));
    EXPECT_TRUE(base.contains("tiles"));
    EXPECT_TRUE(base.contains("auto"));
}

// The keys and values `render --stats` has always written for these fields.
TEST(FrameStatsJson, EachPartWritesItsKeys) {
    const FrameStats s = every_field_changed();
    const json j = frame_stats_json(s);
    EXPECT_EQ(j["lights_total"], 7);
    EXPECT_EQ(j["lights_culled"], 2);
    EXPECT_EQ(j["lights_drawn"], 5);
    EXPECT_EQ(j["light_fragments"], 1234);
    EXPECT_EQ(j["light_invocations"], 4321);
    EXPECT_EQ(j["light_evaluations"], 9999);
    EXPECT_EQ(j["scissor_pixels"], 640);
    EXPECT_EQ(j["light_passes"], 3);
    EXPECT_EQ(j["lights_as_quads"], 1);
    EXPECT_EQ(j["light_markers"], 2);
    EXPECT_EQ(j["transparent_objects"], 3);
    EXPECT_EQ(j["transparent_passes"], 4);
    EXPECT_EQ(j["shadow_maps"], 6);
    EXPECT_EQ(j["shadow_triangles"], 600);
    EXPECT_EQ(j["shadow_atlas_texels"], 4096);
    EXPECT_EQ(j["passes"], json({{"depth_prepass", false}, {"ambient_in_material", false}, {"ambient_folded", true},
                                 {"ambient_in_handoff", false}, {"ambient_writer", "light-fold"}, {"final", false},
                                 {"depth_complexity", 1.75}}));
    EXPECT_EQ(j["tiles"], json({{"vertex_fetch_batches", 6}, {"tile_light_pairs", 77}, {"shared_attenuation_batches", 4},
                                {"depth_culling", true}, {"depth_ms", 0.5}, {"plan_ms", 0.25},
                                {"cpu_ms", {{"spans", 0.125}, {"wait", 0.375}, {"cull", 0.0625}, {"plan", 0.1875},
                                            {"upload", 0.3125}}},
                                {"wait_ms", 0.75}, {"gpu_spans_ms", 1.5},
                                {"gpu_wait_ms", 2.5}, {"gpu_shade_ms", 3.5}}));
    EXPECT_EQ(j["auto"]["lights"], json({{"quad", 1}, {"volume", 2}, {"tiles", 3}}));
    EXPECT_EQ(j["auto"]["scale"], json({{"quad", 1.25}, {"volume", 0.75}, {"tiles", 2.0}}));
    EXPECT_EQ(j["auto"]["explored"], "volume");
    EXPECT_EQ(j["timing"], "gpu-timer");
    EXPECT_EQ(j["ms"]["cpu_lights"], 14);
    EXPECT_EQ(j["ms"].size(), 14u);
    // Not counted: null, never 0.
    const json none = frame_stats_json(FrameStats{});
    EXPECT_TRUE(none["light_fragments"].is_null());
    EXPECT_TRUE(none["light_invocations"].is_null());
    EXPECT_TRUE(none["passes"]["depth_complexity"].is_null());
    EXPECT_TRUE(frame_stats_json(with_tiles_and_auto())["tiles"]["gpu_spans_ms"].is_null()) << "-1: not measured";
}

// A bench row's `frame` is the object `render --stats` writes for the same frame: one frame
// timed and counted, its medians are its own values.
TEST(FrameStatsJson, BenchRowAndRenderWriteTheSameObject) {
    const FrameStats s = every_field_changed();
    bench::Row row;
    row.frame = s;
    const json render_frame = frame_stats_json(reported_frame({s}, s));
    EXPECT_EQ(bench::row_json(row)["frame"], render_frame);
    EXPECT_EQ(render_frame, frame_stats_json(s));
    EXPECT_TRUE(bench::row_json(bench::Row{})["frame"].is_null()) << "a row with no counted frame";
}

// The timed frames' medians replace the counted frame's times; its counts stay.
TEST(FrameStatsJson, ReportedFrameTakesTheTimedFramesMedians) {
    FrameStats a = with_tiles_and_auto(), b = a, c = a, counted = a;
    a.ms.lights = 1, b.ms.lights = 5, c.ms.lights = 3, counted.ms.lights = 100;
    a.tiles.gpu_shade_ms = -1, b.tiles.gpu_shade_ms = 4, c.tiles.gpu_shade_ms = 6;
    a.auto_geometry.predicted_ms = 2, b.auto_geometry.predicted_ms = 2, c.auto_geometry.predicted_ms = 9;
    a.tiles.plan_cpu_ms = 0.5, b.tiles.plan_cpu_ms = 0.1, c.tiles.plan_cpu_ms = 0.2, counted.tiles.plan_cpu_ms = 7;
    a.tiles.wait_ms = 3, b.tiles.wait_ms = 1, c.tiles.wait_ms = 2, counted.tiles.wait_ms = 9;
    counted.lights.drawn = 12;
    const FrameStats r = reported_frame({a, b, c}, counted);
    EXPECT_EQ(r.ms.lights, 3);
    EXPECT_EQ(r.tiles.gpu_shade_ms, 5) << "the median of the frames that measured it";
    EXPECT_EQ(r.tiles.gpu_spans_ms, -1) << "none measured it";
    EXPECT_EQ(r.auto_geometry.predicted_ms, 2);
    EXPECT_EQ(r.tiles.plan_cpu_ms, 0.2) << "the tiles' CPU by step, medians too";
    EXPECT_EQ(r.tiles.wait_ms, 2);
    EXPECT_EQ(r.lights.drawn, 12);
}

// A real `render --stats` file holds every key of the frame's object, `tiles` and `auto` included.
TEST(FrameStatsJson, RenderStatsHoldsEveryKey) {
    const std::string dir = test::temp_dir();
    const test::RunResult r = test::run("render --size 64x64 --frames 2 --light-geometry auto -o " + dir +
                                        "/a.png --stats " + dir + "/a.json");
    ASSERT_EQ(r.status, 0) << r.output;
    std::ifstream in(dir + "/a.json");
    const nlohmann::json got = nlohmann::json::parse(in);
    expect_keys(frame_stats_json(every_field_changed()), got, "");
}
