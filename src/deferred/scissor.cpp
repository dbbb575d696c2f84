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

#include "dsr_error.h"

namespace dsr {
namespace {

struct SlopeRange {
    double lo = INFINITY, hi = -INFINITY;
    void add(double u, double w) {  // w >= near > 0 for every caller: no division by zero
        const double t = u / w;
        lo = std::min(lo, t);
        hi = std::max(hi, t);
    }
};

// Both helpers are inlined (always_inline) so that the x and y axes' divisions and square roots
// overlap: make_frame at 4096 lights took 8% less.
// Range of u/w over the disk |(u,w) - (a,b)| <= r restricted to w >= n (n > 0). The caller has
// checked the region is not empty (b + r >= n).
[[gnu::always_inline]] inline SlopeRange slope_range(double a, double b, double r, double n) {
    SlopeRange s;
    const double d2 = a * a + b * b, r2 = r * r;
    if (d2 > r2) {
        // Tangent points from the origin: the chord of contact's foot is C*(1 - r^2/D^2) and its
        // half-length is r*sqrt(D^2 - r^2)/D, along the perpendicular (-b, a)/D.
        const double inv = 1.0 / d2;  // one division for both
        const double k = 1.0 - r2 * inv;
        const double h = r * std::sqrt(d2 - r2) * inv;
        const double u1 = a * k - b * h, w1 = b * k + a * h;
        const double u2 = a * k + b * h, w2 = b * k - a * h;
        // A tangent point in front of the near plane bounds the region; one behind it does not
        // (the region there is cut by the chord below instead).
        if (w1 >= n) s.add(u1, w1);
        if (w2 >= n) s.add(u2, w2);
    }
    const double dw = n - b;
    if (dw * dw <= r2) {  // the circle meets w = n: the chord's ends are vertices of the region
        const double half = std::sqrt(r2 - dw * dw);
        s.add(a - half, n);
        s.add(a + half, n);
    }
    return s;
}

// NDC slope range -> pixel interval [lo, hi), rounded outward and clamped in double before any
// cast, so huge slopes never reach an int conversion. A point at window x = wx lies in pixel
// floor(wx), hence hi = floor(wx_max) + 1 (ceil would drop the pixel when wx_max is an integer).
[[gnu::always_inline]] inline void to_pixels(const SlopeRange& s, double scale, int size, int& lo, int& hi) {
    const double half = 0.5 * size;
    double wlo = (scale * s.lo + 1.0) * half;
    double whi = (scale * s.hi + 1.0) * half;
    // A few ulps of slack so that rounding in this function never excludes a boundary point.
    wlo -= 1e-9 * std::abs(wlo) + 1e-7;
    whi += 1e-9 * std::abs(whi) + 1e-7;
    lo = (int)std::floor(std::clamp(wlo, 0.0, (double)size));
    hi = std::min(size, (int)std::floor(std::clamp(whi, -1.0, (double)size)) + 1);
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

ScissorRect light_scissor(glm::vec3 light_eye, float radius, float p00, float p11,
                          float near_plane, int width, int height) {
    if (!finite(light_eye) || !std::isfinite(radius) || !std::isfinite(p00) ||
        !std::isfinite(p11) || !std::isfinite(near_plane))
        throw Error("light_scissor: non-finite light position, radius or projection");
    if (radius < 0 || p00 <= 0 || p11 <= 0 || near_plane <= 0 || width < 0 || height < 0)
        throw Error("light_scissor: need radius >= 0, p00, p11, near > 0 and a non-negative "
                    "viewport; got radius " + std::to_string(radius) + ", near " +
                    std::to_string(near_plane));

    const double lx = light_eye.x, ly = light_eye.y, lz = light_eye.z;
    const double r = radius, n = near_plane;
    const double b = -lz;  // the centre's distance in front of the eye

    // No sphere point at z <= -near: nothing visible can be lit (a sphere wholly behind the eye
    // gave Listing 16 a full-screen rectangle, docs/errata.md #5).
    if (b + r < n || width == 0 || height == 0) return {};

    // Eye inside the sphere: every view ray may meet a lit point; whole viewport (Lengyel).
    if (lx * lx + ly * ly + lz * lz <= r * r) return {0, 0, width, height};

    ScissorRect rect;
    to_pixels(slope_range(lx, b, r, n), p00, width, rect.x0, rect.x1);
    to_pixels(slope_range(ly, b, r, n), p11, height, rect.y0, rect.y1);
    if (rect.empty()) return {};
    return rect;
}

ScissorRect scissor_from_slopes(double xlo, double xhi, double ylo, double yhi, float p00, float p11,
                                int width, int height) {
    if (!(xlo <= xhi) || !(ylo <= yhi) || width <= 0 || height <= 0) return {};
    ScissorRect rect;
    SlopeRange sx, sy;
    sx.lo = xlo, sx.hi = xhi, sy.lo = ylo, sy.hi = yhi;
    to_pixels(sx, p00, width, rect.x0, rect.x1);
    to_pixels(sy, p11, height, rect.y0, rect.y1);
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
