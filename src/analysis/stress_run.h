// Runs one stress case (stress_cases.h) in the renderer and checks its invariants:
//   - no NaN/Inf in P-buffer 0 (rendered as RGBA32F so they survive) nor in the reconstructed
//     eye-space positions of surface pixels;
//   - no GL error (a stage's check_gl exception, or errors pending after the frame);
//   - no other exception;
//   - every light's scissor rectangle, computed exactly as the lighting stage does, contains
//     every sampled point of the light's sphere that lies at z <= -near and projects into the
//     viewport (brute force, as tests/test_scissor.cpp).
// And records, without a pass/fail bound: the relative eye-z error against the analytic trace
// (renderer and CPU twin), and the final 8-bit image's error against the analytic reference in
// LSB on interior pixels.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "analysis/shadow_metrics.h"
#include "analysis/stress_cases.h"
#include "analysis/z_accuracy.h"
#include "deferred/scissor.h"
#include "platform/context.h"

namespace dsr {

struct StressResult {
    std::string name, category, path;
    bool limit = false;           // StressCase::limit: failures are reported, not required
    double far_near = 0, light_radius = 0;
    int width = 0, height = 0;
    long long nan_pixels = 0;     // P-buffer 0 pixels with a non-finite channel
    long long nan_positions = 0;  // surface pixels whose reconstructed position is non-finite
    int gl_errors = 0;
    std::string exception;        // what() of an exception other than a GL error
    bool scissor_contains_sphere = true;
    int lights_checked = 0;
    long long scissor_points = 0, scissor_points_outside = 0;
    std::string scissor_first_miss;
    double scissor_exact_miss_px = 0;  // informational: how far (pixels) a point of the sphere
                                       // transformed in double falls outside the rectangle
    int lights_drawn = 0, lights_total = 0;
    long long light_fragments = 0;     // fragments the light passes shaded (FrameStats)
    long long lost_pixels = 0;         // interior pixels where the trace hits a surface and the
                                       // G-buffer holds none (clipped away, e.g. by a far plane
                                       // that float rounding moved nearer)
    long long zero_normal_shaded = 0;  // pixels of no_reference_meshes (zero vertex normals) that
                                       // Listing 20's len > 0.1 test takes as a valid normal
                                       // (an invariant: must be 0)
    ZError z, z_cpu;                   // renderer and CPU twin, over the same pixels
    double max_lsb = -1, mean_lsb = -1;  // -1: no pixel compared
    long long lsb_pixels = 0, lsb_over_2 = 0;  // pixels compared; of them, over 2 LSB
    double ms = 0;                     // wall time of the case (render, read-backs, checks)
    // Shadow cases (StressCase::shadow): the light, the range multiple, the map's settings, and
    // the shadow measured against the trace (recorded, not invariants: the sweep runs bad biases
    // on purpose). shadow_maps: FrameStats' count (0 while the renderer draws none).
    bool shadow = false;
    std::string shadow_light;
    double shadow_range = 0, shadow_bias = 0, shadow_slope = 0;
    int shadow_size = 0, shadow_maps = 0;
    ShadowMeasure shadow_measure;

    std::vector<std::string> failures() const;  // the invariants broken, empty when it passes
    bool passed() const { return failures().empty(); }
    bool counts_as_failure() const { return !limit && !passed(); }
};

// Brute-force scissor check: samples the sphere (eye space) with sphere_samples (surface,
// interior, and the disk where it meets z = -near; as tests/test_scissor.cpp) and counts the samples at
// z <= -near that project into the w x h viewport (p00 = P[0][0], p11 = P[1][1]) but land on
// a pixel outside `rect`.
struct ScissorCheck {
    long long points = 0, outside = 0;
    double max_outside_px = 0;  // how far outside, in pixels (inf for an empty rectangle)
    std::string first_miss;
};
ScissorCheck check_scissor(const glm::dvec3& light_eye, double radius, double p00, double p11, double near_plane,
                           int w, int h, const ScissorRect& rect, unsigned seed = 1234);

class StressRunner {
public:
    // Runs every case on `ctx` (the caller's, from create_context; cases must fit in its main
    // frame buffer, and it must outlive the runner). Shader programs are compiled once per
    // configuration and reused across cases.
    StressRunner(GLContext& ctx, const std::string& shader_dir);
    ~StressRunner();
    StressResult run(const StressCase& c);
    const std::string& renderer() const { return renderer_; }

private:
    GLContext& ctx_;
    int max_w_, max_h_;
    std::string shader_dir_, renderer_;
    std::map<std::string, std::unique_ptr<DeferredShader>> shaders_;
};

}  // namespace dsr
