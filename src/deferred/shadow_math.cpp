// Shadow maps' projections and lookups (shadow_math.h).
#include "deferred/shadow_math.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "deferred/culling.h"

namespace dsr {

namespace {

// An up vector not parallel to `f` (glm::lookAt needs one).
glm::dvec3 up_for(const glm::dvec3& f) {
    return std::fabs(f.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
}

// The directional map's extent, rounded up to the ladder 2^(k/4): while the view's part of the
// scene changes a little, the extent (so the texel size) stays the same.
double ladder(double e) { return std::exp2(std::ceil(std::log2(std::max(e, 1e-30)) * 4.0) / 4.0); }

}  // namespace

ShadowFit shadow_fit(const Camera& camera, float aspect, const std::vector<ObjectBounds>& objects) {
    ShadowFit fit;
    const glm::dmat4 proj = glm::perspective(glm::radians(double(camera.fov_deg)), double(aspect),
                                             double(camera.near_plane), double(camera.far_plane));
    const glm::dmat4 inv = glm::inverse(proj * camera.view_d());
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 ndc((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1, 1);
        const glm::dvec4 w = inv * ndc;
        fit.frustum[size_t(i)] = glm::dvec3(w) / w.w;
    }
    const double inf = std::numeric_limits<double>::infinity();
    fit.lo = glm::dvec3(inf), fit.hi = glm::dvec3(-inf);
    for (const ObjectBounds& b : objects) {
        fit.lo = glm::min(fit.lo, glm::dvec3(b.centre) - double(b.radius));
        fit.hi = glm::max(fit.hi, glm::dvec3(b.centre) + double(b.radius));
        fit.empty = false;
    }
    if (fit.empty) fit.lo = fit.hi = glm::dvec3(0);
    return fit;
}

glm::dvec3 cube_face_axis(int face) {
    glm::dvec3 a(0);
    a[face / 2] = (face % 2) ? -1 : 1;
    return a;
}

glm::dvec3 cube_face_up(int face) { return face / 2 == 1 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0); }

int cube_face(const glm::dvec3& d) {
    const glm::dvec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x >= 0 ? 0 : 1;
    if (a.y >= a.z) return d.y >= 0 ? 2 : 3;
    return d.z >= 0 ? 4 : 5;
}

glm::dvec2 cube_face_uv(const glm::dvec3& d, int face) {
    // glm::lookAt's frame: s = cross(f, up), u = cross(s, f); the 90-degree projection maps
    // (d.s, d.u) / (d.f) in [-1, 1] to the face.
    const glm::dvec3 f = cube_face_axis(face);
    const glm::dvec3 s = glm::normalize(glm::cross(f, cube_face_up(face)));
    const glm::dvec3 u = glm::cross(s, f);
    const double z = glm::dot(d, f);
    return glm::dvec2(glm::dot(d, s), glm::dot(d, u)) / z * 0.5 + 0.5;
}

ShadowLayout shadow_layout(const Light& light, int size, const ShadowFit& fit, int max_texture) {
    ShadowLayout s;
    const glm::dvec3 pos(light.pos), dir = glm::normalize(glm::dvec3(light.dir));
    const double radius = light.radius;
    const bool cube = light.type == Light::Type::point ||
                      (light.type == Light::Type::spot && light.angle_deg > kSpotCubeAngle);
    if (cube) {
        s.kind = ShadowKind::cube;
        s.face = std::min(size, max_texture / 3);
        s.width = 3 * s.face, s.height = 2 * s.face;
        s.light = glm::translate(glm::dmat4(1.0), -pos);
        const double n = std::max(radius * 1e-3, 1e-6);
        for (int f = 0; f < 6; ++f)
            s.views.push_back({glm::lookAt(pos, pos + cube_face_axis(f), cube_face_up(f)),
                               glm::perspective(glm::radians(90.0), 1.0, n, radius)});
        s.depth = glm::vec3(float(1.0 / radius), 0, 0);
        s.texel = glm::vec2(0, float(2.0 / s.face));
        return s;
    }
    s.face = std::min(size, max_texture);
    s.width = s.height = s.face;
    if (light.type == Light::Type::spot) {
        s.kind = ShadowKind::perspective;
        // One texel beyond the cone on every side, so a filtered lookup at its edge stays on the map.
        const double half = std::atan(std::tan(glm::radians(double(light.angle_deg))) * (1.0 + 2.0 / s.face));
        const double n = std::max(radius * 1e-3, 1e-6);
        s.light = glm::lookAt(pos, pos + dir, up_for(dir));
        s.views.push_back({s.light, glm::perspective(2.0 * half, 1.0, n, radius)});
        s.depth = glm::vec3(float(1.0 / radius), 0, 0);
        s.texel = glm::vec2(0, float(2.0 * std::tan(half) / s.face));
        return s;
    }
    // Directional: a fixed frame (the world origin, the light's direction), so the texel grid
    // moves only with the ladder's extent.
    s.kind = ShadowKind::ortho;
    s.light = glm::lookAt(glm::dvec3(0), dir, up_for(dir));
    const double inf = std::numeric_limits<double>::infinity();
    glm::dvec3 flo(inf), fhi(-inf), blo(inf), bhi(-inf);
    for (const glm::dvec3& c : fit.frustum) {
        const glm::dvec3 q = glm::dvec3(s.light * glm::dvec4(c, 1));
        flo = glm::min(flo, q), fhi = glm::max(fhi, q);
    }
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 c((i & 1) ? fit.hi.x : fit.lo.x, (i & 2) ? fit.hi.y : fit.lo.y, (i & 4) ? fit.hi.z : fit.lo.z);
        const glm::dvec3 q = glm::dvec3(s.light * glm::dvec4(c, 1));
        blo = glm::min(blo, q), bhi = glm::max(bhi, q);
    }
    // Across the light: what the camera sees of the scene (the two boxes' overlap); along it, the
    // whole scene, every caster in front of what is seen.
    glm::dvec2 lo = glm::max(glm::dvec2(flo), glm::dvec2(blo)), hi = glm::min(glm::dvec2(fhi), glm::dvec2(bhi));
    if (!(hi.x > lo.x && hi.y > lo.y)) lo = glm::dvec2(blo), hi = glm::dvec2(bhi);
    const double e = ladder(std::max(std::max(hi.x - lo.x, hi.y - lo.y), 1e-6) * (1.0 + 4.0 / s.face));
    const double t = e / s.face;
    const double x0 = std::floor(lo.x / t) * t, y0 = std::floor(lo.y / t) * t;
    const double margin = std::max((bhi.z - blo.z) * 1e-3, 1e-6);
    const double n = -bhi.z - margin, f = -blo.z + margin;
    s.views.push_back({s.light, glm::ortho(x0, x0 + e, y0, y0 + e, n, f)});
    s.depth = glm::vec3(0, float(1.0 / (f - n)), float(-n / (f - n)));
    s.texel = glm::vec2(float(t), 0);
    return s;
}

