// Light volumes (src/deferred/light_volume.h) against brute force: the sphere's rectangle is
// light_scissor's; the cone's rectangle holds every densely sampled cone point that can be a
// visible surface point (z <= -near; camera far, near and inside the cone) and is never larger than
// its bounding sphere's; the meshes are closed, convex, outward and enclose the volume; culling
// never drops a volume that reaches into the frustum.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "analysis/sphere_samples.h"
#include "deferred/culling.h"
#include "deferred/light_volume.h"
#include "deferred/scissor.h"
#include "dsr_error.h"
#include "scene/light_law.h"

namespace {

using dsr::LightVolume;
using dsr::ScissorRect;

constexpr double kPi = 3.14159265358979323846;

double uni(std::mt19937_64& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }

glm::dvec3 random_unit(std::mt19937_64& rng) {
    for (;;) {
        glm::dvec3 v(uni(rng, -1, 1), uni(rng, -1, 1), uni(rng, -1, 1));
        const double l = glm::length(v);
        if (l > 0.1 && l <= 1) return v / l;
    }
}

LightVolume cone(glm::dvec3 apex, glm::dvec3 axis, double range, double angle_deg) {
    LightVolume v;
    v.kind = LightVolume::Kind::cone;
    v.pos = glm::vec3(apex);
    v.axis = glm::vec3(glm::normalize(axis));
    v.radius = float(range);
    v.half_angle = float(glm::radians(angle_deg));
    return v;
}

// Points of the cone (spherical sector): its cap, its side, its interior, and where it meets the
// plane z = -near (the rim of the visible part when it crosses the near plane).
std::vector<glm::dvec3> cone_samples(const LightVolume& v, double near_plane, std::mt19937_64& rng) {
    std::vector<glm::dvec3> out;
    const glm::dvec3 apex(v.pos), w = glm::normalize(glm::dvec3(v.axis));
    const glm::dvec3 a0 = std::abs(w.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(a0, w)), vv = glm::cross(w, u);
    const double R = v.radius, a = v.half_angle;
    auto dir = [&](double th, double ph) { return std::cos(th) * w + std::sin(th) * (std::cos(ph) * u + std::sin(ph) * vv); };
    out.push_back(apex);
    const int nph = 96, nth = 24;
    for (int i = 0; i < nph; ++i) {
        const double ph = 2 * kPi * (i + uni(rng, 0, 1)) / nph;
        for (int j = 0; j <= nth; ++j) {
            const double th = a * j / nth;
            out.push_back(apex + R * dir(th, ph));  // cap
        }
        for (int j = 1; j <= nth; ++j) out.push_back(apex + R * double(j) / nth * dir(a, ph));  // side
        // The side's generator where it crosses z = -near, if it does within the range.
        const glm::dvec3 g = dir(a, ph);
        if (g.z != 0) {
            const double t = (-near_plane - apex.z) / g.z;
            if (t > 0 && t <= R) out.push_back(glm::dvec3(apex.x + t * g.x, apex.y + t * g.y, -near_plane));
        }
    }
    for (int k = 0; k < 400; ++k)
        out.push_back(apex + R * std::cbrt(uni(rng, 0, 1)) * dir(std::acos(uni(rng, std::cos(a), 1)), uni(rng, 0, 2 * kPi)));
    // The ball's circle on z = -near and a disk of it, kept where inside the cone.
    const double dz = -near_plane - apex.z;
    if (std::abs(dz) < R) {
        const double rr = std::sqrt(R * R - dz * dz);
        auto keep = [&](glm::dvec3 p) {
            const glm::dvec3 d = p - apex;
            const double l = glm::length(d);
            if (l == 0 || glm::dot(d, w) >= l * std::cos(a) * (1 - 1e-12)) out.push_back(p);
        };
        for (int k = 0; k < 720; ++k) {
            const double ph = 2 * kPi * k / 720;
            keep(glm::dvec3(apex.x + rr * std::cos(ph), apex.y + rr * std::sin(ph), -near_plane));
        }
        for (int k = 0; k < 2000; ++k) {
            const double r = rr * std::sqrt(uni(rng, 0, 1)), ph = uni(rng, 0, 2 * kPi);
            keep(glm::dvec3(apex.x + r * std::cos(ph), apex.y + r * std::sin(ph), -near_plane));
        }
    }
    return out;
}

struct Cam {
    float p00, p11, near_plane;
    int w, h;
};

// Pixels of the samples at z <= -near that fall on screen, and their window-space bounding box.
struct Brute {
    long long points = 0, outside = 0;
    double minx = INFINITY, maxx = -INFINITY, miny = INFINITY, maxy = -INFINITY;
};
Brute project(const std::vector<glm::dvec3>& pts, const Cam& c, const ScissorRect& r) {
    Brute b;
    for (const glm::dvec3& p : pts) {
        if (p.z > -double(c.near_plane)) continue;
        ++b.points;
        const double wx = (c.p00 * p.x / -p.z + 1.0) * 0.5 * c.w, wy = (c.p11 * p.y / -p.z + 1.0) * 0.5 * c.h;
        b.minx = std::min(b.minx, wx), b.maxx = std::max(b.maxx, wx);
        b.miny = std::min(b.miny, wy), b.maxy = std::max(b.maxy, wy);
        const double px = std::floor(wx), py = std::floor(wy);
        if (px < 0 || px >= c.w || py < 0 || py >= c.h) continue;
        if (px < r.x0 || px >= r.x1 || py < r.y0 || py >= r.y1) ++b.outside;
    }
    return b;
}

TEST(LightVolume, SphereScissorIsLightScissor) {
    std::mt19937_64 rng(7);
    for (int i = 0; i < 2000; ++i) {
        LightVolume v;
        v.pos = glm::vec3(uni(rng, -10, 10), uni(rng, -10, 10), uni(rng, -20, 5));
        v.radius = float(uni(rng, 0.01, 8));
        const float p11 = float(uni(rng, 0.5, 3)), p00 = p11 * float(uni(rng, 0.5, 1.5)), n = float(uni(rng, 0.01, 1));
        const ScissorRect a = dsr::volume_scissor(v, p00, p11, n, 640, 480);
        const ScissorRect b = dsr::light_scissor(v.pos, v.radius, p00, p11, n, 640, 480);
        ASSERT_TRUE(a.x0 == b.x0 && a.x1 == b.x1 && a.y0 == b.y0 && a.y1 == b.y1) << "case " << i;
    }
}

TEST(LightVolume, FullScreenIsTheViewport) {
    LightVolume v;
    v.kind = LightVolume::Kind::full_screen;
    const ScissorRect r = dsr::volume_scissor(v, 1, 1, 0.1f, 64, 32);
    EXPECT_EQ(r.area(), 64 * 32);
    EXPECT_TRUE(dsr::volume_mesh(v).vertices.empty());
    EXPECT_FALSE(dsr::volume_outside(dsr::frustum_planes(glm::perspective(1.0f, 1.0f, 0.1f, 10.0f)), v));
}

// Random cones seen from random cameras: far away, with the apex near the eye, and with the eye
// inside the cone. Every sampled visible point's pixel must be in the rectangle; the rectangle
// must be inside the bounding sphere's; for cones wholly in front of the near plane and on screen
// it must be within a few pixels of the samples' bounding box (tight, not just conservative).
TEST(LightVolume, ConeScissorHoldsBruteForceAndBeatsItsSphere) {
    std::mt19937_64 rng(12);
    const Cam cams[2] = {{1.299f, 1.732f, 0.1f, 640, 480}, {0.8f, 0.8f, 0.5f, 317, 211}};
    long long cone_area = 0, sphere_area = 0, points = 0;
    int inside_cases = 0, near_cases = 0, tight_cases = 0;
    for (int i = 0; i < 600; ++i) {
        const Cam& c = cams[i % 2];
        const double angle = i % 7 == 0 ? 90.0 : uni(rng, 2, 89);
        const double R = uni(rng, 0.2, 6);
        glm::dvec3 apex, axis = random_unit(rng);
        const int mode = i % 3;
        if (mode == 0) apex = glm::dvec3(uni(rng, -6, 6), uni(rng, -6, 6), uni(rng, -15, -1));
        else if (mode == 1) apex = 0.3 * R * random_unit(rng);  // apex near the eye
        else {
            // Eye inside: the apex behind the eye along the axis, within range.
            axis = glm::normalize(glm::dvec3(uni(rng, -0.5, 0.5), uni(rng, -0.5, 0.5), -1.0) * (i % 2 ? 1.0 : -1.0));
            apex = -uni(rng, 0.05, 0.6) * R * axis;
        }
        const LightVolume v = cone(apex, axis, R, angle);
        const bool eye_inside = dsr::inside_volume(v, glm::dvec3(0));
        inside_cases += eye_inside;
        const ScissorRect r = dsr::volume_scissor(v, c.p00, c.p11, c.near_plane, c.w, c.h);
        const dsr::BoundingSphere bs = dsr::bounding_sphere(v);
        const ScissorRect s = dsr::light_scissor(bs.centre, bs.radius, c.p00, c.p11, c.near_plane, c.w, c.h);
        const auto pts = cone_samples(v, c.near_plane, rng);
        const Brute b = project(pts, c, r);
        points += b.points;
        ASSERT_EQ(b.outside, 0) << "case " << i << ": " << b.outside << " of " << b.points << " visible cone points"
                                << " outside the rectangle [" << r.x0 << "," << r.x1 << ")x[" << r.y0 << "," << r.y1 << ")";
        if (!r.empty()) {
            ASSERT_FALSE(s.empty()) << "case " << i;
            ASSERT_TRUE(r.x0 >= s.x0 && r.x1 <= s.x1 && r.y0 >= s.y0 && r.y1 <= s.y1) << "case " << i;
        }
        cone_area += r.area(), sphere_area += s.area();
        // Tightness where the cone is wholly in front of the near plane and well inside the view.
        bool in_front = true;
        for (const glm::dvec3& p : pts) in_front = in_front && p.z < -c.near_plane;
        if (in_front && b.minx > 0 && b.maxx < c.w && b.miny > 0 && b.maxy < c.h) {
            ++tight_cases;
            const double slack_x = 3 + 0.02 * (b.maxx - b.minx), slack_y = 3 + 0.02 * (b.maxy - b.miny);
            EXPECT_LE(b.minx - r.x0, slack_x) << "case " << i;
            EXPECT_LE(r.x1 - b.maxx, slack_x) << "case " << i;
            EXPECT_LE(b.miny - r.y0, slack_y) << "case " << i;
            EXPECT_LE(r.y1 - b.maxy, slack_y) << "case " << i;
        } else if (!in_front) {
            ++near_cases;
        }
    }
    std::printf("cone rectangles: %lld px vs bounding spheres' %lld px (%.2f); %d eye-inside, %d crossing near, "
                "%d tightness cases, %lld points\n",
                cone_area, sphere_area, double(cone_area) / double(sphere_area), inside_cases, near_cases, tight_cases, points);
    EXPECT_GT(inside_cases, 50);
    EXPECT_GT(tight_cases, 50);
    EXPECT_LT(cone_area, sphere_area);
}

// A narrow spot seen side on: its rectangle is a thin fraction of its bounding sphere's.
TEST(LightVolume, NarrowConeRectangleIsFarSmallerThanItsSphere) {
    // Half-angle 6 degrees, range 4, 8 in front: about 4 x 0.84 against the sphere's 4.02 x 4.02.
    const LightVolume v = cone(glm::dvec3(-2, 0, -8), glm::dvec3(1, 0, 0), 4, 6);
    const ScissorRect r = dsr::volume_scissor(v, 1.732f, 1.732f, 0.1f, 512, 512);
    const dsr::BoundingSphere b = dsr::bounding_sphere(v);
    const ScissorRect s = dsr::light_scissor(b.centre, b.radius, 1.732f, 1.732f, 0.1f, 512, 512);
    std::printf("[ stats    ] 6-degree cone side on: %lld px, its bounding sphere %lld px\n", r.area(), s.area());
    EXPECT_LT(double(r.area()), 0.3 * double(s.area())) << r.area() << " vs " << s.area();
    EXPECT_GT(r.area(), 0);
}

// Edges of a closed surface: each directed edge once, its reverse once.
void expect_closed_convex_outward(const dsr::VolumeMesh& m, glm::dvec3 interior, const char* what) {
    std::map<std::pair<uint32_t, uint32_t>, int> edges;
    double min_out = INFINITY;
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        for (int e = 0; e < 3; ++e) ++edges[{m.indices[t + e], m.indices[t + (e + 1) % 3]}];
        const glm::dvec3 a(m.vertices[m.indices[t]]), b(m.vertices[m.indices[t + 1]]), c(m.vertices[m.indices[t + 2]]);
        const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
        min_out = std::min(min_out, glm::dot(n, a - interior));
        for (const glm::vec3& q : m.vertices)  // convex: no vertex in front of any face
            ASSERT_LE(glm::dot(n, glm::dvec3(q) - a), 1e-4 * (1 + glm::length(a - interior))) << what;
    }
    EXPECT_GT(min_out, 0) << what << ": a face turned inward";
    for (const auto& [e, n] : edges) {
        ASSERT_EQ(n, 1) << what << ": edge used twice the same way";
        ASSERT_EQ(edges.count({e.second, e.first}), 1u) << what << ": open edge";
    }
}

