// Shadow maps' pure math (deferred/shadow_math.h) against brute force: each map's lookup lands
// where its own view projects a point, cube faces cover every direction, the directional map
// covers what the camera sees and keeps its texel grid while the camera moves, culling keeps
// every object that reaches a view.
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "deferred/shadow_math.h"

namespace {

using dsr::Light;
using dsr::ShadowKind;
using dsr::ShadowLayout;

glm::dvec3 project(const dsr::ShadowView& v, const glm::dvec3& p) {
    const glm::dvec4 c = v.proj * v.view * glm::dvec4(p, 1);
    return glm::dvec3(c) / c.w;
}

Light spot() {
    Light l;
    l.type = Light::Type::spot;
    l.pos = glm::vec3(1, 4, -2);
    l.dir = glm::normalize(glm::vec3(0.3f, -1, 0.2f));
    l.angle_deg = 35;
    l.radius = 9;
    return l;
}

// big: a scene larger than the view, so the view's part of it decides the map.
dsr::ShadowFit fit_of(const dsr::Camera& cam, float big = 5) {
    std::vector<dsr::ObjectBounds> objects = {{glm::vec3(0, 0, 0), big}, {glm::vec3(2, 1, 1), 1.0f}};
    return dsr::shadow_fit(cam, 1.5f, objects);
}

TEST(ShadowMath, SpotLookupIsItsViewsProjection) {
    const Light l = spot();
    const ShadowLayout s = dsr::shadow_layout(l, 1024, {}, 16384);
    ASSERT_EQ(s.kind, ShadowKind::perspective);
    ASSERT_EQ(s.views.size(), 1u);
    EXPECT_EQ(s.width, 1024);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    int inside = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 p = glm::dvec3(l.pos) + glm::dvec3(u(rng), u(rng), u(rng)) * 9.0;
        const glm::dvec3 d = p - glm::dvec3(l.pos);
        const double dist = glm::length(d);
        if (dist > l.radius || dist < 0.05) continue;
        // The stored depth is the distance over the radius.
        EXPECT_NEAR(dsr::shadow_depth(s, p), dist / l.radius, 1e-6);  // float coefficients, as the GL gets them
        const double c = glm::dot(d, glm::dvec3(l.dir)) / dist;
        if (c <= std::cos(glm::radians(double(l.angle_deg)))) continue;
        ++inside;
        // Inside the cone: on the map, where the view's projection puts it, with a texel to spare.
        const glm::dvec3 ndc = project(s.views[0], p);
        const glm::dvec2 uv = dsr::shadow_uv(s, p);
        EXPECT_NEAR(uv.x, ndc.x * 0.5 + 0.5, 1e-9);
        EXPECT_NEAR(uv.y, ndc.y * 0.5 + 0.5, 1e-9);
        EXPECT_GT(uv.x, 0.5 / s.width);
        EXPECT_LT(uv.x, 1 - 0.5 / s.width);
        EXPECT_GT(uv.y, 0.5 / s.width);
        EXPECT_LT(uv.y, 1 - 0.5 / s.width);
        EXPECT_GE(ndc.z, -1);
        EXPECT_LE(ndc.z, 1);
    }
    EXPECT_GT(inside, 100);
}

