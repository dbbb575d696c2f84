// The tiles' depth spans from the G-buffer read back (tile_spans.h).
#include "deferred/tile_spans.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace dsr {

namespace {

// surface_eye_z's arithmetic (depth_codec.glsl), in double: -planes.y / min(planes.x + depth,
// planes.y / far).
double eye_z(double depth, glm::vec2 planes, float far_plane) {
    return -double(planes.y) / std::min(double(planes.x) + depth, double(planes.y) / double(far_plane));
}

#if defined(__GNUC__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
// Four pixels of spans_from_depth's band loop in SSE2's vectors (GCC's vector extensions): lit_normal
// in float ((byte - 127.5)^2 and their sum are exact in float; v.v > 51^2 is the sum > 650.25), and
// each column's least and greatest depth of a lit pixel. -O2 does not vectorise the scalar loop,
// which is a real share of the spans' time (docs/tiles.md, "Depth culling of the tiles").
typedef float F4 __attribute__((vector_size(16)));
typedef std::int32_t I4 __attribute__((vector_size(16)));

inline void x4(const std::uint8_t* n, const float* d, float* lo, float* hi) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    const F4 pinf = {inf, inf, inf, inf}, minf = -pinf;
    I4 px;
    F4 z, a, b;
    std::memcpy(&px, n, sizeof px);  // RGBA bytes: R the low byte of each little-endian word
    std::memcpy(&z, d, sizeof z);
    std::memcpy(&a, lo, sizeof a);
    std::memcpy(&b, hi, sizeof b);
    const F4 nx = __builtin_convertvector(px & 255, F4) - 127.5f;
    const F4 ny = __builtin_convertvector((px >> 8) & 255, F4) - 127.5f;
    const F4 nz = __builtin_convertvector((px >> 16) & 255, F4) - 127.5f;
    const I4 lit = nx * nx + ny * ny + nz * nz > 650.25f;
    const F4 zl = lit ? z : pinf, zh = lit ? z : minf;
    a = zl < a ? zl : a;
    b = zh > b ? zh : b;
    std::memcpy(lo, &a, sizeof a);
    std::memcpy(hi, &b, sizeof b);
}
#endif

float step_out(float v, float toward, int steps) {
    for (int i = 0; i < steps; ++i) v = std::nextafter(v, toward);
    return v;
}

}  // namespace

std::vector<DepthSpan> spans_from_depth(const GbufferReadback& g, int width, int height, int tile_size,
                                        glm::vec2 planes, float far_plane) {
    const int tx = (width + tile_size - 1) / tile_size, ty = (height + tile_size - 1) / tile_size;
    constexpr float inf = std::numeric_limits<float>::infinity();
    // Each tile's least and greatest depth of its lit pixels. A band of tile_size rows at a time:
    // each column's least and greatest over the band's rows first (no chain of dependent min and
    // max from pixel to pixel, four columns at a time), then each tile's columns together.
    std::vector<float> dmin(size_t(tx) * size_t(ty), inf), dmax(size_t(tx) * size_t(ty), -inf);
    std::vector<float> col_lo(static_cast<size_t>(width)), col_hi(static_cast<size_t>(width));
    for (int band = 0; band < ty; ++band) {
        std::fill(col_lo.begin(), col_lo.end(), inf);
        std::fill(col_hi.begin(), col_hi.end(), -inf);
        float* lo = col_lo.data();
        float* hi = col_hi.data();
        const int y1 = std::min(height, (band + 1) * tile_size);
        for (int y = band * tile_size; y < y1; ++y) {
            const float* d = g.depth + size_t(y) * size_t(g.stride);
            const std::uint8_t* n = g.normal + size_t(y) * size_t(g.stride) * 4;
            int x = 0;
#if defined(__GNUC__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
            for (; x + 4 <= width; x += 4) x4(n + 4 * x, d + x, lo + x, hi + x);
#endif
            for (; x < width; ++x) {
                const bool lit = lit_normal(n + 4 * x);
                lo[x] = std::min(lo[x], lit ? d[x] : inf);
                hi[x] = std::max(hi[x], lit ? d[x] : -inf);
            }
        }
        for (int t = 0; t < tx; ++t) {
            const size_t i = size_t(band) * size_t(tx) + size_t(t);
            const int x1 = std::min(width, (t + 1) * tile_size);
            for (int x = t * tile_size; x < x1; ++x) {
                dmin[i] = std::min(dmin[i], lo[x]);
                dmax[i] = std::max(dmax[i], hi[x]);
            }
        }
    }
    // The eye z is decreasing in the depth: the farthest depth gives the span's low end.
    std::vector<DepthSpan> out(dmin.size());
    for (size_t i = 0; i < out.size(); ++i) {
        if (dmin[i] > dmax[i]) {
            out[i] = DepthSpan{1e30f, -1e30f};
            continue;
        }
        const double lo = eye_z(double(step_out(dmax[i], inf, 4)), planes, far_plane);
        const double hi = eye_z(double(step_out(dmin[i], -inf, 4)), planes, far_plane);
        out[i] = DepthSpan{step_out(float(lo - 1e-6 * std::abs(lo)), -inf, 1), step_out(float(hi + 1e-6 * std::abs(hi)), inf, 1)};
    }
    return out;
}

}  // namespace dsr
