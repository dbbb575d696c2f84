// Relative eye-space z error of a depth path, measured in the renderer (the positions the light
// pass reconstructs, DeferredShader::reconstructed_positions) against the exact depth of the
// analytic trace, and the same error predicted by the CPU twins of the path for the same z.
#pragma once
#include <cstdint>
#include <vector>

#include "analysis/analytic_reference.h"
#include "deferred/deferred_shader.h"

namespace dsr {

struct ZError {
    double max = 0, mean = 0;  // of |z - z_exact| / |z_exact|
    long long pixels = 0;
    void add(double rel) {  // accumulate; finish() turns the sum into the mean
        max = rel > max || rel != rel ? rel : max;  // NaN sticks
        mean += rel;
        ++pixels;
    }
    void finish() { mean = pixels ? mean / double(pixels) : 0; }
};

// The pixels compared: mask != 0 (interior_mask: the pixel and its neighbours on one mesh, so
// the rasteriser and the trace see the same surface), a hit in the trace, and alpha 1 in
// `positions` (the G-buffer holds a usable normal there). z_exact = -trace.eye_depth.
ZError reconstructed_z_error(const Image& positions, const AnalyticTrace& trace, const std::vector<uint8_t>& mask);

// What the depth path's CPU twin gives back for an exact eye z < 0 with near n and far f:
//   texture: the window depth quantised to 24 bits (k/(2^24-1), the value the depth texture
//            returns), then Listing 20's -planes.y/(planes.x + depth) in float;
//   packed:  decode_eye_z(store_unorm8(encode_eye_z(z))), the float twin of the shaders;
//   position16 / position32: z rounded to half (clamped to +-65504) / to float.
float modelled_eye_z(DepthPath path, DepthEncoding enc, double z, float n, float f);

// modelled_eye_z's relative error over the same pixels as reconstructed_z_error.
ZError modelled_z_error(DepthPath path, DepthEncoding enc, float n, float f, const Image& positions,
                        const AnalyticTrace& trace, const std::vector<uint8_t>& mask);

}  // namespace dsr
