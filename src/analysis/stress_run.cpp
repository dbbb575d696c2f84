// One stress case through the renderer, and its invariants (stress_run.h).
#include "dsr_clock.h"
#include "analysis/stress_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>


#include "analysis/analytic_reference.h"
#include "analysis/sphere_samples.h"
#include "dsr_error.h"
#include "gl/caps.h"
#include "gl/check.h"
#include "gl/readback.h"

namespace dsr {

namespace {

bool finite4(const float* p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) && std::isfinite(p[3]);
}

struct Projected {
    bool visible;  // z <= -near and inside the viewport
    double wx, wy;
};

Projected project(const glm::dvec3& p, double p00, double p11, double near_plane, int w, int h) {
    if (p.z > -near_plane) return {false, 0, 0};
    const double wx = (p00 * p.x / -p.z + 1.0) * 0.5 * w, wy = (p11 * p.y / -p.z + 1.0) * 0.5 * h;
    const bool in = std::floor(wx) >= 0 && std::floor(wx) < w && std::floor(wy) >= 0 && std::floor(wy) < h;
    return {in, wx, wy};
}

// Pixels (window units) by which window point (wx, wy) lies outside rect; 0 inside.
double outside_by(const ScissorRect& rc, double wx, double wy) {
    if (rc.empty()) return INFINITY;
    const double px = std::floor(wx), py = std::floor(wy);
    if (px >= rc.x0 && px < rc.x1 && py >= rc.y0 && py < rc.y1) return 0;
    return std::max({rc.x0 - wx, wx - rc.x1, rc.y0 - wy, wy - rc.y1, 1e-9});
}

bool is_gl_error(const Error& e) { return std::string(e.what()).rfind("GL error", 0) == 0; }

}  // namespace

ScissorCheck check_scissor(const glm::dvec3& light_eye, double radius, double p00, double p11, double near_plane,
                           int w, int h, const ScissorRect& rect, unsigned seed) {
    ScissorCheck k;
    std::mt19937_64 rng(seed);
    for (const glm::dvec3& p : sphere_samples(light_eye, radius, near_plane, SphereSampleCounts{}, rng)) {
        const Projected pr = project(p, p00, p11, near_plane, w, h);
        if (!pr.visible) continue;
        ++k.points;
        const double out = outside_by(rect, pr.wx, pr.wy);
        k.max_outside_px = std::max(k.max_outside_px, out);
        if (out > 0 && k.outside++ == 0) {
            char buf[200];
            std::snprintf(buf, sizeof buf, "eye-space point (%.6g, %.6g, %.6g) at window (%.2f, %.2f), rect [%d,%d)x[%d,%d)",
                          p.x, p.y, p.z, pr.wx, pr.wy, rect.x0, rect.x1, rect.y0, rect.y1);
            k.first_miss = buf;
        }
    }
    return k;
}

std::vector<std::string> StressResult::failures() const {
    std::vector<std::string> f;
    if (nan_pixels) f.push_back(std::to_string(nan_pixels) + " non-finite pixels in P-buffer 0");
    if (nan_positions) f.push_back(std::to_string(nan_positions) + " non-finite reconstructed positions");
    if (gl_errors) f.push_back(std::to_string(gl_errors) + " GL errors");
    if (!exception.empty()) f.push_back("exception: " + exception);
    if (zero_normal_shaded)
        f.push_back(std::to_string(zero_normal_shaded) + " pixels of zero-normal meshes taken as lit surfaces");
    if (!scissor_contains_sphere)
        f.push_back("scissor misses " + std::to_string(scissor_points_outside) + " sphere points, first " +
                    scissor_first_miss);
    return f;
}

StressRunner::StressRunner(GLContext& ctx, const std::string& shader_dir)
    : ctx_(ctx), max_w_(ctx.width()), max_h_(ctx.height()), shader_dir_(shader_dir) {
    ctx_.make_current();
    renderer_ = probe_caps().renderer;
}

StressRunner::~StressRunner() {
    try {
        ctx_.make_current();  // the shaders' GL objects belong to ctx_
    } catch (const std::exception&) {
    }
    shaders_.clear();
}