// Every direction's face is the one whose 90-degree view holds it, at the face's projection.
TEST(ShadowMath, CubeFacesCoverEveryDirection) {
    Light l;
    l.pos = glm::vec3(-3, 2, 5);
    l.radius = 6;
    const ShadowLayout s = dsr::shadow_layout(l, 256, {}, 16384);
    ASSERT_EQ(s.kind, ShadowKind::cube);
    ASSERT_EQ(s.views.size(), 6u);
    EXPECT_EQ(s.width, 768);
    EXPECT_EQ(s.height, 512);
    std::mt19937 rng(3);
    std::normal_distribution<double> g;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng))) * (0.1 + 5.8 * (i % 97) / 97.0);
        const glm::dvec3 p = glm::dvec3(l.pos) + d;
        const int f = dsr::cube_face(d);
        const glm::dvec3 ndc = project(s.views[size_t(f)], p);
        ASSERT_LE(std::fabs(ndc.x), 1 + 1e-9);
        ASSERT_LE(std::fabs(ndc.y), 1 + 1e-9);
        ASSERT_LE(std::fabs(ndc.z), 1 + 1e-9);
        const glm::dvec2 fu = dsr::cube_face_uv(d, f);
        EXPECT_NEAR(fu.x, ndc.x * 0.5 + 0.5, 1e-9);
        EXPECT_NEAR(fu.y, ndc.y * 0.5 + 0.5, 1e-9);
        const glm::dvec2 uv = dsr::shadow_uv(s, p);
        EXPECT_NEAR(uv.x, (f % 3 + fu.x) / 3.0, 1e-9);
        EXPECT_NEAR(uv.y, (f / 3 + fu.y) / 2.0, 1e-9);
        EXPECT_NEAR(dsr::shadow_depth(s, p), glm::length(d) / l.radius, 1e-6);
    }
    // A wide spot takes the six faces; a narrow one a single map.
    Light w = spot();
    w.angle_deg = 80;
    EXPECT_EQ(dsr::shadow_layout(w, 256, {}, 16384).kind, ShadowKind::cube);
    // The texture fits the GL's largest: the faces shrink.
    EXPECT_EQ(dsr::shadow_layout(l, 8192, {}, 16384).face, 5461);
}

dsr::Camera camera_at(glm::vec3 pos) {
    dsr::Camera c;
    c.pos = pos;
    c.target = glm::vec3(0, 0, 0);
    c.near_plane = 0.1f;
    c.far_plane = 40;
    return c;
}

Light sun() {
    Light l;
    l.type = Light::Type::directional;
    l.dir = glm::normalize(glm::vec3(0.4f, -1, 0.3f));
    return l;
}

// Every point of the scene's bounds that the camera sees is on the map, at a depth in [0, 1].
TEST(ShadowMath, DirectionalMapCoversWhatTheCameraSees) {
    const dsr::Camera cam = camera_at(glm::vec3(3, 4, 9));
    const dsr::ShadowFit fit = fit_of(cam);
    const ShadowLayout s = dsr::shadow_layout(sun(), 1024, fit, 16384);
    ASSERT_EQ(s.kind, ShadowKind::ortho);
    const glm::dmat4 vp = glm::dmat4(cam.projection(1.5f)) * cam.view_d();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    int seen = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 p = fit.lo + (fit.hi - fit.lo) * glm::dvec3(u(rng), u(rng), u(rng));
        const glm::dvec4 c = vp * glm::dvec4(p, 1);
        if (c.w <= 0 || std::fabs(c.x) > c.w || std::fabs(c.y) > c.w || std::fabs(c.z) > c.w) continue;
        ++seen;
        const glm::dvec2 uv = dsr::shadow_uv(s, p);
        EXPECT_GE(uv.x, 0);
        EXPECT_LE(uv.x, 1);
        EXPECT_GE(uv.y, 0);
        EXPECT_LE(uv.y, 1);
        const double d = dsr::shadow_depth(s, p);
        EXPECT_GT(d, 0);
        EXPECT_LT(d, 1);
        const glm::dvec3 ndc = project(s.views[0], p);
        EXPECT_NEAR(d, ndc.z * 0.5 + 0.5, 1e-6);  // linear: the orthographic view's own depth
    }
    EXPECT_GT(seen, 1000);
}

