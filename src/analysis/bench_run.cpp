// The benchmark's runner (bench_run.h): builds every row's renderer, warms up, times the frames
// interleaved across rows, counts the ideal fragments and compares each image with the references.
#include "analysis/bench_run.h"

#include <unistd.h>

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>

#include "dsr_clock.h"
#include "analysis/analytic_reference.h"
#include "analysis/bench_floor.h"
#include "analysis/bench_scenes.h"
#include "analysis/ideal_fragments.h"
#include "deferred/deferred_shader.h"
#include "deferred/reconstruct.h"
#include "forward/forward_renderer.h"
#include "gl/readback.h"

namespace dsr::bench {

namespace {

constexpr double kSlowFrameMs = 2000;   // above this, fewer frames (see frames_for)
constexpr double kSlowRowBudgetMs = 20000;

// Everything one scene variant (scene, light count, size) shares across its rows.
struct Variant {
    std::string name;
    Scene scene;
    int sweep_index = 0;
    std::string lights_label;
    std::optional<AnalyticTrace> trace;
    std::vector<uint8_t> interior;
    std::optional<long long> ideal;
};

// One row's renderer, alive for the whole variant so that frames can be interleaved.
struct RowRun {
    Row row;
    std::unique_ptr<DeferredShader> ds;
    std::unique_ptr<ForwardRenderer> fr;
    std::vector<double> ms, depth_copy_ms, cpu_ms;
    FrameStats last;
    ForwardStats last_forward;
    Image image;
    // One frame; returns its wall time (glFinish-bounded, as measured by the renderer).
    double frame(const Scene& s, int w, int h) {
        if (ds) {
            last = ds->render(s, w, h);
            depth_copy_ms.push_back(last.ms.depth_copy);
            cpu_ms.push_back(last.ms.cpu);
            return last.ms.frame;
        }
        last_forward = fr->render(s);
        cpu_ms.push_back(last_forward.ms_cpu);
        return last_forward.ms_frame;
    }
};

Row base_row(const Config& cfg, const Variant& v, const std::string& renderer) {
    Row r;
    r.scene = v.name;
    r.renderer = renderer;
    r.lights = int(v.scene.lights.size());
    r.w = cfg.w, r.h = cfg.h;
    r.sweep_index = v.sweep_index;
    r.lights_label = v.lights_label;
    return r;
}

std::unique_ptr<RowRun> deferred(const Config& cfg, const Caps& caps, const std::string& shaders, const Variant& v,
                                 DepthPath depth, DepthEncoding enc, bool scissor, const SkipOptions& skip,
                                 const std::vector<std::string>& skips_off, bool gbuffer_half,
                                 LightGeometry geometry) {
    ShaderOptions o;
    o.light_geometry = geometry;
    o.tile_size = cfg.tile_size, o.tile_lights = cfg.tile_lights, o.tile_plan = cfg.tile_plan;
    o.tile_depth = cfg.tile_depth;
    o.depth = depth;
    o.encoding = enc;
    o.scissor = scissor;
    o.skip = skip;
    o.gbuffer_half = gbuffer_half;
    o.post.bloom = o.post.aa = false;  // the tutorial's core passes only; post costs the same on every row
    auto run = std::make_unique<RowRun>();
    run->ds = std::make_unique<DeferredShader>(caps, cfg.w, cfg.h, o, shaders);
    run->ds->set_scene(v.scene);
    Row& r = run->row = base_row(cfg, v, "deferred");
    r.depth = depth_path_name(depth);
    r.gbuffer_bytes_per_pixel = run->ds->paths().gbuffer_bytes_per_pixel;
    if (depth == DepthPath::packed) r.encoding = encoding_name(enc);
    r.gbuffer = gbuffer_half ? "half" : "rgba8";
    r.light_geometry = light_geometry_name(run->ds->paths().light_geometry);
    if (run->ds->paths().light_geometry == LightGeometry::tiles)
        r.tile_size = run->ds->paths().tile_size, r.tile_lights = run->ds->paths().tile_lights;
    r.scissor = scissor;
    r.skips_off = skips_off;
    return run;
}

// float_target: an RGBA32F target copied to the main buffer at the end (both forms round once,
// as the reference does); otherwise straight into the RGBA8 main buffer, every additive pass
// rounded to 8 bits, as Listing 4 ran in 2005 (framebuffer += light).
std::unique_ptr<RowRun> forward(const Config& cfg, const Caps& caps, const std::string& shaders, const Variant& v,
                                ForwardMode mode, bool float_target) {
    ForwardOptions o;
    o.mode = mode;
    o.float_target = float_target;
    auto run = std::make_unique<RowRun>();
    run->fr = std::make_unique<ForwardRenderer>(caps, cfg.w, cfg.h, o, shaders);
    run->fr->set_scene(v.scene);
    run->row = base_row(cfg, v, mode == ForwardMode::single ? "forward-single" : "forward-multi");
    run->row.accum = float_target ? "float" : "rgba8";
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

}  // namespace

std::string config_text(const Row& r) {
    if (r.renderer != "deferred") return r.accum ? r.renderer + " " + *r.accum : r.renderer;
    std::string s = "deferred " + *r.depth;
    if (r.encoding) s += "/" + *r.encoding;
    s += r.scissor ? " sc" : " -";
    if (r.gbuffer == std::string("half")) s += " half";
    for (auto& k : r.skips_off) s += " no-" + k;
    if (r.light_geometry && *r.light_geometry != "quad") s += " " + *r.light_geometry;
    if (r.tile_size && r.tile_lights) s += " " + std::to_string(*r.tile_size) + "/" + std::to_string(*r.tile_lights);
    return s;
}

bool analytic_capable(const Scene& s) {
    for (const Material& m : s.materials)
        if (m.diffuse_map >= 0 || m.normal_map >= 0 || m.specular_map >= 0) return false;
    return true;
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

Runner::Runner(const Config& cfg, const Caps& caps, const std::string& shader_dir)
    : cfg_(cfg), caps_(caps), shaders_(shader_dir) {}

void Runner::run_scene(const std::string& path, int light_count, int sweep_index, int index, int total) {
    auto say = [&](const std::string& line) {
        if (progress) progress(line);
    };
    const LightSpec spec{light_count, size_t(sweep_index) < cfg_.light_sets.size() ? cfg_.light_sets[size_t(sweep_index)]
                                                                                   : LightSet::spread};
    Variant v;
    v.name = bench_scene_name(file_stem(path), spec);
    for (const Row& r : rows_)
        if (r.scene == v.name && r.lights == light_count) return;  // "large" replaces every base: once
    Scene base = load_scene(path);
    v.scene = bench_scene(base, spec);
    v.sweep_index = sweep_index;
    v.lights_label = light_count < 0 ? "own"
                     : std::to_string(light_count) + (spec.set == LightSet::overlap ? "-overlap"
                                                      : spec.set == LightSet::large ? "-large"
                                                                                    : "");
    if (analytic_capable(v.scene)) {
        double t0 = now_ms();
        v.trace = analytic_trace(v.scene, cfg_.w, cfg_.h);
        v.interior = interior_mask(*v.trace, cfg_.w, cfg_.h);
        say(printf_line("bench: analytic reference of %s with %zu lights traced in %.1f s", v.name.c_str(),
                        v.scene.lights.size(), (now_ms() - t0) / 1000));
    }

    // Every renderer of the variant is built (shaders compiled) before any frame is timed.
    std::vector<std::unique_ptr<RowRun>> runs;
    auto add_deferred = [&](DepthPath d, DepthEncoding e, bool sc, const SkipOptions& skip,
                            const std::vector<std::string>& skips_off, bool half,
                            LightGeometry g = LightGeometry::quad) {
        runs.push_back(deferred(cfg_, caps_, shaders_, v, d, e, sc, skip, skips_off, half, g));
    };
    // runs[0], float single-pass: the forward reference. The RGBA8 forms are the baseline a 2005
    // user would have run; the speed goal takes the faster of each kind.
    const bool float_forward = caps_.fbo && caps_.texture_float;
    if (!float_forward && index == 0)
        notes_.push_back("float forward rows left out (no ARB_texture_float or EXT_framebuffer_object): the forward "
                         "reference is then the RGBA8 single-pass render");
    for (ForwardMode m : {ForwardMode::single, ForwardMode::multi})
        for (bool f : {true, false})
            if (!f || float_forward) runs.push_back(forward(cfg_, caps_, shaders_, v, m, f));
    SkipOptions all;
    for (DepthPath d : {DepthPath::texture, DepthPath::packed})
        for (bool sc : {false, true}) add_deferred(d, DepthEncoding::corrected, sc, all, {}, false);
    // Each skip turned off alone, on the default configuration (depth texture, scissor on).
    for (int k = 0; k < 4; ++k) {
        SkipOptions s = all;
        bool* flag[4] = {&s.material_variants, &s.empty_lights, &s.light_depth_test, &s.light_sphere_test};
        const char* name[4] = {"material_variants", "empty_lights", "light_depth_test", "light_sphere_test"};
        *flag[k] = false;
        add_deferred(DepthPath::texture, DepthEncoding::corrected, true, s, {name[k]}, false);
    }
    for (DepthEncoding e : {DepthEncoding::literal, DepthEncoding::linear, DepthEncoding::log})
        add_deferred(DepthPath::packed, e, true, all, {}, false);
    // Each light geometry on the default configuration (issue 12); quad's is the row above.
    for (LightGeometry g : cfg_.geometries)
        if (g != LightGeometry::quad) add_deferred(DepthPath::texture, DepthEncoding::corrected, true, all, {}, false, g);
    // The peers' G-buffer (issue 16): eye-space position stored in a float target, where the GL has one.
    for (DepthPath d : {DepthPath::position16, DepthPath::position32}) {
        ShaderOptions probe;
        probe.depth = d;
        const std::string refused = choose_paths(caps_, probe).refused;
        if (refused.empty()) add_deferred(d, DepthEncoding::corrected, true, all, {}, false);
        else if (index == 0) notes_.push_back(std::string(depth_path_name(d)) + " rows left out: " + refused);
    }
    // Higher-precision G-buffer targets where the GL has them.
    if (caps_.texture_float && caps_.half_float) {
        for (DepthPath d : {DepthPath::texture, DepthPath::packed})
            add_deferred(d, DepthEncoding::corrected, true, all, {}, true);
    } else if (index == 0) {
        notes_.push_back("half-float G-buffer rows left out: the GL lacks ARB_texture_float or ARB_half_float_pixel");
    }

    // The floor (bench_floor.h): one FloorBench per G-buffer layout the deferred rows use.
    std::map<GbufferLayout, std::unique_ptr<FloorBench>> floors;
    std::map<GbufferLayout, std::vector<double>> fill_ms;
    if (caps_.fbo) {
        for (auto& run : runs)
            if (run->ds && !floors.count(layout_of(*run->ds))) {
                const GbufferLayout l = layout_of(*run->ds);
                floors[l] = std::make_unique<FloorBench>(caps_, cfg_.w, cfg_.h, l, shaders_);
                floors[l]->set_scene(v.scene);
            }
    } else if (index == 0) {
        notes_.push_back("floor not measured: it renders into framebuffer objects (EXT_framebuffer_object)");
    }

    // Warm-up, then the timed frames interleaved across rows (one frame of each row per round), so
    // a burst of load from elsewhere on the machine spreads over all rows instead of biasing one.
    for (auto& [l, fb] : floors)
        for (int i = 0; i < cfg_.warmup; ++i) fb->fill_frame(v.scene);
    for (auto& run : runs) {
        double first = 0;
        for (int i = 0; i < cfg_.warmup; ++i) {
            double ms = run->frame(v.scene, cfg_.w, cfg_.h);
            if (i == 0) first = ms;
            if (ms > kSlowFrameMs) break;  // a slow frame is its own warm-up
        }
        run->row.frames = frames_for(first, cfg_.frames);
    }
    int rounds = 0;
    for (auto& run : runs) rounds = std::max(rounds, run->row.frames);
    // The timed frames do not count: the counting queries around every light draw are the
    // measurement's cost, not the renderer's (on the H200 at 1024 lights most of the CPU's frame).
    for (auto& run : runs)
        if (run->ds) run->ds->set_counting(false);
    for (int f = 0; f < rounds; ++f) {
        for (auto& run : runs) {
            if (f >= run->row.frames) continue;
            run->ms.push_back(run->frame(v.scene, cfg_.w, cfg_.h));
            if (f + 1 == run->row.frames) run->image = opaque(read_pixels(cfg_.w, cfg_.h));
        }
        if (f < cfg_.frames)  // (a) in the same rounds, as many frames as the fast rows
            for (auto& [l, fb] : floors) fill_ms[l].push_back(fb->fill_frame(v.scene));
    }
    // One counted frame per deferred row after the timed ones: its counts go in the row.
    for (auto& run : runs)
        if (run->ds) {
            run->ds->set_counting(true);
            run->last = run->ds->render(v.scene, cfg_.w, cfg_.h);
        }
    std::map<GbufferLayout, FloorParts> parts;
    for (auto& [l, fb] : floors) {
        FloorParts p;
        p.fill_ms = median(fill_ms[l]);
        p.light_ns_per_fragment = fb->light_ns_per_fragment();
        parts[l] = p;
    }

    // The ideal count from exact surface points, not from the light shader's reconstruction: the
    // analytic trace's exact eye depth where the scene allows, otherwise the first depth-texture
    // row's 24-bit depth codes decoded in double. A light with no colour needs no fragment.
    const glm::dvec2 pscale = projection_scale(v.scene.camera, cfg_.w, cfg_.h);
    std::optional<std::string> ideal_source;
    if (v.trace) {
        v.ideal = ideal_fragments(surface_from_eye_depth(v.trace->eye_depth, cfg_.w, cfg_.h, pscale),
                                  eye_volumes(v.scene));
        ideal_source = "analytic";
    } else {
        for (auto& run : runs) {
            if (!run->ds || run->ds->options().depth != DepthPath::texture) continue;
            const SurfacePoints pts =
                surface_from_depth_codes(run->ds->read_gbuffer_depth_codes(), cfg_.w, cfg_.h,
                                         v.scene.camera.near_plane, v.scene.camera.far_plane, pscale);
            v.ideal = ideal_fragments(pts, eye_volumes(v.scene));
            ideal_source = "depth24";
            break;
        }
    }

    const Image& ref = runs[0]->image;
    const Image* quad_image = nullptr;  // the default configuration's image: every geometry against it
    for (auto& run : runs)
        if (run->ds && run->row.depth == std::string("texture") && run->row.scissor && run->row.skips_off.empty() &&
            run->row.gbuffer == std::string("rgba8") && run->row.light_geometry == std::string("quad")) {
            quad_image = &run->image;
            break;
        }
    for (auto& run : runs) {
        Row& r = run->row;
        r.ms_median = median(run->ms);
        r.ms_min = *std::min_element(run->ms.begin(), run->ms.end());
        r.ms_max = *std::max_element(run->ms.begin(), run->ms.end());
        r.cpu_ms = median(run->cpu_ms);
        if (run->ds) {
            r.light_fragments = run->last.counted_light_fragments();
            r.light_invocations = run->last.light_invocations;
            r.scissor_pixels = run->last.scissor_pixels;
            r.lights_drawn = run->last.lights_drawn;
            r.light_passes = run->last.light_passes;
            r.depth_copy_ms = median(run->depth_copy_ms);
            if (quad_image) r.err_quad = compare_images(run->image, *quad_image, 1.0 / 255.0);
            r.ideal_fragments = v.ideal;
            r.ideal_source = ideal_source;
            auto p = parts.find(layout_of(*run->ds));
            if (p != parts.end()) {
                FloorParts fp = p->second;
                fp.post_ms = post_floor_ms(run->ds->options().post, cfg_.w, cfg_.h, fp.light_ns_per_fragment);
                r.floor_fill_ms = fp.fill_ms;
                r.floor_light_ns = fp.light_ns_per_fragment;
                r.floor_post_ms = fp.post_ms;
                r.floor_ms = floor_ms(fp, v.ideal);
                r.floor_ratio = floor_ratio(r.ms_median, r.floor_ms);
            }
        } else {
            r.passes = run->last_forward.passes;
        }
        r.err = compare_images(run->image, ref, 1.0 / 255.0);
        if (v.trace) r.err_analytic = compare_images_masked(run->image, v.trace->image, v.interior, 1.0 / 255.0);
        say(printf_line("bench [%d/%d] %s, %d lights: %-46s %9.2f ms (%d frames)", index + 1, total, r.scene.c_str(),
                        r.lights, config_text(r).c_str(), r.ms_median, r.frames));
        rows_.push_back(r);
    }
}

}  // namespace dsr::bench
