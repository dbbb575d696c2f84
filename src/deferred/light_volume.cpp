// Light volumes (docs/light_geometry.md): sphere, cone (spherical sector), full screen. The cone's rectangle and
// culling come from a convex mesh that encloses it, because the bounding sphere of a narrow cone is
// far larger than the cone; the sphere keeps the exact tangent-plane
// rectangle of scissor.cpp.
#include "deferred/light_volume.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dsr_error.h"

namespace dsr {
namespace {

constexpr double kPi = 3.14159265358979323846;

bool finite3(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A mesh in double, so enclosure holds to rounding before the float copy.
struct DMesh {
    std::vector<glm::dvec3> v;
    std::vector<uint32_t> idx;
};

// Any two unit vectors completing `w` to a right-handed frame.
void frame(glm::dvec3 w, glm::dvec3& u, glm::dvec3& v) {
    const glm::dvec3 a = std::abs(w.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    u = glm::normalize(glm::cross(a, w));
    v = glm::cross(w, u);
}

// Orients every triangle counter-clockwise seen from outside: its normal must point away from
// `interior`, a point strictly inside the convex mesh.
void orient(DMesh& m, glm::dvec3 interior) {
    for (size_t t = 0; t + 2 < m.idx.size(); t += 3) {
        const glm::dvec3 a = m.v[m.idx[t]], b = m.v[m.idx[t + 1]], c = m.v[m.idx[t + 2]];
        if (glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0 - interior) < 0)
            std::swap(m.idx[t + 1], m.idx[t + 2]);
    }
}

// Triangles of a ring strip: ring a (count n, first index ia) to ring b (ib), or to one point.
void strip(DMesh& m, uint32_t ia, uint32_t ib, int n) {
    for (int i = 0; i < n; ++i) {
        const uint32_t j = uint32_t((i + 1) % n);
        m.idx.insert(m.idx.end(), {ia + uint32_t(i), ib + uint32_t(i), ib + j});
        m.idx.insert(m.idx.end(), {ia + uint32_t(i), ib + j, ia + j});
    }
}
void fan(DMesh& m, uint32_t centre, uint32_t ring, int n) {
    for (int i = 0; i < n; ++i) m.idx.insert(m.idx.end(), {centre, ring + uint32_t(i), ring + uint32_t((i + 1) % n)});
}

// Points at polar angle `polar` from w, at unit distance from the origin.
void ring(DMesh& m, glm::dvec3 u, glm::dvec3 v, glm::dvec3 w, double polar, int n) {
    for (int i = 0; i < n; ++i) {
        const double az = 2.0 * kPi * i / n;
        m.v.push_back(std::sin(polar) * (std::cos(az) * u + std::sin(az) * v) + std::cos(polar) * w);
    }
}

// Unit normal and plane offset (from `origin`) of triangle t.
void face_plane(const DMesh& m, size_t t, glm::dvec3 origin, glm::dvec3& n, double& c) {
    const glm::dvec3 a = m.v[m.idx[t]], b = m.v[m.idx[t + 1]], cc = m.v[m.idx[t + 2]];
    n = glm::normalize(glm::cross(b - a, cc - a));
    c = glm::dot(n, a - origin);
}

// Support of the unit-range sector of half-angle `a` about +w in direction n (unit): the largest
// dot(n, x) over its points. Within a of the axis the cap point along n; else the nearest cone
// generator if it is less than 90 degrees from n; else the apex.
double sector_support(glm::dvec3 n, glm::dvec3 w, double a) {
    const double psi = std::acos(std::clamp(glm::dot(n, w), -1.0, 1.0));
    if (psi <= a) return 1.0;
    const double phi = psi - a;
    return phi < 0.5 * kPi ? std::cos(phi) : 0.0;
}

// Scales the convex mesh about `interior` until every face plane has moved out by at least
// 1e-6 * (size + |interior|): well over float's relative rounding (6e-8) of the coordinates, so
// the float copy still encloses the volume, boundary points included.
void inflate(DMesh& m, glm::dvec3 interior, double size) {
    const double margin = 1e-6 * (size + glm::length(interior));
    double dmin = INFINITY;
    for (size_t t = 0; t < m.idx.size(); t += 3) {
        glm::dvec3 n;
        double off;
        face_plane(m, t, interior, n, off);
        dmin = std::min(dmin, off);
    }
    const double k = 1.0 + margin / dmin;
    for (glm::dvec3& p : m.v) p = interior + k * (p - interior);
}

DMesh sphere_mesh(glm::dvec3 c, double r, int segments) {
    DMesh m;
    const int stacks = std::max(2, segments / 2);
    const glm::dvec3 u(1, 0, 0), v(0, 1, 0), w(0, 0, 1);
    m.v.push_back(w);  // 0: north pole
    for (int i = 1; i < stacks; ++i) ring(m, u, v, w, kPi * i / stacks, segments);
    m.v.push_back(-w);
    const uint32_t south = uint32_t(m.v.size() - 1);
    fan(m, 0, 1, segments);
    for (int i = 1; i + 1 < stacks; ++i) strip(m, 1 + uint32_t((i - 1) * segments), 1 + uint32_t(i * segments), segments);
    fan(m, south, 1 + uint32_t((stacks - 2) * segments), segments);
    orient(m, glm::dvec3(0));
    // Each face of the unit mesh cuts inside the unit sphere by its plane offset; scale until the
    // nearest face plane is at r (a convex mesh whose face planes all clear the ball encloses it).
    double dmin = 1.0;
    for (size_t t = 0; t < m.idx.size(); t += 3) {
        glm::dvec3 n;
        double off;
        face_plane(m, t, glm::dvec3(0), n, off);
        dmin = std::min(dmin, off);
    }
    const double s = r / dmin;
    for (glm::dvec3& p : m.v) p = c + s * p;
    inflate(m, c, r);
    return m;
}

DMesh cone_mesh(glm::dvec3 apex, glm::dvec3 w, double range, double a, int segments) {
    DMesh m;
    glm::dvec3 u, v;
    frame(w, u, v);
    // The side fan's ring: its faces are tangent to the circular cone when the ring's polar angle
    // a' has tan a' = tan a / cos(pi / n) (a' < 90 degrees for every a < 90; at 90 the fan is
    // the flat disc under the hemisphere).
    const double edge = a >= 0.5 * kPi ? 0.5 * kPi : std::atan(std::tan(a) / std::cos(kPi / segments));
    const int rings = std::max(1, int(std::ceil(edge / (2.0 * kPi / segments))));
    m.v.push_back(glm::dvec3(0));  // 0: apex
    for (int j = 0; j < rings; ++j) ring(m, u, v, w, edge * (1.0 - double(j) / rings), segments);
    m.v.push_back(w);  // tip on the axis
    const uint32_t tip = uint32_t(m.v.size() - 1);
    fan(m, 0, 1, segments);
    for (int j = 0; j + 1 < rings; ++j) strip(m, 1 + uint32_t(j * segments), 1 + uint32_t((j + 1) * segments), segments);
    fan(m, tip, 1 + uint32_t((rings - 1) * segments), segments);
    orient(m, 0.5 * std::cos(0.5 * edge) * w);
    // Scale about the apex until every cap face clears the sector (faces through the apex are
    // the tangent side and keep their planes under the scale).
    double s = 0;
    for (size_t t = 0; t < m.idx.size(); t += 3) {
        if (m.idx[t] == 0 || m.idx[t + 1] == 0 || m.idx[t + 2] == 0) continue;
        glm::dvec3 n;
        double off;
        face_plane(m, t, glm::dvec3(0), n, off);
        s = std::max(s, sector_support(n, w, a) / off);
    }
    s *= range;
    for (glm::dvec3& p : m.v) p = apex + s * p;
    inflate(m, apex + 0.5 * range * std::cos(0.5 * edge) * w, range);
    return m;
}

DMesh make_mesh(const LightVolume& vol, int segments) {
    if (segments < 3) throw Error("volume_mesh: need at least 3 segments, got " + std::to_string(segments));
    if (vol.kind == LightVolume::Kind::full_screen || !(vol.radius > 0)) return {};
    if (vol.kind == LightVolume::Kind::sphere) return sphere_mesh(glm::dvec3(vol.pos), vol.radius, segments);
    return cone_mesh(glm::dvec3(vol.pos), glm::normalize(glm::dvec3(vol.axis)), vol.radius, vol.half_angle, segments);
}

// Segments of the mesh the cone's rectangle and culling use: 1 - cos(pi/32) ~ 0.5% looser than
// the cone at most.
constexpr int kBoundSegments = 32;

}  // namespace

LightVolume light_volume(const Light& light) {
    LightVolume v;
    if (light.type == Light::Type::directional) {
        if (!finite3(light.dir) || glm::length(light.dir) == 0)
            throw Error("light_volume: a directional light needs a non-zero direction");
        v.kind = LightVolume::Kind::full_screen;
        v.axis = glm::normalize(light.dir);
        v.radius = std::numeric_limits<float>::infinity();
        return v;
    }
    if (!finite3(light.pos) || !std::isfinite(light.radius) || light.radius < 0)
        throw Error("light_volume: need a finite position and a finite radius >= 0");
    v.pos = light.pos;
    v.radius = light.radius;
    if (light.type == Light::Type::point) return v;
    if (!finite3(light.dir) || glm::length(light.dir) == 0)
        throw Error("light_volume: a spot light needs a non-zero direction");
    if (!(light.angle_deg > 0 && light.angle_deg <= 90))
        throw Error("light_volume: a spot light's angle must be in (0, 90], got " + std::to_string(light.angle_deg));
    v.kind = LightVolume::Kind::cone;
    v.axis = glm::normalize(light.dir);
    v.half_angle = float(glm::radians(double(light.angle_deg)));
    return v;
}

LightVolume transformed(const LightVolume& v, const glm::mat4& m) {
    LightVolume t = v;
    t.pos = glm::vec3(m * glm::vec4(v.pos, 1.0f));
    t.axis = glm::normalize(glm::mat3(m) * v.axis);
    return t;
}

LightVolume to_eye(const LightVolume& v, const Camera& camera) { return to_eye(v, EyeTransform(camera)); }

LightVolume to_eye(const LightVolume& v, const EyeTransform& eye) {
    // A sphere has no axis to turn (at 4096 lights, the float transform was a tenth of make_frame).
    LightVolume t = v.kind == LightVolume::Kind::sphere ? v : transformed(v, eye.view);
    t.pos = eye.to_eye(v.pos);
    return t;
}

BoundingSphere bounding_sphere(const LightVolume& v) {
    if (v.kind == LightVolume::Kind::full_screen) return {v.pos, std::numeric_limits<float>::infinity()};
    if (v.kind == LightVolume::Kind::sphere) return {v.pos, v.radius};
    const double a = v.half_angle, r = v.radius;
    const glm::dvec3 apex(v.pos), w = glm::normalize(glm::dvec3(v.axis));
    double along, radius;
    if (a < 0.25 * kPi) along = radius = r / (2.0 * std::cos(a));  // apex and rim on the sphere
    else along = r * std::cos(a), radius = r * std::sin(a);           // the rim is a great circle
    // Rounding to float must not shrink it: a relative margin far below any pixel.
    return {glm::vec3(apex + along * w), float(radius * (1.0 + 1e-6))};
}

bool volume_outside(const FrustumTest& frustum, const LightVolume& v) {
    if (v.kind == LightVolume::Kind::full_screen) return false;
    if (v.kind == LightVolume::Kind::sphere) return frustum.sphere_outside(v.pos, v.radius);
    const BoundingSphere b = bounding_sphere(v);
    if (frustum.sphere_outside(b.centre, b.radius)) return true;
    return frustum.all_outside_one_plane(make_mesh(v, kBoundSegments).v);
}

bool volume_outside(const std::array<Plane, 6>& planes, const LightVolume& v) {
    return volume_outside(FrustumTest(planes), v);
}

ScissorRect volume_scissor(const LightVolume& v, float p00, float p11, float near_plane, int width, int height) {
    if (v.kind == LightVolume::Kind::full_screen) {
        if (width <= 0 || height <= 0) return {};
        return {0, 0, width, height};
    }
    if (v.kind == LightVolume::Kind::sphere) return light_scissor(v.pos, v.radius, p00, p11, near_plane, width, height);
    const BoundingSphere b = bounding_sphere(v);
    const ScissorRect rs = light_scissor(b.centre, b.radius, p00, p11, near_plane, width, height);
    if (rs.empty()) return {};
    // The enclosing mesh clipped to z <= -near is a convex polytope; a perspective projection maps
    // it to the convex hull of its vertices' images, so their slope ranges bound the cone's.
    const DMesh m = make_mesh(v, kBoundSegments);
    const double n = near_plane;
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    auto add = [&](glm::dvec3 p) {
        const double wz = -p.z;  // >= near > 0
        xlo = std::min(xlo, p.x / wz), xhi = std::max(xhi, p.x / wz);
        ylo = std::min(ylo, p.y / wz), yhi = std::max(yhi, p.y / wz);
    };
    for (const glm::dvec3& p : m.v)
        if (p.z <= -n) add(p);
    for (size_t t = 0; t < m.idx.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            const glm::dvec3 a = m.v[m.idx[t + e]], c = m.v[m.idx[t + (e + 1) % 3]];
            if ((a.z < -n) != (c.z < -n)) {  // the edge crosses the near plane
                const double s = (-n - a.z) / (c.z - a.z);
                glm::dvec3 q = a + s * (c - a);
                q.z = -n;
                add(q);
            }
        }
    ScissorRect r = scissor_from_slopes(xlo, xhi, ylo, yhi, p00, p11, width, height);
    r.x0 = std::max(r.x0, rs.x0), r.y0 = std::max(r.y0, rs.y0);
    r.x1 = std::min(r.x1, rs.x1), r.y1 = std::min(r.y1, rs.y1);
    if (r.empty()) return {};
    return r;
}

VolumeMesh volume_mesh(const LightVolume& v, int segments) {
    const DMesh d = make_mesh(v, segments);
    VolumeMesh m;
    m.vertices.reserve(d.v.size());
    for (const glm::dvec3& p : d.v) m.vertices.push_back(glm::vec3(p));
    m.indices = d.idx;
    return m;
}

bool inside_volume(const LightVolume& v, glm::dvec3 p) {
    if (v.kind == LightVolume::Kind::full_screen) return true;
    const glm::dvec3 d = p - glm::dvec3(v.pos);
    const double r = v.radius, d2 = glm::dot(d, d);
    if (!(d2 < r * r)) return false;
    if (v.kind == LightVolume::Kind::sphere) return true;
    const double len = std::sqrt(d2);
    return len > 0 && glm::dot(d, glm::normalize(glm::dvec3(v.axis))) > len * std::cos(double(v.half_angle));
}

bool volume_reaches(const LightVolume& v, glm::vec3 centre, float radius) {
    if (v.kind == LightVolume::Kind::full_screen) return true;
    const BoundingSphere b = bounding_sphere(v);
    return glm::length(centre - b.centre) <= radius + b.radius;
}

}  // namespace dsr