bool inside_mesh(const dsr::VolumeMesh& m, glm::dvec3 p) {
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::dvec3 a(m.vertices[m.indices[t]]), b(m.vertices[m.indices[t + 1]]), c(m.vertices[m.indices[t + 2]]);
        const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
        if (glm::dot(n, p - a) > 1e-9 * (1 + glm::length(a))) {
            std::printf("point (%.9g %.9g %.9g) %.3g in front of face %zu (%u %u %u)\n", p.x, p.y, p.z, glm::dot(n, p - a),
                        t / 3, m.indices[t], m.indices[t + 1], m.indices[t + 2]);
            return false;
        }
    }
    return true;
}

TEST(LightVolume, MeshesAreClosedConvexAndEncloseTheVolume) {
    std::mt19937_64 rng(3);
    for (int i = 0; i < 60; ++i) {
        const int segments = 3 + i % 30;
        LightVolume v;
        if (i % 2 == 0) {
            v.pos = glm::vec3(uni(rng, -5, 5), uni(rng, -5, 5), uni(rng, -5, 5));
            v.radius = float(uni(rng, 0.1, 10));
        } else {
            const double angles[] = {1, 10, 30, 44.9, 45, 60, 75, 85, 89.9, 90};
            v = cone(glm::dvec3(uni(rng, -5, 5), uni(rng, -5, 5), uni(rng, -5, 5)), random_unit(rng), uni(rng, 0.1, 10),
                     angles[(i / 2) % 10]);
        }
        const dsr::VolumeMesh m = dsr::volume_mesh(v, segments);
        ASSERT_GT(m.triangles(), 0u);
        const glm::dvec3 interior = v.kind == LightVolume::Kind::sphere
                                        ? glm::dvec3(v.pos)
                                        : glm::dvec3(v.pos) + 0.5 * double(v.radius) * std::cos(0.5 * double(v.half_angle)) * glm::dvec3(v.axis);
        expect_closed_convex_outward(m, interior, v.kind == LightVolume::Kind::sphere ? "sphere" : "cone");
        const auto pts = v.kind == LightVolume::Kind::sphere
                             ? dsr::sphere_samples(glm::dvec3(v.pos), v.radius, 1e9, {800, 200, 0}, rng)
                             : cone_samples(v, 1e9, rng);
        const dsr::BoundingSphere b = dsr::bounding_sphere(v);
        for (const glm::dvec3& p : pts) {
            ASSERT_TRUE(inside_mesh(m, p)) << "case " << i << " (" << segments << " segments): point outside the mesh";
            ASSERT_LE(glm::length(p - glm::dvec3(b.centre)), double(b.radius) * (1 + 1e-6)) << "case " << i;
        }
        // Not absurdly loose: the mesh's farthest vertex within 1/cos^2(pi/segments) + rounding of
        // the radius (sphere) or range (cone) from the centre/apex, for meshes of 8 or more segments.
        if (segments >= 8) {
            double far = 0;
            for (const glm::vec3& q : m.vertices) far = std::max(far, double(glm::length(q - v.pos)));
            const double c = std::cos(kPi / segments);
            EXPECT_LE(far, double(v.radius) / (c * c) * 1.01) << "case " << i;
        }
    }
}

