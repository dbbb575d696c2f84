// The analytic reference's shadow rays (src/analysis/analytic_reference.h) against closed forms
// that share none of its ray code: the shadow of a box under a directional light is the convex
// hull of its corners projected along the light onto the floor; the shadow of a ball under a
// point light is where the segment to the light passes within r of the centre. No GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analysis/analytic_reference.h"
#include "render_fixture.h"

using namespace dsr;
using namespace dsr::test;
using dvec3 = glm::dvec3;

namespace {
constexpr int kSize = 97;

Material matte() {
    Material m;
    m.name = "m";
    m.diffuse = glm::vec3(0.6f);
    m.specular = glm::vec3(0.3f);
    m.shininess = 16;
    return m;
}

// A floor seen from above and in front, nothing else yet.
Scene floor_scene() {
    Scene s;
    s.camera.pos = {0, 7, 4};
    s.camera.target = {0, 0, 0};
    s.camera.up = {0, 1, 0};
    s.camera.fov_deg = 55;
    s.camera.near_plane = 0.5f;
    s.camera.far_plane = 30;
    s.ambient = glm::vec3(0.1f);
    s.background = {0.2f, 0.3f, 0.4f};
    s.materials.push_back(matte());
    add_plane(s, 12, {0, 0, 0}, 0);
    return s;
}

Light point_light(glm::vec3 pos, glm::vec3 color, float radius) {
    Light l;
    l.pos = pos;
    l.color = color;
    l.radius = radius;
    return l;
}

Light shadowed(Light l) {
    l.shadow.on = true;
    return l;
}

// World position of pixel (i, j)'s hit, from the trace's eye depth: the camera of
// Camera::view() / projection() written out (lookAt frame, vertical fov, aspect 1).
dvec3 hit_point(const Camera& c, int n, int i, int j, double eye_depth) {
    const dvec3 f = glm::normalize(dvec3(c.target) - dvec3(c.pos));
    const dvec3 s = glm::normalize(glm::cross(f, dvec3(c.up)));
    const dvec3 u = glm::cross(s, f);
    const double t = std::tan(double(c.fov_deg) * M_PI / 360.0);
    const dvec3 d = f + ((i + 0.5) / n * 2 - 1) * t * s + ((j + 0.5) / n * 2 - 1) * t * u;
    return dvec3(c.pos) + eye_depth * d;
}

// Signed distance of q from the convex polygon `hull` (counter-clockwise in (x, z) taken as a
// plane's (x, y)): negative inside.
double hull_distance(const std::vector<glm::dvec2>& hull, glm::dvec2 q) {
    double inside = -std::numeric_limits<double>::infinity(), outside = std::numeric_limits<double>::infinity();
    bool in = true;
    for (size_t k = 0; k < hull.size(); ++k) {
        const glm::dvec2 a = hull[k], b = hull[(k + 1) % hull.size()], e = b - a;
        const glm::dvec2 nrm = glm::normalize(glm::dvec2(e.y, -e.x));  // outward for this winding
        const double side = glm::dot(q - a, nrm);
        in = in && side <= 0;
        inside = std::max(inside, side);
        const double t = std::clamp(glm::dot(q - a, e) / glm::dot(e, e), 0.0, 1.0);
        outside = std::min(outside, glm::length(q - (a + t * e)));
    }
    return in ? inside : outside;
}

// Convex hull (Andrew's monotone chain), counter-clockwise in (x, z) taken as (x, y).
std::vector<glm::dvec2> convex_hull(std::vector<glm::dvec2> p) {
    std::sort(p.begin(), p.end(), [](auto a, auto b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    auto cross = [](glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
    std::vector<glm::dvec2> h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);
    return h;
}
}  // namespace

// By hand: a plane seen from straight above (65x65, 60 degrees, eye 5 up), a light 1 above its
// centre and a 0.1 box centred 0.5 up. Along the middle row the floor point of pixel i is at
// x_i = ((i + 0.5) / 65 * 2 - 1) tan 30 * 5: pixel 33 at x = 0.0888, whose segment to the light is
// at x = 0.0888 (1 - 0.45) = 0.049 < 0.05 at the box's bottom face (hidden); pixel 34 at 0.178,
// 0.098 at the bottom face and 0.080 at the top (lit). Pixel 32 sees the box's top, facing the
// light: lit, not hidden by its own box.
TEST(AnalyticShadows, HandComputedPixels) {
    Scene s = plane_from_above();  // the light 1 above the centre (render_fixture.h)
    add_box(s, {0.1f, 0.1f, 0.1f}, {0, 0.5f, 0}, 0);
    const int n = 65;
    auto at = [&](int i) { return size_t(32) * n + i; };
    const AnalyticTrace plain = analytic_trace(s, n, n);
    ASSERT_EQ(plain.occluded.size(), 1u);
    EXPECT_TRUE(plain.occluded[0].empty());  // no shadow rays for a light without `shadow`

    s.lights[0] = shadowed(s.lights[0]);
    const AnalyticTrace t = analytic_trace(s, n, n);
    ASSERT_EQ(t.occluded[0].size(), size_t(n) * n);
    ASSERT_EQ(t.mesh[at(32)], 1);
    ASSERT_EQ(t.mesh[at(33)], 0);
    ASSERT_EQ(t.mesh[at(34)], 0);
    EXPECT_EQ(t.occluded[0][at(32)], 0);
    EXPECT_EQ(t.occluded[0][at(33)], 1);
    EXPECT_EQ(t.occluded[0][at(34)], 0);
    // Hidden: the ambient term alone, 0.1 * 0.5. Lit: exactly the image without shadows.
    EXPECT_NEAR(t.image.at(33, 32)[0], 0.05, 1e-7);
    EXPECT_GT(plain.image.at(33, 32)[0], 0.3f);
    EXPECT_EQ(t.image.at(34, 32)[0], plain.image.at(34, 32)[0]);
    EXPECT_EQ(t.image.at(32, 32)[0], plain.image.at(32, 32)[0]);
    // The same on the other side and along the column (the box is symmetric).
    EXPECT_EQ(t.occluded[0][at(31)], 1);
    EXPECT_EQ(t.occluded[0][size_t(33) * n + 32], 1);
    // AnalyticOptions::shadows off: the light passes through the box, as before.
    AnalyticOptions off;
    off.shadows = false;
    const AnalyticTrace o = analytic_trace(s, n, n, off);
    EXPECT_TRUE(o.occluded[0].empty());
    EXPECT_EQ(o.image.at(33, 32)[0], plain.image.at(33, 32)[0]);
}

namespace {
// Compares the trace's occluded mask of light 0 on floor pixels with `inside(q)`, the signed
// distance of the floor point q from the closed-form shadow (negative inside); pixels within
// `margin` of its edge are skipped. Returns the number of floor pixels checked.
template <class F>
int check_floor(const Scene& s, const AnalyticTrace& t, F signed_distance, double margin, int* in_shadow) {
    int checked = 0;
    *in_shadow = 0;
    for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i) {
            const size_t p = size_t(j) * kSize + i;
            if (t.mesh[p] != 0) continue;
            const dvec3 q = hit_point(s.camera, kSize, i, j, t.eye_depth[p]);
            const double sd = signed_distance(q);
            if (std::fabs(sd) < margin) continue;
            ++checked;
            *in_shadow += sd < 0;
            EXPECT_EQ(int(t.occluded[0][p]), sd < 0 ? 1 : 0) << "pixel " << i << "," << j << " floor point (" << q.x
                                                             << ", " << q.z << ") at " << sd << " from the edge";
            if (::testing::Test::HasFailure()) return checked;
        }
    return checked;
}

// The corners of an axis-aligned box.
std::vector<dvec3> corners(glm::vec3 size, glm::vec3 at) {
    std::vector<dvec3> c;
    for (int k = 0; k < 8; ++k)
        c.push_back(dvec3(at) + dvec3((k & 1) ? 0.5 : -0.5, (k & 2) ? 0.5 : -0.5, (k & 4) ? 0.5 : -0.5) * dvec3(size));
    return c;
}
}  // namespace

// A box floating over the floor under a directional light: a floor pixel is occluded exactly
// when its point lies in the convex hull of the box's corners moved along the light onto the
// floor. Pixels within 1e-6 of the hull's edge are skipped; the exact box and its triangles agree.
TEST(AnalyticShadows, DirectionalBoxShadowIsTheProjectedHull) {
    Scene s = floor_scene();
    const glm::vec3 size(1.0f, 1.4f, 0.8f), at(0.3f, 1.0f, -0.5f);  // 0.3 above the floor
    add_box(s, size, at, 0);
    Light sun;
    sun.type = Light::Type::directional;
    sun.dir = glm::normalize(glm::vec3(0.6f, -1.0f, -0.35f));
    sun.color = glm::vec3(0.8f);
    s.lights.push_back(shadowed(sun));
    const dvec3 d(sun.dir);
    std::vector<glm::dvec2> proj;
    for (const dvec3& c : corners(size, at)) {
        const dvec3 q = c + (-c.y / d.y) * d;
        proj.push_back({q.x, q.z});
    }
    const std::vector<glm::dvec2> hull = convex_hull(proj);
    auto sd = [&](const dvec3& q) { return hull_distance(hull, {q.x, q.z}); };
    for (bool triangles : {false, true}) {
        AnalyticOptions o;
        o.triangles = triangles;
        const AnalyticTrace t = analytic_trace(s, kSize, kSize, o);
        int shadow = 0;
        const int n = check_floor(s, t, sd, 1e-6, &shadow);
        std::printf("[ shadows  ] directional, %s: %d floor pixels checked, %d in the shadow\n",
                    triangles ? "triangles" : "exact box", n, shadow);
        EXPECT_GT(n, kSize * kSize / 3);
        EXPECT_GT(shadow, 50);
    }
}

// A spot light above a box on the floor: occluded exactly where the point is inside the cone,
// within range, and in the hull of the box's corners projected from the light onto the floor.
// The box rests on the floor (its bottom face on the floor's plane): the floor beside it is not
// hidden by that shared plane, and the contact itself is traced without a gap.
TEST(AnalyticShadows, SpotBoxShadowIsTheCentralProjection) {
    Scene s = floor_scene();
    const glm::vec3 size(1.2f, 0.9f, 1.0f), at(-0.4f, 0.45f, 0.2f);
    add_box(s, size, at, 0);
    Light spot;
    spot.type = Light::Type::spot;
    spot.pos = {-2.0f, 3.5f, 1.5f};
    spot.dir = glm::normalize(glm::vec3(0.5f, -1.0f, -0.3f));
    spot.angle_deg = 40;
    spot.radius = 12;
    spot.color = glm::vec3(0.9f);
    s.lights.push_back(shadowed(spot));
    const dvec3 L(spot.pos), D = glm::normalize(dvec3(spot.dir));
    std::vector<glm::dvec2> proj;
    for (const dvec3& c : corners(size, at)) {
        const dvec3 q = L + (L.y / (L.y - c.y)) * (c - L);  // from the light through c to y = 0
        proj.push_back({q.x, q.z});
    }
    const std::vector<glm::dvec2> hull = convex_hull(proj);
    // How far q is inside the light's reach (cone and range; radians or units, > 0 inside).
    auto reach = [&](const dvec3& q) {
        const dvec3 l = q - L;
        return std::min(glm::radians(double(spot.angle_deg)) - std::acos(glm::dot(glm::normalize(l), D)),
                        double(spot.radius) - glm::length(l));
    };
    auto sd = [&](const dvec3& q) {
        const double in = reach(q);
        if (std::fabs(in) < 1e-6) return 0.0;  // on the cone's edge: skipped
        return in < 0 ? 1.0 : hull_distance(hull, {q.x, q.z});
    };
    const AnalyticTrace t = analytic_trace(s, kSize, kSize);
    int shadow = 0;
    const int n = check_floor(s, t, sd, 1e-6, &shadow);
    std::printf("[ shadows  ] spot: %d floor pixels checked, %d in the shadow\n", n, shadow);
    EXPECT_GT(shadow, 80);
    // The box's faces towards the light are lit, those turned away are hidden (by the box itself).
    int lit = 0, self = 0;
    for (size_t p = 0; p < t.mesh.size(); ++p) {
        if (t.mesh[p] != 1) continue;
        const int i = int(p % kSize), j = int(p / kSize);
        const dvec3 q = hit_point(s.camera, kSize, i, j, t.eye_depth[p]);
        // The face's normal: the axis where q is on the box's surface.
        dvec3 nrm(0);
        for (int a = 0; a < 3; ++a)
            if (std::fabs(std::fabs(q[a] - at[a]) - 0.5 * size[a]) < 1e-9) nrm[a] = q[a] > at[a] ? 1 : -1;
        const double nl = glm::dot(nrm, glm::normalize(L - q));
        if (std::fabs(nl) < 1e-6 || std::fabs(reach(q)) < 1e-6) continue;
        if (reach(q) < 0) {  // the light does not reach it: nothing to hide
            EXPECT_EQ(int(t.occluded[0][p]), 0);
            continue;
        }
        EXPECT_EQ(int(t.occluded[0][p]), nl < 0 ? 1 : 0) << "box pixel " << i << "," << j << " n.l " << nl;
        (nl < 0 ? self : lit)++;
    }
    std::printf("[ shadows  ] spot: box pixels lit %d, turned away %d\n", lit, self);
    EXPECT_GT(lit, 100);
}

// A ball over the floor under a point light: a floor point is hidden exactly when the segment to
// the light passes within r of the centre; a ball pixel exactly when it faces away (n.l < 0).
TEST(AnalyticShadows, PointBallShadowIsTheSegmentDistance) {
    Scene s = floor_scene();
    const dvec3 c(0.5, 1.2, -0.3);
    const double r = 0.7;
    add_sphere(s, float(r), glm::vec3(c), 0);
    s.lights.push_back(shadowed(point_light({1.3f, 3.2f, 0.4f}, {0.9f, 0.9f, 0.9f}, 20)));
    const dvec3 L(s.lights[0].pos);
    auto sd = [&](const dvec3& q) {
        const dvec3 e = L - q;
        const double t = std::clamp(glm::dot(c - q, e) / glm::dot(e, e), 0.0, 1.0);
        return glm::length(q + t * e - c) - r;  // < 0: the segment enters the ball
    };
    const AnalyticTrace t = analytic_trace(s, kSize, kSize);
    int shadow = 0;
    const int n = check_floor(s, t, sd, 1e-6, &shadow);
    std::printf("[ shadows  ] point: %d floor pixels checked, %d in the ball's shadow\n", n, shadow);
    EXPECT_GT(shadow, 150);
    int lit = 0, self = 0;
    for (size_t p = 0; p < t.mesh.size(); ++p) {
        if (t.mesh[p] != 1) continue;
        const dvec3 q = hit_point(s.camera, kSize, int(p % kSize), int(p / kSize), t.eye_depth[p]);
        const double nl = glm::dot(glm::normalize(q - c), glm::normalize(L - q));
        if (std::fabs(nl) < 1e-6) continue;
        EXPECT_EQ(int(t.occluded[0][p]), nl < 0 ? 1 : 0) << "ball pixel n.l " << nl;
        (nl < 0 ? self : lit)++;
    }
    std::printf("[ shadows  ] point: ball pixels lit %d, turned away %d\n", lit, self);
    EXPECT_GT(lit, 200);
    EXPECT_GT(self, 20);
}

// The floor lit alone, at grazing and head-on incidence, far from the origin as near it: its
// own surface never hides a light (the epsilon of shadow_ray_blocked), so nothing is occluded.
TEST(AnalyticShadows, NoSelfShadowOnAFloor) {
    for (double offset : {0.0, 1e3, 1e6}) {
        Scene s = floor_scene();
        const glm::vec3 o = float(offset) * glm::vec3(1, 0.25f, -1);
        s.camera.pos += o;
        s.camera.target += o;
        s.meshes.clear();
        s.objects.clear();
        add_plane(s, 12, o, 0);
        s.lights.push_back(shadowed(point_light(o + glm::vec3(0, 0.05f, 0), {1, 1, 1}, 8)));  // grazing
        s.lights.push_back(shadowed(point_light(o + glm::vec3(0, 4, 0), {1, 1, 1}, 8)));      // head-on
        Light sun;
        sun.type = Light::Type::directional;
        sun.dir = glm::normalize(glm::vec3(1, -0.01f, 0));  // 0.57 degrees above the horizon
        s.lights.push_back(shadowed(sun));
        const AnalyticTrace t = analytic_trace(s, kSize, kSize);
        for (size_t k = 0; k < s.lights.size(); ++k) {
            const long n = std::count(t.occluded[k].begin(), t.occluded[k].end(), 1);
            EXPECT_EQ(n, 0) << "light " << k << " at offset " << offset;
        }
    }
}
