#include "analysis/z_accuracy.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/packing.hpp>

#include "deferred/depth_codec.h"
#include "deferred/reconstruct.h"
#include "dsr_error.h"

namespace dsr {

namespace {
bool compared(size_t p, const Image& positions, const AnalyticTrace& trace, const std::vector<uint8_t>& mask) {
    return mask[p] && trace.mesh[p] >= 0 && positions.rgba[p * 4 + 3] > 0.5f;
}

void check_sizes(const Image& positions, const AnalyticTrace& trace, const std::vector<uint8_t>& mask) {
    const size_t n = size_t(positions.width) * positions.height;
    if (trace.mesh.size() != n || trace.eye_depth.size() != n || mask.size() != n)
        throw Error("z error: positions, trace and mask differ in size");
}
}  // namespace

ZError reconstructed_z_error(const Image& positions, const AnalyticTrace& trace, const std::vector<uint8_t>& mask) {
    check_sizes(positions, trace, mask);
    ZError e;
    for (size_t p = 0; p < mask.size(); ++p) {
        if (!compared(p, positions, trace, mask)) continue;
        const double exact = -trace.eye_depth[p];
        e.add(std::fabs(double(positions.rgba[p * 4 + 2]) - exact) / -exact);
    }
    e.finish();
    return e;
}

float modelled_eye_z(DepthPath path, DepthEncoding enc, double z, float n, float f) {
    // Position paths: z itself, rounded once to the target's float (fp16: clamped to its largest
    // finite value, 65504, as material.frag clamps).
    if (path == DepthPath::position32) return float(z);
    if (path == DepthPath::position16) return glm::unpackHalf1x16(glm::packHalf1x16(std::clamp(float(z), -65504.0f, 65504.0f)));
    if (path == DepthPath::packed) return decode_eye_z(enc, store_unorm8(encode_eye_z(enc, float(z), n, f)), n, f);
    // The depth buffer holds round(d * (2^24 - 1)) of the exact window depth d; sampling the
    // depth texture returns k / (2^24 - 1). The decode is the shader's, in float.
    const double a = -z, d = double(f) * (a - n) / (a * (double(f) - n));
    const double k = std::round(std::fmin(std::fmax(d, 0.0), 1.0) * 16777215.0);
    const float depth = float(k / 16777215.0);
    const glm::vec2 planes = planes_uniform(n, f);
    return -planes.y / (planes.x + depth);  // float arithmetic, as the GPU
}

ZError modelled_z_error(DepthPath path, DepthEncoding enc, float n, float f, const Image& positions,
                        const AnalyticTrace& trace, const std::vector<uint8_t>& mask) {
    check_sizes(positions, trace, mask);
    ZError e;
    for (size_t p = 0; p < mask.size(); ++p) {
        if (!compared(p, positions, trace, mask)) continue;
        const double exact = -trace.eye_depth[p];
        e.add(std::fabs(double(modelled_eye_z(path, enc, exact, n, f)) - exact) / -exact);
    }
    e.finish();
    return e;
}

}  // namespace dsr