TEST(LightVolume, BoundingSphereIsTheSmallestForTheCone) {
    // Below 45 degrees the apex and the rim lie on the sphere; from 45 on the rim is a great circle.
    const dsr::BoundingSphere a = dsr::bounding_sphere(cone({0, 0, 0}, {0, 0, -1}, 2, 30));
    EXPECT_NEAR(a.radius, 2 / (2 * std::cos(glm::radians(30.0))), 1e-5);
    EXPECT_NEAR(a.centre.z, -a.radius, 1e-5);
    const dsr::BoundingSphere b = dsr::bounding_sphere(cone({0, 0, 0}, {0, 0, -1}, 2, 60));
    EXPECT_NEAR(b.radius, 2 * std::sin(glm::radians(60.0)), 1e-5);
    const dsr::BoundingSphere c = dsr::bounding_sphere(cone({0, 0, 0}, {0, 0, -1}, 2, 90));
    EXPECT_NEAR(c.radius, 2, 1e-5);
    EXPECT_NEAR(glm::length(c.centre), 0, 1e-5);
}

TEST(LightVolume, CullingKeepsEveryVolumeThatReachesTheFrustum) {
    const glm::mat4 vp = glm::perspective(glm::radians(60.0f), 1.333f, 0.1f, 50.0f) *
                         glm::lookAt(glm::vec3(0, 2, 6), glm::vec3(0), glm::vec3(0, 1, 0));
    const auto planes = dsr::frustum_planes(vp);
    std::mt19937_64 rng(5);
    int culled = 0;
    for (int i = 0; i < 1500; ++i) {
        const LightVolume v = cone(glm::dvec3(uni(rng, -30, 30), uni(rng, -30, 30), uni(rng, -30, 30)), random_unit(rng),
                                   uni(rng, 0.5, 15), uni(rng, 3, 90));
        const bool out = dsr::volume_outside(planes, v);
        culled += out;
        if (!out) continue;
        for (const glm::dvec3& p : cone_samples(v, 1e9, rng)) {
            const glm::dvec4 c = glm::dmat4(vp) * glm::dvec4(p, 1.0);
            const bool in = std::abs(c.x) <= c.w && std::abs(c.y) <= c.w && std::abs(c.z) <= c.w;
            ASSERT_FALSE(in) << "case " << i << ": culled a cone with a point inside the frustum";
        }
    }
    EXPECT_GT(culled, 100);
    // A narrow cone just outside the right plane, running along it: its bounding sphere (radius
    // ~4) reaches in, the cone (at least 1 - 8 sin 5deg = 0.3 outside) does not.
    const dsr::Plane right = planes[1];
    const glm::dvec3 cam(0, 2, 6), fwd = glm::normalize(-cam), n(right.n);
    glm::dvec3 q = cam + 5.0 * fwd;
    q -= (glm::dot(n, q) + double(right.d)) * n;
    const glm::dvec3 along = glm::normalize(fwd - glm::dot(fwd, n) * n);
    const LightVolume side = cone(q - 1.0 * n, along, 8, 5);
    EXPECT_FALSE(dsr::sphere_outside(planes, dsr::bounding_sphere(side).centre, dsr::bounding_sphere(side).radius));
    EXPECT_TRUE(dsr::volume_outside(planes, side));
}