StressResult StressRunner::run(const StressCase& c) {
    const double t0 = now_ms();
    StressResult r;
    r.name = c.name;
    r.category = c.category;
    r.limit = c.limit;
    r.path = c.path;
    r.far_near = c.far_near;
    r.light_radius = c.light_radius;
    r.width = c.width;
    r.height = c.height;
    const int w = c.width, h = c.height;
    if (w > max_w_ || h > max_h_) throw Error("stress case " + c.name + " is larger than the context");

    ShaderOptions opts = c.opts;
    opts.hdr.accum = AccumFormat::float32;  // P-buffers in RGBA32F: NaN and Inf survive to be counted
    char key[200];
    std::snprintf(key, sizeof key, "%dx%d %d %d skip%d%d%d%d scissor%d geometry%d shadows%d%d%d", w, h,
                  int(opts.depth), int(opts.encoding), opts.skip.material_variants, opts.skip.empty_lights,
                  opts.skip.light_depth_test, opts.skip.light_sphere_test, opts.scissor, int(opts.light_geometry),
                  opts.shadows.on, opts.shadow_lights, int(opts.shadows.filter));
    std::string cache_key = key;
    for (const std::string& off : c.caps_off) cache_key += " " + off;
    r.shadow = c.shadow;
    if (c.shadow) {
        const LightShadow& sh = c.scene.lights.at(0).shadow;
        r.shadow_light = c.shadow_light;
        r.shadow_range = c.shadow_range;
        r.shadow_bias = sh.bias;
        r.shadow_slope = sh.slope;
        r.shadow_size = sh.size;
    }

    Image final_img, p0, pos;
    bool rendered = false;
    try {
        ctx_.make_current();  // another context may have been made current since the last case
        drain_gl_errors();  // nothing left over from an earlier case counts against this one
        std::unique_ptr<DeferredShader>& ds = shaders_[cache_key];
        if (!ds) ds = std::make_unique<DeferredShader>(probe_caps(c.caps_off), w, h, opts, shader_dir_);
        ds->set_scene(c.scene);
        const FrameStats st = ds->render(c.scene, w, h);
        r.shadow_maps = st.shadows.maps;
        r.lights_drawn = st.lights.drawn;
        r.lights_total = st.lights.total;
        r.light_fragments = st.lights.fragments;
        r.gl_errors += drain_gl_errors();
        final_img = read_pixels(w, h);
        p0 = ds->read_pbuffer(0);
        pos = ds->reconstructed_positions(c.scene.camera);
        r.gl_errors += drain_gl_errors();
        rendered = true;
    } catch (const Error& e) {
        if (is_gl_error(e)) ++r.gl_errors;
        else r.exception = e.what();
        shaders_.erase(cache_key);  // its GL state is unknown now
    } catch (const std::exception& e) {
        r.exception = e.what();
        shaders_.erase(cache_key);
    }

    if (rendered) {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                r.nan_pixels += !finite4(p0.at(x, y));
                const float* q = pos.at(x, y);
                r.nan_positions += !std::isfinite(q[3]) || (q[3] > 0.5f && !finite4(q));
            }
    }

    // Scissor rectangles exactly as the lighting stage computes them (projection as
    // geometry_stage builds it, the light centre transformed to eye space in double and rounded
    // once, Camera::to_eye).
    const Camera& cam = c.scene.camera;
    const glm::mat4 proj = cam.projection(float(w) / float(h));
    const glm::dmat4 view_exact = cam.view_d();
    for (size_t i = 0; i < c.scene.lights.size(); ++i) {
        const Light& light = c.scene.lights[i];
        const glm::vec3 eye = cam.to_eye(light.pos);
        ScissorRect rc;
        try {
            rc = light_scissor(eye, light.radius, proj[0][0], proj[1][1], cam.near_plane, w, h);
        } catch (const Error& e) {
            r.exception = std::string("light_scissor: ") + e.what();
            continue;
        }
        ++r.lights_checked;
        const unsigned seed = 1234u + unsigned(i);
        const ScissorCheck k = check_scissor(glm::dvec3(eye), light.radius, proj[0][0], proj[1][1], cam.near_plane,
                                             w, h, rc, seed);
        r.scissor_points += k.points;
        if (k.outside && !r.scissor_points_outside) r.scissor_first_miss = "light " + std::to_string(i) + ": " + k.first_miss;
        r.scissor_points_outside += k.outside;
        // The same sphere not rounded to float: how far the rounding moves it.
        const glm::dvec3 exact = glm::dvec3(view_exact * glm::dvec4(glm::dvec3(light.pos), 1.0));
        const ScissorCheck e = check_scissor(exact, light.radius, proj[0][0], proj[1][1], cam.near_plane, w, h, rc, seed);
        r.scissor_exact_miss_px = std::max(r.scissor_exact_miss_px, e.max_outside_px);
    }
    r.scissor_contains_sphere = r.scissor_points_outside == 0;

    if (rendered) {
        const AnalyticTrace trace = analytic_trace(c.scene, w, h);
        const std::vector<uint8_t> mask = interior_mask(trace, w, h);
        r.z = reconstructed_z_error(pos, trace, mask);
        r.z_cpu = modelled_z_error(opts.depth, opts.encoding, cam.near_plane, cam.far_plane, pos, trace, mask);
        std::vector<uint8_t> lsb_mask = mask;
        for (size_t p = 0; p < lsb_mask.size(); ++p)
            for (int m : c.no_reference_meshes)
                if (trace.mesh[p] == m) lsb_mask[p] = 0;
        const ImageDiff d = compare_images_masked(final_img, trace.image, lsb_mask, 2.0 / 255.0);
        r.lsb_pixels = d.pixels;
        r.lsb_over_2 = d.failing;
        for (size_t p = 0; p < mask.size(); ++p) {
            const bool surface = pos.rgba[p * 4 + 3] > 0.5f;
            const int m = trace.mesh[p];
            if (std::find(c.no_reference_meshes.begin(), c.no_reference_meshes.end(), m) != c.no_reference_meshes.end())
                r.zero_normal_shaded += surface;
            else if (mask[p] && m >= 0 && !surface)
                r.lost_pixels += 1;
        }
        if (d.pixels) r.max_lsb = d.max_lsb(), r.mean_lsb = d.mean_lsb();
        if (c.shadow) r.shadow_measure = measure_shadow(c.scene, trace, final_img, c.shadow_receiver, c.shadow_occluder);
    }
    r.ms = now_ms() - t0;
    return r;
}

}  // namespace dsr
