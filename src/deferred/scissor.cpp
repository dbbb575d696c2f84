// Light scissor rectangle (§3.4.2, Listing 16, after Lengyel).
//
// Why the problem splits per axis: the window x of an eye-space point depends only on x/(-z), and
// the near-plane restriction z <= -near only on z. So the x extent of the projected region
// {p in sphere : p.z <= -near} is the range of u/w over the disk of radius r about (l.x, -l.z) in
// the (u = x, w = -z) plane, cut to w >= near; y is the same problem with l.y. Listing 16's
// tangent planes through the eye are the tangent lines from the origin to that disk; computing
// the tangent points directly needs no division by l.z or by nx/ny (docs/errata.md #5), and the near
// plane adds the two ends of the chord w = near as candidates. The range over that convex
// region is attained at one of these candidates, so the result is exact, not just conservative.
#include "deferred/scissor.h"

#include <algorithm>
#include <cmath>
#include <string>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "dsr_error.h"

namespace dsr {
namespace {

// Two lanes of doubles: SSE2's width, which every x86-64 has. make_frame computes its lights'
// rectangles a pair at a time in these, without a branch: the scalar form waited on each light's
// chain of divisions and square roots (perf: light_scissor was half of make_frame at 4096 lights).
// Each lane's arithmetic is the scalar formula's, operation for operation.
using D2 = double __attribute__((vector_size(16)));
using M2 = long long __attribute__((vector_size(16)));  // a comparison's lanes: all ones or zero
using I2 = int __attribute__((vector_size(8)));

inline D2 splat(double v) { return D2{v, v}; }

inline D2 vsqrt(D2 x) {
#if defined(__SSE2__)
    return _mm_sqrt_pd(x);
#else
    return D2{std::sqrt(x[0]), std::sqrt(x[1])};
#endif
}

// Each lane's range of slopes u / w, and the candidates' adds in the scalar code's order:
// std::min's (t < lo ? t : lo) and std::max's (hi < t ? t : hi), under a lane mask.
struct SlopeRange {
    D2 lo = splat(INFINITY), hi = splat(-INFINITY);
    void add(M2 take, D2 t) {
        lo = (take & (t < lo)) ? t : lo;
        hi = (take & (hi < t)) ? t : hi;
    }
};

// Range of u/w over the disk |(u,w) - (a,b)| <= r restricted to w >= n (n > 0), a lane a disk.
// The caller has checked the region is not empty (b + r >= n). A lane's untaken candidates are
// computed and dropped (their square roots of zero instead of a negative number).
inline SlopeRange slope_range(D2 a, D2 b, D2 r, D2 n) {
    SlopeRange s;
    const D2 d2 = a * a + b * b, r2 = r * r, zero = splat(0.0);
    // Tangent points from the origin: the chord of contact's foot is C*(1 - r^2/D^2) and its
    // half-length is r*sqrt(D^2 - r^2)/D, along the perpendicular (-b, a)/D.
    const M2 tangent = d2 > r2;
    const D2 inv = 1.0 / d2;  // one division for both
    const D2 k = 1.0 - r2 * inv;
    const D2 h = r * vsqrt(tangent ? d2 - r2 : zero) * inv;
    const D2 u1 = a * k - b * h, w1 = b * k + a * h;
    const D2 u2 = a * k + b * h, w2 = b * k - a * h;
    // A tangent point in front of the near plane bounds the region; one behind it does not
    // (the region there is cut by the chord below instead).
    s.add(tangent & (w1 >= n), u1 / w1);
    s.add(tangent & (w2 >= n), u2 / w2);
    const D2 dw = n - b;
    const M2 chord = dw * dw <= r2;  // the circle meets w = n: the chord's ends are vertices
    const D2 half = vsqrt(chord ? r2 - dw * dw : zero);
    s.add(chord, (a - half) / n);
    s.add(chord, (a + half) / n);
    return s;
}

// NDC slope range -> pixel interval [lo, hi), each lane with its own scale and size, rounded
// outward and clamped in double before any cast, so huge slopes never reach an int conversion. A
// point at window x = wx lies in pixel floor(wx), hence hi = floor(wx_max) + 1 (ceil would drop
// the pixel when wx_max is an integer). A lane with no slope (lo > hi) gets lo = hi = 0.
struct PixelSpan {
    I2 lo, hi;
};
inline PixelSpan to_pixels(const SlopeRange& s, D2 scale, D2 size) {
    const D2 half = 0.5 * size;
    D2 wlo = (scale * s.lo + 1.0) * half;
    D2 whi = (scale * s.hi + 1.0) * half;
    // A few ulps of slack so that rounding in this function never excludes a boundary point.
    wlo -= 1e-9 * (wlo < 0 ? -wlo : wlo) + 1e-7;
    whi += 1e-9 * (whi < 0 ? -whi : whi) + 1e-7;
    // std::clamp's order (v < lo ? lo : hi < v ? hi : v), then floor: truncation is floor for
    // lo (>= 0 there); for hi (>= -1) a truncation above the value steps down one.
    const D2 clo = wlo < 0 ? splat(0.0) : (size < wlo ? size : wlo);
    const D2 chi = whi < -1 ? splat(-1.0) : (size < whi ? size : whi);
    const I2 ilo = __builtin_convertvector(clo, I2);
    I2 ihi = __builtin_convertvector(chi, I2);
    ihi -= __builtin_convertvector(__builtin_convertvector(ihi, D2) > chi, I2) & 1;
    const I2 isize = __builtin_convertvector(size, I2);
    ihi += 1;
    ihi = isize < ihi ? isize : ihi;
    const I2 some = __builtin_convertvector(s.lo <= s.hi, I2);
    return {some ? ilo : I2{0, 0}, some ? ihi : I2{0, 0}};
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void check(const EyeSphere& s, float p00, float p11, float near_plane, int width, int height) {
    if (!finite(s.centre) || !std::isfinite(s.radius) || !std::isfinite(p00) || !std::isfinite(p11) ||
        !std::isfinite(near_plane))
        throw Error("light_scissor: non-finite light position, radius or projection");
    if (s.radius < 0 || p00 <= 0 || p11 <= 0 || near_plane <= 0 || width < 0 || height < 0)
        throw Error("light_scissor: need radius >= 0, p00, p11, near > 0 and a non-negative "
                    "viewport; got radius " + std::to_string(s.radius) + ", near " +
                    std::to_string(near_plane));
}

// Two spheres' rectangles (lanes 0 and 1).
void scissor_pair(const EyeSphere& s0, const EyeSphere& s1, float p00, float p11, float near_plane, int width,
                  int height, ScissorRect* out0, ScissorRect* out1) {
    const D2 lx{s0.centre.x, s1.centre.x}, ly{s0.centre.y, s1.centre.y}, lz{s0.centre.z, s1.centre.z};
    const D2 r{s0.radius, s1.radius}, n = splat(near_plane);
    const D2 b = -lz;  // the centre's distance in front of the eye
    // No sphere point at z <= -near: nothing visible can be lit (a sphere wholly behind the eye
    // gave Listing 16 a full-screen rectangle, docs/errata.md #5).
    const M2 behind = b + r < n;
    // Eye inside the sphere: every view ray may meet a lit point; whole viewport (Lengyel).
    const M2 inside = lx * lx + ly * ly + lz * lz <= r * r;
    const PixelSpan x = to_pixels(slope_range(lx, b, r, n), splat(p00), splat(width));
    const PixelSpan y = to_pixels(slope_range(ly, b, r, n), splat(p11), splat(height));
    ScissorRect* out[2] = {out0, out1};
    for (int l = 0; l < 2; ++l) {
        if (!out[l]) continue;
        ScissorRect rect;
        if (behind[l] || width == 0 || height == 0)
            rect = {};
        else if (inside[l])
            rect = {0, 0, width, height};
        else
            rect = {x.lo[l], y.lo[l], x.hi[l], y.hi[l]};
        *out[l] = rect.empty() ? ScissorRect{} : rect;
    }
}

}  // namespace

void light_scissors(const EyeSphere* spheres, size_t n, float p00, float p11, float near_plane, int width,
                    int height, ScissorRect* rects) {
    for (size_t i = 0; i < n; ++i) check(spheres[i], p00, p11, near_plane, width, height);
    size_t i = 0;
    for (; i + 1 < n; i += 2)
        scissor_pair(spheres[i], spheres[i + 1], p00, p11, near_plane, width, height, &rects[i], &rects[i + 1]);
    if (i < n) scissor_pair(spheres[i], spheres[i], p00, p11, near_plane, width, height, &rects[i], nullptr);
}

ScissorRect light_scissor(glm::vec3 light_eye, float radius, float p00, float p11,
                          float near_plane, int width, int height) {
    const EyeSphere s{light_eye, radius};
    ScissorRect rect;
    light_scissors(&s, 1, p00, p11, near_plane, width, height, &rect);
    return rect;
}

ScissorRect scissor_from_slopes(double xlo, double xhi, double ylo, double yhi, float p00, float p11,
                                int width, int height) {
    if (!(xlo <= xhi) || !(ylo <= yhi) || width <= 0 || height <= 0) return {};
    SlopeRange s;  // lane 0 the x axis, lane 1 the y axis
    s.lo = D2{xlo, ylo}, s.hi = D2{xhi, yhi};
    const PixelSpan p = to_pixels(s, D2{p00, p11}, D2{double(width), double(height)});
    const ScissorRect rect{p.lo[0], p.lo[1], p.hi[0], p.hi[1]};
    if (rect.empty()) return {};
    return rect;
}

ScissorRect light_scissor_listing16(glm::vec3 lightpos, float radius, float aspect, int sx,
                                    int sy) {
    // Listing 16, lines 002-093, variable names kept. to_int stands for the listing's (int)
    // casts; a non-finite argument there means "UB in the original": give the full viewport.
    bool undefined = false;
    auto to_int = [&undefined](float v) {
        if (!std::isfinite(v)) {
            undefined = true;
            return 0;
        }
        return (int)std::clamp(v, -1073741824.0f, 1073741824.0f);  // (int) truncates toward 0
    };

    int rect[4] = {0, 0, sx, sy};
    float d;
    float r = radius;
    float r2 = r * r;
    glm::vec3 l = lightpos;
    glm::vec3 l2 = lightpos * lightpos;
    float e1 = 1.2f;
    float e2 = 1.2f * aspect;

    d = r2 * l2.x - (l2.x + l2.z) * (r2 - l2.z);
    if (d >= 0) {
        d = std::sqrt(d);
        float nx1 = (r * l.x + d) / (l2.x + l2.z);
        float nx2 = (r * l.x - d) / (l2.x + l2.z);
        float nz1 = (r - nx1 * l.x) / l.z;
        float nz2 = (r - nx2 * l.x) / l.z;
        float pz1 = (l2.x + l2.z - r2) / (l.z - (nz1 / nx1) * l.x);
        float pz2 = (l2.x + l2.z - r2) / (l.z - (nz2 / nx2) * l.x);
        if (pz1 < 0) {
            float fx = nz1 * e1 / nx1;
            int ix = to_int((fx + 1.0f) * sx * 0.5f);
            float px = -pz1 * nz1 / nx1;
            if (px < l.x)
                rect[0] = std::max(rect[0], ix);
            else
                rect[2] = std::min(rect[2], ix);
        }
        if (pz2 < 0) {
            float fx = nz2 * e1 / nx2;
            int ix = to_int((fx + 1.0f) * sx * 0.5f);
            float px = -pz2 * nz2 / nx2;
            if (px < l.x)
                rect[0] = std::max(rect[0], ix);
            else
                rect[2] = std::min(rect[2], ix);
        }
    }

    d = r2 * l2.y - (l2.y + l2.z) * (r2 - l2.z);
    if (d >= 0) {
        d = std::sqrt(d);
        float ny1 = (r * l.y + d) / (l2.y + l2.z);
        float ny2 = (r * l.y - d) / (l2.y + l2.z);
        float nz1 = (r - ny1 * l.y) / l.z;
        float nz2 = (r - ny2 * l.y) / l.z;
        float pz1 = (l2.y + l2.z - r2) / (l.z - (nz1 / ny1) * l.y);
        float pz2 = (l2.y + l2.z - r2) / (l.z - (nz2 / ny2) * l.y);
        if (pz1 < 0) {
            float fy = nz1 * e2 / ny1;
            int iy = to_int((fy + 1.0f) * sy * 0.5f);
            float py = -pz1 * nz1 / ny1;
            if (py < l.y)
                rect[1] = std::max(rect[1], iy);
            else
                rect[3] = std::min(rect[3], iy);
        }
        if (pz2 < 0) {
            float fy = nz2 * e2 / ny2;
            int iy = to_int((fy + 1.0f) * sy * 0.5f);
            float py = -pz2 * nz2 / ny2;
            if (py < l.y)
                rect[1] = std::max(rect[1], iy);
            else
                rect[3] = std::min(rect[3], iy);
        }
    }

    if (undefined) return {0, 0, sx, sy};
    // Line 095: with both extents negative n is positive and the listing would pass negative
    // sizes to glScissor; the rectangle is returned as is (empty() is true for it).
    long long n = (long long)(rect[2] - rect[0]) * (rect[3] - rect[1]);
    if (n <= 0) return {};
    return {rect[0], rect[1], rect[2], rect[3]};
}

}  // namespace dsr