TEST(LightVolume, FromLights) {
    dsr::Light l;
    l.type = dsr::Light::Type::spot;
    l.pos = {1, 2, 3};
    l.dir = {0, -2, 0};
    l.radius = 5;
    l.angle_deg = 30;
    const LightVolume v = dsr::light_volume(l);
    EXPECT_EQ(v.kind, LightVolume::Kind::cone);
    EXPECT_NEAR(v.axis.y, -1, 1e-6);
    EXPECT_NEAR(v.half_angle, glm::radians(30.0), 1e-6);
    l.angle_deg = 91;
    EXPECT_THROW(dsr::light_volume(l), dsr::Error);
    l.angle_deg = 30, l.dir = glm::vec3(0);
    EXPECT_THROW(dsr::light_volume(l), dsr::Error);
    l.type = dsr::Light::Type::directional, l.dir = {0, -1, 0};
    EXPECT_EQ(dsr::light_volume(l).kind, LightVolume::Kind::full_screen);
    // Eye space: the view's rotation turns the axis.
    l.type = dsr::Light::Type::spot;
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    const LightVolume e = dsr::transformed(dsr::light_volume(l), view);
    EXPECT_NEAR(e.pos.z, 3 - 5, 1e-5);
    EXPECT_NEAR(e.axis.y, -1, 1e-6);
}