// Moving the camera a little keeps the texel size and puts the map's corner on the same grid:
// a world point stays at the same place within its texel.
TEST(ShadowMath, DirectionalTexelGridIsStableUnderCameraMotion) {
    const ShadowLayout a = dsr::shadow_layout(sun(), 1024, fit_of(camera_at(glm::vec3(3, 4, 9)), 60), 16384);
    int same_grid = 0;
    for (int k = 1; k <= 20; ++k) {
        const ShadowLayout b =
            dsr::shadow_layout(sun(), 1024, fit_of(camera_at(glm::vec3(3 + 0.013f * k, 4, 9 - 0.007f * k)), 60), 16384);
        if (b.texel.x != a.texel.x) continue;  // the ladder stepped: a new grid, rarely
        ++same_grid;
        const glm::dvec3 p(0.37, 0.21, -0.44);
        const glm::dvec2 ta = dsr::shadow_uv(a, p) * double(a.width), tb = dsr::shadow_uv(b, p) * double(b.width);
        const glm::dvec2 fa = ta - glm::floor(ta), fb = tb - glm::floor(tb);
        EXPECT_NEAR(fa.x, fb.x, 1e-6) << k;
        EXPECT_NEAR(fa.y, fb.y, 1e-6) << k;
    }
    EXPECT_GE(same_grid, 15);
}

// The bias: none without bias and slope; the slope part grows with the angle to the light.
TEST(ShadowMath, ReceiverDepthBias) {
    const Light l = spot();
    const ShadowLayout s = dsr::shadow_layout(l, 1024, {}, 16384);
    const glm::dvec3 p = glm::dvec3(l.pos) + glm::dvec3(l.dir) * 5.0;
    const glm::dvec3 to_light = -glm::dvec3(l.dir);
    dsr::LightShadow none;
    none.bias = 0, none.slope = 0;
    EXPECT_DOUBLE_EQ(dsr::shadow_receiver_depth(s, none, p, to_light, to_light), dsr::shadow_depth(s, p));
    dsr::LightShadow sh;
    sh.bias = 0.01f, sh.slope = 2;
    // Facing the light: the constant part alone.
    EXPECT_NEAR(dsr::shadow_receiver_depth(s, sh, p, to_light, to_light), dsr::shadow_depth(s, p) - 0.01, 1e-6);
    // At 45 degrees: slope x one texel at 5 units x tan 45, over the radius.
    const glm::dvec3 n45 = glm::normalize(to_light + glm::normalize(glm::cross(to_light, glm::dvec3(1, 0, 0))));
    const double texel = 5.0 * double(s.texel.y);
    EXPECT_NEAR(dsr::shadow_receiver_depth(s, sh, p, n45, to_light), dsr::shadow_depth(s, p) - 0.01 - 2 * texel / 9.0, 1e-6);
}

// Culling keeps every object whose sphere reaches a view's volume (brute force: points of the
// sphere inside the clip volume) and drops some that do not.
TEST(ShadowMath, CullingKeepsEveryCaster) {
    const Light l = spot();
    const ShadowLayout s = dsr::shadow_layout(l, 512, {}, 16384);
    Light p;
    p.pos = glm::vec3(0, 1, 0);
    p.radius = 3;
    const ShadowLayout c = dsr::shadow_layout(p, 512, {}, 16384);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-8, 8);
    std::normal_distribution<double> g;
    int culled = 0, kept = 0;
    for (const ShadowLayout* m : {&s, &c})
        for (const dsr::ShadowView& v : m->views)
            for (int i = 0; i < 2000; ++i) {
                const dsr::ObjectBounds b{glm::vec3(u(rng), u(rng), u(rng)), float(0.2 + (i % 7) * 0.3)};
                bool reaches = false;
                for (int k = 0; k < 300 && !reaches; ++k) {
                    const glm::dvec3 q = glm::dvec3(b.centre) +
                                         glm::normalize(glm::dvec3(g(rng), g(rng), g(rng))) * double(b.radius) * std::cbrt((k + 0.5) / 300);
                    const glm::dvec4 cl = v.proj * v.view * glm::dvec4(q, 1);
                    reaches = cl.w > 0 && std::fabs(cl.x) <= cl.w && std::fabs(cl.y) <= cl.w && std::fabs(cl.z) <= cl.w;
                }
                const bool cull = dsr::shadow_view_culls(v, b);
                if (reaches) {
                    EXPECT_FALSE(cull);
                }
                (cull ? culled : kept)++;
            }
    EXPECT_GT(culled, 1000);
    EXPECT_GT(kept, 100);
}

}  // namespace
