// The light scissor rectangle of §3.4.2 / Listing 16 (Lengyel's tangent planes) as pure math,
// so it can be tested against brute force without GL.
#pragma once
#include <cstddef>

#include <glm/glm.hpp>

namespace dsr {

// Pixels [x0,x1) x [y0,y1) in GL window coordinates (origin bottom-left); glScissor takes
// (x0, y0, x1 - x0, y1 - y0).
struct ScissorRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    long long area() const { return empty() ? 0 : (long long)(x1 - x0) * (y1 - y0); }
};

// The smallest pixel rectangle (rounded outward) holding the projection of every point of the
// light sphere that can be a visible surface point, i.e. every sphere point with z <= -near.
// light_eye: light centre in eye space (camera looks down -Z); radius >= 0.
// p00 = P[0][0], p11 = P[1][1] of the symmetric perspective projection (ndc_x = p00*x/(-z)).
// Results: empty when no sphere point lies at z <= -near; the whole viewport when the eye is
// inside the sphere (and the sphere reaches past the near plane); otherwise the exact bounding
// box of the projected region, clamped to [0,width] x [0,height].
// Throws dsr::Error on non-finite input, radius < 0, p00/p11/near_plane <= 0 or a negative size.
ScissorRect light_scissor(glm::vec3 light_eye, float radius, float p00, float p11,
                          float near_plane, int width, int height);

// A sphere in eye space, for light_scissors.
struct EyeSphere {
    glm::vec3 centre{0};
    float radius = 0;
};

// light_scissor for n spheres at once (make_frame's lights): rects[i] is
// light_scissor(spheres[i].centre, spheres[i].radius, ...), the same arithmetic a pair of lights
// at a time in SIMD lanes, so that one light's divisions and square roots need not wait on the
// last's. Throws as light_scissor does, for the first bad sphere, before writing any rectangle.
void light_scissors(const EyeSphere* spheres, size_t n, float p00, float p11, float near_plane, int width,
                    int height, ScissorRect* rects);

// The pixel rectangle of a region whose eye-space points (all at z <= -near) have x / (-z) in
// [xlo, xhi] and y / (-z) in [ylo, yhi]: the same outward rounding and clamping as light_scissor.
// xlo > xhi (no point) gives an empty rectangle. light_volume.cpp's cone rectangle uses it.
ScissorRect scissor_from_slopes(double xlo, double xhi, double ylo, double yhi, float p00, float p11,
                                int width, int height);

// Listing 16 as printed, kept only to measure its defects (docs/errata.md): float arithmetic,
// fixed e1 = 1.2 and e2 = 1.2*aspect (a fixed field of view), no near plane, no guards on the
// divisions by l.z and nx/ny, (int) truncation toward zero. The one change: a non-finite value
// about to be cast to int (undefined behaviour in C++) gives the full viewport instead, and a
// finite one is clamped to +-2^30 first. The rectangle is returned as the listing computes it
// (it may have x1 < x0 or y1 < y0; empty() is then true); a zero or negative area n returns {}.
ScissorRect light_scissor_listing16(glm::vec3 light_eye, float radius, float aspect, int width,
                                    int height);

}  // namespace dsr
