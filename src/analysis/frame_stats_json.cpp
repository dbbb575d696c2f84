#include "analysis/frame_stats_json.h"

#include "deferred/auto_policy.h"
#include "dsr_clock.h"

namespace dsr {

namespace {

using json = nlohmann::ordered_json;

template <class T>
json opt(const std::optional<T>& v) {
    return v ? json(*v) : json(nullptr);
}

json measured(double ms) { return ms >= 0 ? json(ms) : json(nullptr); }

template <class T>
json per_path(const std::array<T, kLightPaths>& v) {
    json j;
    for (LightPath p : kAllLightPaths) j[light_path_name(p)] = v[at(p)];
    return j;
}

// Adds b's keys to a, in b's order.
void put(json& a, const json& b) {
    for (auto it = b.begin(); it != b.end(); ++it) a[it.key()] = it.value();
}

}  // namespace

json to_json(const LightCounts& c) {
    return {{"lights_total", c.total},       {"lights_culled", c.culled},
            {"lights_drawn", c.drawn},       {"light_fragments", opt(c.counted_fragments())},
            {"light_invocations", opt(c.invocations)}, {"light_evaluations", opt(c.evaluations)},
            {"scissor_pixels", c.scissor_pixels},      {"light_passes", c.passes},
            {"lights_as_quads", c.as_quads}};
}

json to_json(const TileStats& t) {
    return {{"vertex_fetch_batches", t.vertex_batches}, {"tile_light_pairs", t.light_pairs},
            {"shared_attenuation_batches", t.att_shared_batches}, {"depth_culling", t.depth},
            {"depth_ms", t.depth_ms}, {"plan_ms", t.plan_ms},
            {"cpu_ms", {{"spans", t.spans_cpu_ms}, {"wait", t.wait_cpu_ms}, {"cull", t.cull_cpu_ms},
                        {"plan", t.plan_cpu_ms}, {"upload", t.upload_cpu_ms}}},
            {"wait_ms", t.wait_ms}, {"gpu_spans_ms", measured(t.gpu_spans_ms)},
            {"gpu_wait_ms", measured(t.gpu_wait_ms)}, {"gpu_shade_ms", measured(t.gpu_shade_ms)}};
}

json to_json(const AutoStats& a) {
    return {{"lights", per_path(a.lights)},
            {"depth_spans", a.spans},
            {"quads_against_depth", a.quad_depth},
            {"handoff_ms", a.handoff_ms},
            {"kept", a.kept},
            {"explored", a.explored ? json(light_path_name(*a.explored)) : json(nullptr)},
            {"predicted_lights_ms", a.predicted_ms},
            {"scale", per_path(a.scale)}};
}

json to_json(const ShadowCounts& s) {
    return {{"shadow_maps", s.maps}, {"shadow_triangles", s.triangles}, {"shadow_atlas_texels", s.atlas_texels}};
}

json to_json(const ForwardCounts& f) {
    return {{"light_markers", f.light_markers}, {"transparent_objects", f.transparent_objects},
            {"transparent_passes", f.transparent_passes}};
}

json to_json(const PassesRun& p) {
    return {{"depth_prepass", p.depth_prepass},
            {"ambient_in_material", p.ambient_in_material()},
            {"ambient_folded", p.ambient_folded()},
            {"ambient_in_handoff", p.ambient_in_handoff()},
            {"ambient_writer", ambient_writer_name(p.ambient)},
            {"final", p.final},
            {"depth_complexity", opt(p.depth_complexity)}};
}

json to_json(const StageTimes& t) {
    return {{"geometry", t.geometry}, {"ambient", t.ambient},   {"lights", t.lights},
            {"bloom", t.bloom},       {"aa", t.aa},             {"final", t.final},
            {"depth_copy", t.depth_copy}, {"ssao", t.ssao},     {"forward", t.forward},
            {"shadows", t.shadows},   {"cpu", t.cpu},           {"cpu_make_frame", t.cpu_make_frame},
            {"cpu_lights", t.cpu_lights}, {"frame", t.frame}};
}

json frame_stats_json(const FrameStats& s) {
    json j = to_json(s.lights);
    put(j, to_json(s.forward));
    put(j, to_json(s.shadows));
    j["passes"] = to_json(s.passes);
    if (s.tiles.on) j["tiles"] = to_json(s.tiles);
    if (s.auto_geometry.on) j["auto"] = to_json(s.auto_geometry);
    j["timing"] = timing_name(s.timing);
    j["ms"] = to_json(s.ms);
    return j;
}

FrameStats reported_frame(const std::vector<FrameStats>& timed, const FrameStats& counted) {
    FrameStats r = counted;
    if (timed.empty()) return r;
    auto med = [&](auto get) {
        std::vector<double> v;
        for (const FrameStats& s : timed) v.push_back(get(s));
        return median(v);
    };
    auto med_measured = [&](auto get) {
        std::vector<double> v;
        for (const FrameStats& s : timed)
            if (get(s) >= 0) v.push_back(get(s));
        return v.empty() ? -1.0 : median(v);
    };
    StageTimes& m = r.ms;
    for (double StageTimes::*f : {&StageTimes::geometry, &StageTimes::ambient, &StageTimes::lights, &StageTimes::bloom,
                                  &StageTimes::aa, &StageTimes::final, &StageTimes::frame, &StageTimes::ssao,
                                  &StageTimes::depth_copy, &StageTimes::forward, &StageTimes::shadows, &StageTimes::cpu,
                                  &StageTimes::cpu_make_frame, &StageTimes::cpu_lights})
        m.*f = med([&](const FrameStats& s) { return s.ms.*f; });
    for (double TileStats::*f : {&TileStats::depth_ms, &TileStats::plan_ms, &TileStats::spans_cpu_ms, &TileStats::wait_cpu_ms,
                                 &TileStats::cull_cpu_ms, &TileStats::plan_cpu_ms, &TileStats::upload_cpu_ms,
                                 &TileStats::wait_ms})
        r.tiles.*f = med([&](const FrameStats& s) { return s.tiles.*f; });
    r.tiles.gpu_spans_ms = med_measured([](const FrameStats& s) { return s.tiles.gpu_spans_ms; });
    r.tiles.gpu_wait_ms = med_measured([](const FrameStats& s) { return s.tiles.gpu_wait_ms; });
    r.tiles.gpu_shade_ms = med_measured([](const FrameStats& s) { return s.tiles.gpu_shade_ms; });
    r.auto_geometry.predicted_ms = med([](const FrameStats& s) { return s.auto_geometry.predicted_ms; });
    return r;
}

}  // namespace dsr