double shadow_depth(const ShadowLayout& s, const glm::dvec3& p) {
    const glm::dvec3 q = glm::dvec3(s.light * glm::dvec4(p, 1));
    return double(s.depth.x) * glm::length(q) + double(s.depth.y) * -q.z + double(s.depth.z);
}

glm::dvec2 shadow_uv(const ShadowLayout& s, const glm::dvec3& p) {
    const glm::dvec3 q = glm::dvec3(s.light * glm::dvec4(p, 1));
    if (s.kind == ShadowKind::cube) {
        const int f = cube_face(q);
        const glm::dvec2 uv = glm::clamp(cube_face_uv(q, f), 0.0, 1.0);
        return glm::dvec2((f % 3 + uv.x) / 3.0, (f / 3 + uv.y) / 2.0);
    }
    const glm::dvec4 c = s.views[0].proj * glm::dvec4(q, 1);
    return glm::dvec2(c) / c.w * 0.5 + 0.5;
}

double shadow_receiver_depth(const ShadowLayout& s, const LightShadow& sh, const glm::dvec3& p,
                             const glm::dvec3& n, const glm::dvec3& l) {
    const glm::dvec3 q = glm::dvec3(s.light * glm::dvec4(p, 1));
    const glm::dvec3 a = glm::abs(q);
    const double axis = s.kind == ShadowKind::cube ? std::max(a.x, std::max(a.y, a.z)) : -q.z;
    const double texel = double(s.texel.x) + double(s.texel.y) * axis;
    const double c = std::clamp(glm::dot(n, l), 1e-6, 1.0);
    const double tangent = std::min(std::sqrt(1.0 - c * c) / c, double(kMaxShadowTangent));
    const double per_unit = double(s.depth.x) + double(s.depth.y);
    return shadow_depth(s, p) - double(sh.bias) - double(sh.slope) * texel * tangent * per_unit;
}

bool shadow_view_culls(const ShadowView& v, const ObjectBounds& b) {
    return sphere_outside(frustum_planes(glm::mat4(v.proj * v.view)), b.centre, b.radius);
}

}  // namespace dsr
