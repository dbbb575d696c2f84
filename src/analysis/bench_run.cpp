// The benchmark's runner (bench_run.h): builds every row's renderer, warms up, times the frames
// interleaved across rows, counts the ideal fragments and compares each image with the references.
// Runner::run_scene calls one function per job, in that order.
#include "analysis/bench_run.h"

#include <unistd.h>

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <tuple>

#include "dsr_clock.h"
#include "analysis/analytic_reference.h"
#include "analysis/bench_floor.h"
#include "analysis/bench_goals.h"
#include "analysis/bench_scenes.h"
#include "analysis/ideal_fragments.h"
#include "deferred/deferred_shader.h"
#include "deferred/option_table.h"
#include "forward/forward_renderer.h"
#include "gl/program.h"
#include "gl/readback.h"

namespace dsr::bench {

namespace {

constexpr double kSlowFrameMs = 2000;   // above this, fewer frames (see frames_for)
constexpr double kSlowRowBudgetMs = 20000;

// What every job of one scene variant reads: the sweep, the GL and the shaders.
struct Setup {
    const Config& cfg;
    const Caps& caps;
    const std::string& shaders;
};

// Everything one scene variant (scene, light count, size) shares across its rows.
struct Variant {
    std::string name;
    int w = 0, h = 0;  // variant_size: the sweep's, or the demo's for N-large
    int frames = 0;    // variant_frames: the sweep's, or more for N-large
    Scene scene;
    int sweep_index = 0;
    std::string lights_label;
    std::optional<AnalyticTrace> trace;
    std::vector<uint8_t> interior;
    // N-large: the scene with the linear law (linear_law_twin), which the linear-law rows draw.
    std::optional<Scene> linear_twin;
    // Where the scene has a Phong material: every material metallic-roughness (metal_rough_twin),
    // which the metallic-roughness row draws.
    std::optional<Scene> metal_rough_twin;
};

// One row's renderer, alive for the whole variant so that frames can be interleaved.
struct RowRun {
    Row row;
    const Scene* scene = nullptr;  // what it draws: the variant's scene, or its linear_twin
    std::unique_ptr<DeferredShader> ds;
    std::unique_ptr<ForwardRenderer> fr;
    std::vector<double> ms;  // the timed frames' wall times
    // What each frame took beside its wall time, warm-up frames included until time_frames drops them.
    struct Samples {
        std::vector<double> depth_copy_ms, lights_ms, cpu_ms, cpu_make_frame_ms, cpu_lights_ms;
    } samples;
    FrameStats last;
    ForwardStats last_forward;
    Image image;
    // One frame; returns its wall time (glFinish-bounded, as measured by the renderer).
    double frame(const Scene& s, int w, int h) {
        if (ds) {
            last = ds->render(s, w, h);
            samples.depth_copy_ms.push_back(last.ms.depth_copy);
            samples.lights_ms.push_back(last.ms.lights);
            samples.cpu_ms.push_back(last.ms.cpu);
            samples.cpu_make_frame_ms.push_back(last.ms.cpu_make_frame);
            samples.cpu_lights_ms.push_back(last.ms.cpu_lights);
            return last.ms.frame;
        }
        last_forward = fr->render(s);
        samples.cpu_ms.push_back(last_forward.ms_cpu);
        return last_forward.ms_frame;
    }
};
using Runs = std::vector<std::unique_ptr<RowRun>>;

// The floor (bench_floor.h): one FloorBench per G-buffer layout the deferred rows use, and the
// fill times measured in the timed rounds.
struct Floors {
    std::map<GbufferLayout, std::unique_ptr<FloorBench>> bench;
    std::map<GbufferLayout, std::vector<double>> fill_ms;
};

Row base_row(const Config& cfg, const Variant& v, Renderer renderer) {
    Row r;
    r.scene = v.name;
    r.renderer = renderer;
    r.lights = int(v.scene.lights.size());
    r.w = v.w, r.h = v.h;
    r.sweep_index = v.sweep_index;
    r.lights_label = v.lights_label;
    return r;
}

// A deferred row of the configuration `want` names (depth path, encoding, scissor, skips, G-buffer
// precision, light geometry); the row records what ran (the geometry and tile settings as resolved).
std::unique_ptr<RowRun> deferred(const Setup& st, const Variant& v, const Row& want) {
    ShaderOptions o;
    o.light_geometry = want.light_geometry;
    o.tile_size = st.cfg.tile_size, o.tile_lights = st.cfg.tile_lights, o.tile_plan = st.cfg.tile_plan;
    o.tile_depth = st.cfg.tile_depth;
    o.depth = want.depth;
    o.encoding = want.encoding;
    o.scissor = want.scissor;
    o.skip = want.skip;
    o.gbuffer_half = want.gbuffer_half;
    o.hdr.accum = want.accum_format;
    o.post.bloom = o.post.aa = false;  // the tutorial's core passes only; post costs the same on every row
    // The shadow rows: every map drawn every frame, so a row's time holds the shadow stage.
    for (const Light& l : v.scene.lights) o.shadow_lights = o.shadow_lights || l.shadow.on;
    o.shadows.reuse = false;
    auto run = std::make_unique<RowRun>();
    run->scene = want.linear_law ? &*v.linear_twin : want.metal_rough ? &*v.metal_rough_twin : &v.scene;
    run->ds = std::make_unique<DeferredShader>(st.caps, v.w, v.h, o, st.shaders);
    run->ds->set_scene(*run->scene);
    run->ds->set_read_back(true);  // its image is read back (read_output): the final pass may be skipped
    Row& r = run->row = base_row(st.cfg, v, Renderer::deferred);
    r.depth = want.depth;
    r.encoding = want.encoding;
    r.gbuffer_half = want.gbuffer_half;
    r.accum_format = want.accum_format;
    r.scissor = want.scissor;
    r.skip = want.skip;
    r.linear_law = want.linear_law;
    r.metal_rough = want.metal_rough;
    if (want.metal_rough) r.scene = metal_rough_name(v.name);
    r.gbuffer_bytes_per_pixel = run->ds->paths().gbuffer_bytes_per_pixel;
    r.light_geometry = run->ds->paths().light_geometry;
    if (r.light_geometry == LightGeometry::tiles)
        r.tile_size = run->ds->paths().tile_size, r.tile_lights = run->ds->paths().tile_lights;
    return run;
}

// float_target: an RGBA32F target copied to the main buffer at the end (both forms round once,
// as the reference does); otherwise straight into the RGBA8 main buffer, every additive pass
// rounded to 8 bits, as Listing 4 ran in 2005 (framebuffer += light).
std::unique_ptr<RowRun> forward(const Setup& st, const Variant& v, ForwardMode mode, bool float_target) {
    ForwardOptions o;
    o.mode = mode;
    o.float_target = float_target;
    o.shadows.reuse = false;  // as the deferred rows: the shadow rows' maps drawn in every timed frame
    auto run = std::make_unique<RowRun>();
    run->scene = &v.scene;
    run->fr = std::make_unique<ForwardRenderer>(st.caps, v.w, v.h, o, st.shaders);
    run->fr->set_scene(v.scene);
    run->row = base_row(st.cfg, v, mode == ForwardMode::single ? Renderer::forward_single : Renderer::forward_multi);
    run->row.float_accum = float_target;
    return run;
}

GbufferLayout layout_of(const DeferredShader& ds) {
    GbufferLayout l;
    l.depth_texture = ds.paths().gbuffer_depth_texture;
    l.formats = ds.paths().gbuffer_formats;
    return l;
}

std::string printf_line(const char* f, ...) __attribute__((format(printf, 1, 2)));
std::string printf_line(const char* f, ...) {
    char buf[512];
    va_list ap;
    va_start(ap, f);
    std::vsnprintf(buf, sizeof buf, f, ap);
    va_end(ap);
    return buf;
}

// The scene variant: the base scene with the spec's lights, its label, and the analytic trace
// where every material is constant.
Variant make_variant(const Setup& st, const std::string& path, const std::string& name, const LightSpec& spec,
                     int sweep_index, const std::function<void(const std::string&)>& say) {
    Variant v;
    v.name = name;
    std::tie(v.w, v.h) = variant_size(st.cfg, spec.set);
    v.frames = variant_frames(st.cfg, spec.set);
    v.scene = bench_scene(load_scene(path), spec);
    if (spec.set == LightSet::large) v.linear_twin = linear_law_twin(v.scene);
    if (has_phong_material(v.scene)) v.metal_rough_twin = metal_rough_twin(v.scene);
    v.sweep_index = sweep_index;
    v.lights_label = (spec.count < 0 ? std::string("own") : std::to_string(spec.count)) +
                     (spec.set == LightSet::overlap ? "-overlap"
                      : spec.set == LightSet::large ? "-large"
                      : spec.set == LightSet::shadow ? "-shadow"
                                                     : "");
    if (analytic_capable(v.scene)) {
        const double t0 = now_ms();
        v.trace = analytic_trace(v.scene, v.w, v.h);
        v.interior = interior_mask(*v.trace, v.w, v.h);
        say(printf_line("bench: analytic reference of %s with %zu lights traced in %.1f s", v.name.c_str(),
                        v.scene.lights.size(), (now_ms() - t0) / 1000));
    }
    return v;
}

// Every renderer of the variant, built (shaders compiled) before any frame is timed; runs[0] is
// the forward reference. Configurations the GL cannot run are noted once (first variant).
Runs build_runs(const Setup& st, const Variant& v, bool first, std::vector<std::string>& notes) {
    Runs runs;
    auto add = [&](const Row& want) { runs.push_back(deferred(st, v, want)); };
    auto config = [](DepthPath d, bool scissor) {  // the default configuration on depth path d
        Row r;
        r.depth = d;
        r.scissor = scissor;
        return r;
    };
    // runs[0], float single-pass: the forward reference. The RGBA8 forms are the baseline a 2005
    // user would have run; the speed goal takes the faster of each kind.
    const bool float_forward = st.caps.fbo && st.caps.texture_float;
    if (!float_forward && first)
        notes.push_back("float forward rows left out (no ARB_texture_float or EXT_framebuffer_object): the forward "
                        "reference is then the RGBA8 single-pass render");
    for (ForwardMode m : {ForwardMode::single, ForwardMode::multi})
        for (bool f : {true, false})
            if (!f || float_forward) runs.push_back(forward(st, v, m, f));
    for (DepthPath d : {DepthPath::texture, DepthPath::packed})
        for (bool sc : {false, true}) add(config(d, sc));
    // Each skip turned off alone, on the default configuration (depth texture, scissor on). The
    // fold skips the ambient pass only where the material pass does not write it, so its row turns
    // both off: the tutorial's ambient pass, against the ambient target's row (the fold where it can).
    for (const SkipName& k : skip_names()) {
        Row r = config(DepthPath::texture, true);
        r.skip.*k.on = false;
        if (k.on == &SkipOptions::ambient_pass) r.skip.ambient_target = false;
        add(r);
    }
    for (DepthEncoding e : {DepthEncoding::literal, DepthEncoding::linear, DepthEncoding::log}) {
        Row r = config(DepthPath::packed, true);
        r.encoding = e;
        add(r);
    }
    // Each light geometry on the default configuration (docs/light_geometry.md); quad's is the row above.
    for (LightGeometry g : st.cfg.geometries)
        if (g != LightGeometry::quad) {
            Row r = config(DepthPath::texture, true);
            r.light_geometry = g;
            add(r);
        }
    // On N-large, the default configuration of quad and each geometry again with the linear law
    // (goal `law`): the light programs' cost per pair under each law, in the same rounds.
    if (v.linear_twin) {
        std::vector<LightGeometry> gs = {LightGeometry::quad};
        gs.insert(gs.end(), st.cfg.geometries.begin(), st.cfg.geometries.end());
        for (size_t i = 0; i < gs.size(); ++i)
            if (std::find(gs.begin(), gs.begin() + long(i), gs[i]) == gs.begin() + long(i)) {
                Row r = config(DepthPath::texture, true);
                r.light_geometry = gs[i];
                r.linear_law = true;
                add(r);
            }
    }
    // dsr's default configuration with quad again, every material metallic-roughness: the light
    // stage's cost per pair under each material model, in the same rounds (bench_material.h).
    if (v.metal_rough_twin) {
        Row r = config(DepthPath::texture, true);
        r.metal_rough = true;
        add(r);
    }
    // The other documents' G-buffer: eye-space position stored in a float target, where the GL has one.
    for (DepthPath d : {DepthPath::position16, DepthPath::position32}) {
        ShaderOptions probe;
        probe.depth = d;
        const std::string refused = choose_paths(st.caps, probe).refused;
        if (refused.empty()) add(config(d, true));
        else if (first) notes.push_back(std::string(depth_path_name(d)) + " rows left out: " + refused);
    }
    // P-buffer 0 in half or float (--accum, docs/hdr.md) on the default configuration, where the GL
    // renders into and blends float targets: what accumulation beyond 1.0 costs.
    for (AccumFormat a : {AccumFormat::half, AccumFormat::float32}) {
        const std::string missing = accum_format_missing(st.caps, st.caps.fbo, a);
        Row r = config(DepthPath::texture, true);
        r.accum_format = a;
        if (missing.empty()) add(r);
        else if (first) notes.push_back(std::string("--accum ") + accum_format_name(a) + " rows left out: " + missing);
    }
    // Higher-precision G-buffer targets where the GL has them.
    if (st.caps.texture_float && st.caps.half_float) {
        for (DepthPath d : {DepthPath::texture, DepthPath::packed}) {
            Row r = config(d, true);
            r.gbuffer_half = true;
            add(r);
        }
    } else if (first) {
        notes.push_back("half-float G-buffer rows left out: the GL lacks ARB_texture_float or ARB_half_float_pixel");
    }
    return runs;
}

// One FloorBench per G-buffer layout the deferred rows use, where framebuffer objects exist.
Floors build_floors(const Setup& st, const Variant& v, const Runs& runs, bool first, std::vector<std::string>& notes) {
    Floors floors;
    if (!st.caps.fbo) {
        if (first) notes.push_back("floor not measured: it renders into framebuffer objects (EXT_framebuffer_object)");
        return floors;
    }
    for (auto& run : runs)
        if (run->ds && !floors.bench.count(layout_of(*run->ds))) {
            const GbufferLayout l = layout_of(*run->ds);
            floors.bench[l] = std::make_unique<FloorBench>(st.caps, v.w, v.h, l, st.shaders);
            floors.bench[l]->set_scene(v.scene);
        }
    return floors;
}

}  // namespace

std::vector<size_t> round_order(size_t rows, int round) {
    std::vector<size_t> order(rows);
    std::iota(order.begin(), order.end(), size_t(0));
    std::mt19937 rng(unsigned(round) + 1u);  // the same orders in every run
    std::shuffle(order.begin(), order.end(), rng);
    return order;
}

std::vector<size_t> goal_rounds_rows(const std::vector<Row>& rows, const std::string& scene, int lights) {
    const Row* a = find_geometry_row(rows, scene, lights, LightGeometry::automatic);
    const std::vector<const Row*> fixed = fixed_geometry_rows(rows, scene, lights);
    double fastest = 0;
    for (const Row* r : fixed) fastest = r == fixed.front() ? r->ms_median : std::min(fastest, r->ms_median);
    std::vector<size_t> pick;
    const auto add = [&](const Row* r) {
        const size_t i = size_t(r - rows.data());
        if (std::find(pick.begin(), pick.end(), i) == pick.end()) pick.push_back(i);
    };
    if (a && !fixed.empty()) {
        add(a);
        for (const Row* r : fixed)
            if (r->ms_median <= kGoalRoundsWithin * fastest) add(r);
    }
    if (const Row* d = find_default_row(rows, scene, lights))
        if (const Row* twin = find_linear_law_row(rows, scene, lights, d->light_geometry)) {
            add(d);
            add(twin);
        }
    return pick;
}

namespace {

// Warm-up, then the timed frames interleaved across rows (one frame of each row per round), so a
// burst of load from elsewhere on the machine spreads over all rows instead of biasing one; the
// floor's fill frames in the same rounds. Each round takes the rows in an order of its own
// (round_order): in one fixed order a row paid for the row before it, the same one every round.
// Each row keeps its last frame's image. Then the CPU goal's frames back to back and the close
// goals' own rounds (Row::cpu_alone_ms, Row::goal_rounds_ms), and one counted frame per deferred
// row, whose counts go in the row.
void time_frames(const Config& cfg, const Variant& v, Runs& runs, Floors& floors) {
    for (auto& [l, fb] : floors.bench)
        for (int i = 0; i < cfg.warmup; ++i) fb->fill_frame(v.scene);
    // The warm-up and the timed frames do not count: the counting queries around every light draw
    // are the measurement's cost, not the renderer's (most of the CPU's frame on a GPU). Off from
    // the warm-up on: llvmpipe compiles a shader's code for the state it is drawn in, an occlusion
    // query's count included, so a warm-up with the queries on would leave the compiles without
    // them to the first timed frame (docs/benchmarks.md, "How the rows are timed").
    for (auto& run : runs)
        if (run->ds) run->ds->set_counting(false);
    // Each row's warm-up (warm_up): until its frames stop building programs and exploring.
    for (auto& run : runs) {
        run->row.warmup_frames = warm_up(cfg.warmup, cfg.compile_warmup, [&] {
            const long long built = Program::built();
            const double ms = run->frame(*run->scene, v.w, v.h);
            run->row.warmup_frames_ms.push_back(ms);
            // A slow frame is its own warm-up.
            return WarmupFrame{Program::built() != built, run->ds && run->last.auto_geometry.explored.has_value(), ms > kSlowFrameMs};
        });
        run->row.frames = frames_for(run->row.warmup_frames_ms.front(), v.frames);
        // The medians are the timed frames': the warm-up's (the first with the shaders' compiles)
        // used to sit among them in the light stage's, the hand-off's and the CPU's.
        run->samples = {};
    }
    int rounds = 0;
    for (auto& run : runs) rounds = std::max(rounds, run->row.frames);
    for (int f = 0; f < rounds; ++f) {
        for (size_t i : round_order(runs.size(), f)) {
            auto& run = runs[i];
            if (f >= run->row.frames) continue;
            run->ms.push_back(run->frame(*run->scene, v.w, v.h));
            if (f + 1 == run->row.frames)
                run->image = opaque(run->ds ? run->ds->read_output(v.w, v.h) : read_pixels(v.w, v.h));
        }
        if (f < v.frames)  // (a) in the same rounds, as many frames as the fast rows
            for (auto& [l, fb] : floors.bench) floors.fill_ms[l].push_back(fb->fill_frame(v.scene));
    }
    // The CPU goal's frames: dsr's default row's frames again, back to back. In the rounds a frame
    // runs after the other rows' and finds the caches holding their data, which costs it CPU time a
    // render of the same frame does not pay (docs/benchmarks.md, "How the rows are timed").
    std::vector<Row> rows;
    for (auto& run : runs) rows.push_back(run->row);
    if (const Row* d = rows.empty() ? nullptr : find_default_row(rows, v.name, rows.front().lights)) {
        RowRun& run = *runs[size_t(d - rows.data())];
        for (int f = 0; f < run.row.frames; ++f)
            run.row.cpu_alone_frames_ms.push_back(run.ds->render(*run.scene, v.w, v.h).ms.cpu);
        run.row.cpu_alone_ms = median(run.row.cpu_alone_frames_ms);
    }
    // The close goals' rows again, those alone (goal_rounds_rows), in rounds of their own order.
    for (size_t i = 0; i < rows.size(); ++i)
        if (!runs[i]->ms.empty()) rows[i].ms_median = median(runs[i]->ms);
    const std::vector<size_t> pick = rows.empty() ? std::vector<size_t>{} : goal_rounds_rows(rows, v.name, rows.front().lights);
    const int paired = pick.empty() ? 0 : kGoalRoundsFactor * runs[pick.front()]->row.frames;
    for (int f = 0; f < paired; ++f)
        for (size_t k : round_order(pick.size(), f)) {
            RowRun& run = *runs[pick[k]];
            const FrameStats s = run.ds->render(*run.scene, v.w, v.h);
            run.row.goal_rounds_frames_ms.push_back(s.ms.frame);
            run.row.goal_rounds_lights_frames_ms.push_back(s.ms.lights);
        }
    for (size_t i : pick) {
        runs[i]->row.goal_rounds_ms = median(runs[i]->row.goal_rounds_frames_ms);
        runs[i]->row.goal_rounds_lights_ms = median(runs[i]->row.goal_rounds_lights_frames_ms);
    }
    for (auto& run : runs)
        if (run->ds) {
            run->ds->set_counting(true);
            run->last = run->ds->render(*run->scene, v.w, v.h);
        }
}

// (a), (b) and (d) of each layout's floor; (c) depends on the row's post options (finish_rows).
std::map<GbufferLayout, FloorParts> floor_parts(Floors& floors) {
    std::map<GbufferLayout, FloorParts> parts;
    std::optional<double> output_ms;  // (d): the same RGBA8 target whatever the layout, timed once
    for (auto& [l, fb] : floors.bench) {
        FloorParts p;
        p.fill_ms = median(floors.fill_ms[l]);
        if (!output_ms) output_ms = fb->output_clear_ms();
        p.output_ms = *output_ms;
        p.light_ns_per_fragment = fb->light_ns_per_fragment();
        parts[l] = p;
    }
    return parts;
}

// The variant's ideal count: the analytic trace's exact eye depth where the scene allows,
// otherwise the first depth-texture row's 24-bit depth codes.
IdealCount variant_ideal(const Config& cfg, const Variant& v, const Runs& runs) {
    if (v.trace) return ideal_from_eye_depth(v.scene, v.w, v.h, v.trace->eye_depth);
    for (auto& run : runs)
        if (run->ds && run->ds->options().depth == DepthPath::texture && !run->row.linear_law)
            return ideal_from_depth_codes(v.scene, v.w, v.h, run->ds->read_gbuffer_depth_codes());
    return {};
}

// The default configuration's quad image: every light geometry is compared with it (the
// linear-law rows with the linear-law quad row's).
const Image* quad_image(const Runs& runs, bool linear_law = false) {
    for (auto& run : runs) {
        const Row& r = run->row;
        if ((linear_law ? default_configuration_twin(r) : default_configuration(r)) &&
            r.light_geometry == LightGeometry::quad)
            return &run->image;
    }
    return nullptr;
}

// A twin's forward reference (the linear-law rows', the metallic-roughness row's): `twin` drawn once
// as runs[0] (`ref_row`) draws the scene.
Image twin_reference(const Setup& st, const Variant& v, const Row& ref_row, const Scene& twin) {
    ForwardOptions o;
    o.mode = ForwardMode::single;
    o.float_target = ref_row.float_accum.value_or(false);
    o.shadows.reuse = false;
    ForwardRenderer fr(st.caps, v.w, v.h, o, st.shaders);
    fr.set_scene(twin);
    fr.render(twin);
    return opaque(read_pixels(v.w, v.h));
}

// Each row's figures from its frames: times, counts, the floor, the errors against the references.
void finish_row(const Config& cfg, const Variant& v, RowRun& run, const IdealCount& ideal,
                const std::map<GbufferLayout, FloorParts>& parts, const Image& ref, const Image* quad) {
    Row& r = run.row;
    r.ms_median = median(run.ms);
    r.frames_ms = run.ms;
    r.ms_min = *std::min_element(run.ms.begin(), run.ms.end());
    r.ms_max = *std::max_element(run.ms.begin(), run.ms.end());
    r.cpu_ms = median(run.samples.cpu_ms);
    r.cpu_frames_ms = run.samples.cpu_ms;
    if (run.ds) {
        const FrameStats& st = run.last;
        r.frame = st;
        r.depth_copy_ms = median(run.samples.depth_copy_ms);
        r.lights_ms = median(run.samples.lights_ms);
        r.lights_frames_ms = run.samples.lights_ms;
        r.cpu_make_frame_ms = median(run.samples.cpu_make_frame_ms);
        r.cpu_lights_ms = median(run.samples.cpu_lights_ms);
        if (quad) r.err_quad = compare_images(run.image, *quad, 1.0 / 255.0);
        r.ideal_fragments = ideal.fragments;
        r.ideal_source = ideal.source;
        auto p = parts.find(layout_of(*run.ds));
        if (p != parts.end()) {
            FloorParts fp = p->second;
            fp.post_ms = post_floor_ms(run.ds->options().post, v.w, v.h, fp.light_ns_per_fragment);
            r.floor_fill_ms = fp.fill_ms;
            r.floor_light_ns = fp.light_ns_per_fragment;
            r.floor_post_ms = fp.post_ms;
            r.floor_output_ms = fp.output_ms;
            r.floor_ms = floor_ms(fp, ideal.fragments);
            r.floor_ratio = floor_ratio(r.ms_median, r.floor_ms);
        }
    } else {
        r.passes = run.last_forward.passes;
    }
    r.err = compare_images(run.image, ref, 1.0 / 255.0);
    if (v.trace && !r.linear_law && !r.metal_rough)  // the trace has the scene's law and materials
        r.err_analytic = compare_images_masked(run.image, v.trace->image, v.interior, 1.0 / 255.0);
}

}  // namespace

const char* renderer_name(Renderer r) {
    switch (r) {
        case Renderer::deferred: return "deferred";
        case Renderer::forward_single: return "forward-single";
        case Renderer::forward_multi: return "forward-multi";
    }
    return "?";
}

std::vector<std::string> skips_off(const SkipOptions& skip) { return skip_names_off(skip, &SkipName::field); }

namespace {

// The default configuration's settings, whatever the lights' law.
bool default_settings(const Row& r) {
    return r.renderer == Renderer::deferred && r.depth == DepthPath::texture && r.scissor &&
           skips_off(r.skip).empty() && !r.gbuffer_half && r.accum_format == AccumFormat::rgba8;
}

}  // namespace

bool default_configuration(const Row& r) { return !r.linear_law && !r.metal_rough && default_settings(r); }

bool default_configuration_twin(const Row& r) { return r.linear_law && default_settings(r); }

std::string metal_rough_name(const std::string& scene) { return scene + "-metal-rough"; }

std::optional<long long> light_fragments(const Row& r) {
    return r.frame ? r.frame->lights.counted_fragments() : std::nullopt;
}

std::optional<long long> light_invocations(const Row& r) {
    return r.frame ? r.frame->lights.invocations : std::nullopt;
}

std::optional<long long> light_evaluations(const Row& r) {
    return r.frame ? r.frame->lights.evaluations : std::nullopt;
}

std::optional<int> light_passes(const Row& r) { return r.frame ? std::optional<int>(r.frame->lights.passes) : std::nullopt; }

std::optional<double> evaluations_ratio(const Row& r) {
    const std::optional<long long> e = light_evaluations(r);
    if (!e || !r.ideal_fragments || *r.ideal_fragments <= 0) return std::nullopt;
    return double(*e) / double(*r.ideal_fragments);
}

std::string config_text(const Row& r) {
    const std::string name = renderer_name(r.renderer);
    if (r.renderer != Renderer::deferred) return r.float_accum ? name + (*r.float_accum ? " float" : " rgba8") : name;
    std::string s = name + " " + depth_path_name(r.depth);
    if (r.depth == DepthPath::packed) s += std::string("/") + encoding_name(r.encoding);
    s += r.scissor ? " sc" : " -";
    if (r.gbuffer_half) s += " half";
    if (r.accum_format != AccumFormat::rgba8) s += std::string(" accum-") + accum_format_name(r.accum_format);
    for (auto& k : skips_off(r.skip)) s += " no-" + k;
    if (r.light_geometry != LightGeometry::quad) s += std::string(" ") + light_geometry_name(r.light_geometry);
    if (r.tile_size && r.tile_lights) s += " " + std::to_string(*r.tile_size) + "/" + std::to_string(*r.tile_lights);
    if (r.linear_law) s += " linear-law";
    if (r.metal_rough) s += " metal-rough";
    return s;
}

std::string row_words(const Row& r) {
    if (r.renderer != Renderer::deferred) {
        std::string s = r.renderer == Renderer::forward_single ? "forward, a pass per object" : "forward, a pass per light and object";
        if (r.float_accum) s += *r.float_accum ? ", float sums" : ", 8-bit sums";
        return s;
    }
    std::string s = "deferred";
    switch (r.light_geometry) {
        case LightGeometry::quad: break;  // the tutorial's, and the configuration sweep's
        case LightGeometry::automatic: s += ", auto light geometry"; break;
        case LightGeometry::volume: s += ", light volumes"; break;
        case LightGeometry::stencil: s += ", stencil light volumes"; break;
        case LightGeometry::screen: s += ", every light at every pixel"; break;
        case LightGeometry::tiles:
            s += ", screen tiles";
            if (r.tile_size && r.tile_lights)
                s += " of " + std::to_string(*r.tile_size) + " px, " + std::to_string(*r.tile_lights) + " lights a pass";
            break;
        default: s += std::string(", ") + light_geometry_name(r.light_geometry);
    }
    if (r.depth == DepthPath::packed) s += std::string(", packed depth (") + encoding_name(r.encoding) + ")";
    else if (r.depth == DepthPath::position16) s += ", positions in half floats";
    else if (r.depth == DepthPath::position32) s += ", positions in floats";
    else if (r.depth != DepthPath::texture) s += std::string(", depth ") + depth_path_name(r.depth);
    if (!r.scissor) s += ", no scissor";
    if (r.gbuffer_half) s += ", half-float G-buffer";
    if (r.accum_format == AccumFormat::half) s += ", half-float light sums";
    if (r.accum_format == AccumFormat::float32) s += ", float light sums";
    std::vector<std::string> off = skips_off(r.skip);
    for (size_t i = 0; i < off.size(); ++i) {
        std::replace(off[i].begin(), off[i].end(), '_', ' ');
        s += (i ? ", " : off.size() == 1 ? ", skip off: " : ", skips off: ") + off[i];
    }
    if (r.linear_law) s += ", the tutorial's linear law";
    if (r.metal_rough) s += ", metallic-roughness materials";
    return s;
}

bool analytic_capable(const Scene& s) {
    for (const Material& m : s.materials)
        if (m.diffuse_map >= 0 || m.normal_map >= 0 || m.specular_map >= 0) return false;
    return true;
}

std::pair<int, int> variant_size(const Config& cfg, LightSet set) {
    if (set == LightSet::large && !cfg.size_given) return {kDemoWidth, kDemoHeight};
    return {cfg.w, cfg.h};
}

int variant_frames(const Config& cfg, LightSet set) {
    return set == LightSet::large && !cfg.frames_given ? kLargeFrameFactor * cfg.frames : cfg.frames;
}

std::string large_frames_note(const Config& cfg) {
    const int n = variant_frames(cfg, LightSet::large);
    const bool large = std::find(cfg.light_sets.begin(), cfg.light_sets.end(), LightSet::large) != cfg.light_sets.end();
    return large && n != cfg.frames ? " (N-large " + std::to_string(n) + ")" : "";
}

std::pair<int, int> context_size(const Config& cfg) {
    int w = cfg.w, h = cfg.h;
    for (size_t i = 0; i < cfg.lights.size(); ++i) {
        const auto [vw, vh] = variant_size(cfg, i < cfg.light_sets.size() ? cfg.light_sets[i] : LightSet::spread);
        w = std::max(w, vw), h = std::max(h, vh);
    }
    return {w, h};
}

int warm_up(int warmup, int compile_warmup, const std::function<WarmupFrame()>& frame) {
    int frames = 0, quiet = 0;
    while (quiet < warmup && frames < warmup + compile_warmup) {
        const WarmupFrame f = frame();
        ++frames;
        if (f.slow) break;
        quiet = f.built || f.exploring ? 0 : quiet + 1;
    }
    return frames;
}

int frames_for(double first_ms, int frames) {
    if (first_ms <= kSlowFrameMs) return frames;
    return std::min(frames, std::max(3, int(kSlowRowBudgetMs / first_ms)));
}

std::string machine_name() {
    std::ifstream in("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return model + ", " + std::to_string(n) + " logical CPUs";
}

std::string file_stem(const std::string& path) {
    std::string b = path.substr(path.find_last_of('/') + 1);
    return b.substr(0, b.find_last_of('.'));
}

IdealCount ideal_from_eye_depth(const Scene& scene, int w, int h, const std::vector<double>& eye_depth) {
    const SurfacePoints s = surface_from_eye_depth(eye_depth, w, h, projection_scale(scene.camera, w, h));
    return {ideal_count(s, scene.lights, scene.camera.view_d()), std::string("analytic")};
}

IdealCount ideal_from_depth_codes(const Scene& scene, int w, int h, const std::vector<uint32_t>& codes) {
    return {ideal_count_from_depth_codes(codes, w, h, scene.camera, scene.lights), std::string("depth24")};
}

Runner::Runner(const Config& cfg, const Caps& caps, const std::string& shader_dir)
    : cfg_(cfg), caps_(caps), shaders_(shader_dir) {}

void Runner::run_scene(const std::string& path, int light_count, int sweep_index, int index, int total) {
    auto say = [&](const std::string& line) {
        if (progress) progress(line);
    };
    const LightSpec spec{light_count, size_t(sweep_index) < cfg_.light_sets.size() ? cfg_.light_sets[size_t(sweep_index)]
                                                                                   : LightSet::spread};
    const std::string name = bench_scene_name(file_stem(path), spec);
    for (const Row& r : rows_)
        if (r.scene == name && r.lights == light_count) return;  // "large" replaces every base: once
    const Setup st{cfg_, caps_, shaders_};
    const bool first = index == 0;
    const Variant v = make_variant(st, path, name, spec, sweep_index, say);
    Runs runs = build_runs(st, v, first, notes_);
    Floors floors = build_floors(st, v, runs, first, notes_);
    time_frames(cfg_, v, runs, floors);
    const std::map<GbufferLayout, FloorParts> parts = floor_parts(floors);
    const IdealCount ideal = variant_ideal(cfg_, v, runs);
    const Image* quad = quad_image(runs), *linear_quad = quad_image(runs, true);
    const Image linear_ref = v.linear_twin ? twin_reference(st, v, runs[0]->row, *v.linear_twin) : Image{};
    const Image mr_ref = v.metal_rough_twin ? twin_reference(st, v, runs[0]->row, *v.metal_rough_twin) : Image{};
    for (auto& run : runs) {
        const bool linear = run->row.linear_law;  // against the twin's own reference and quad row
        const bool mr = run->row.metal_rough;     // against the twin's forward render; no quad row of its model
        finish_row(cfg_, v, *run, ideal, parts, linear ? linear_ref : mr ? mr_ref : runs[0]->image,
                   linear ? linear_quad : mr ? nullptr : quad);
        rows_.push_back(run->row);
    }
    // One line a variant: its rows are printed together at the end (bench_report.h rows_text).
    say(printf_line("bench [%d/%d] %s scene, %d lights: %zu rows measured", index + 1, total, name.c_str(),
                    runs.empty() ? light_count : runs[0]->row.lights, runs.size()));
}

}  // namespace dsr::bench