// inside_volume is where the laws (scene/light_law.h) can be non-zero.
TEST(LightVolume, InsideIsWhereTheLawIsNonZero) {
    std::mt19937_64 rng(9);
    int lit = 0;
    for (int i = 0; i < 200; ++i) {
        dsr::Light l;
        l.type = i % 2 ? dsr::Light::Type::spot : dsr::Light::Type::point;
        l.pos = glm::vec3(uni(rng, -2, 2), uni(rng, -2, 2), uni(rng, -2, 2));
        l.dir = glm::vec3(random_unit(rng));
        l.radius = float(uni(rng, 0.5, 3));
        l.angle_deg = float(uni(rng, 5, 90));
        l.exponent = float(i % 3);
        if (i % 4 == 1) {
            l.attenuation = true, l.kc = 1, l.kl = 0.7f, l.kq = 1.8f;
        }
        const LightVolume v = dsr::light_volume(l);
        for (int k = 0; k < 500; ++k) {
            const glm::dvec3 p(uni(rng, -5, 5), uni(rng, -5, 5), uni(rng, -5, 5));
            const bool in = dsr::inside_volume(v, p);
            const double f = dsr::light_at(l, p).factor;
            ASSERT_EQ(in, f > 0) << "light " << i << " factor " << f;
            lit += in;
        }
    }
    EXPECT_GT(lit, 1000);
}

}  // namespace
