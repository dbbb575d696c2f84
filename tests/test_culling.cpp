// Light culling (Listing 17) against geometry built independently of Gribb-Hartmann: the
// frustum's corners come from the inverse view-projection (in double), each face's plane from
// three of its corners, and "is any point of the sphere inside" from clip-space tests of
// sample points.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "deferred/culling.h"
#include "dsr_error.h"

namespace {

using dsr::Plane;

struct Frustum {
    glm::mat4 view_proj;
    glm::dmat4 clip;  // the same matrix in double, for the brute-force tests
    glm::dvec3 corner[8];  // index bits: x (1), y (2), z (4); NDC -1 for a clear bit
    glm::dvec3 centroid;
    double size;  // largest corner distance from the centroid
};

struct Face {
    int axis, sign;  // NDC axis (0 x, 1 y, 2 z) and side (-1 or +1)
};
// Same order as frustum_planes: left, right, bottom, top, near, far.
const Face kFaces[6] = {{0, -1}, {0, 1}, {1, -1}, {1, 1}, {2, -1}, {2, 1}};

class Gen {
public:
    explicit Gen(unsigned seed) : rng_(seed) {}
    double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
    double log_uni(double a, double b) { return std::exp(uni(std::log(a), std::log(b))); }
    glm::dvec3 vec(double a) { return {uni(-a, a), uni(-a, a), uni(-a, a)}; }

    Frustum frustum(bool ortho) {
        const float n = (float)log_uni(0.05, 2), f = n * (float)log_uni(2, 1000);
        const float aspect = (float)uni(0.5, 2);
        glm::mat4 proj;
        if (ortho) {
            const float hw = (float)uni(0.5, 20), hh = hw / aspect;
            proj = glm::ortho(-hw, hw, -hh, hh, n, f);
        } else {
            proj = glm::perspective((float)glm::radians(uni(20, 120)), aspect, n, f);
        }
        glm::dvec3 eye = vec(50), target = eye + vec(1), up = vec(1);
        while (glm::length(glm::cross(target - eye, up)) < 0.1) up = vec(1);
        const glm::mat4 view = glm::lookAt(glm::vec3(eye), glm::vec3(target), glm::vec3(up));
        Frustum fr;
        fr.view_proj = proj * view;
        fr.clip = glm::dmat4(fr.view_proj);
        const glm::dmat4 inv = glm::inverse(fr.clip);
        fr.centroid = glm::dvec3(0);
        for (int i = 0; i < 8; ++i) {
            const glm::dvec4 p = inv * glm::dvec4(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1, 1);
            fr.corner[i] = glm::dvec3(p) / p.w;
            fr.centroid += fr.corner[i] / 8.0;
        }
        fr.size = 0;
        for (const auto& c : fr.corner) fr.size = std::max(fr.size, glm::length(c - fr.centroid));
        return fr;
    }

private:
    std::mt19937_64 rng_;
};

// Corners of face k, in order around the face.
std::array<glm::dvec3, 4> face_corners(const Frustum& fr, int k) {
    const Face fc = kFaces[k];
    const int a = (fc.axis + 1) % 3, b = (fc.axis + 2) % 3;
    const int base = fc.sign > 0 ? 1 << fc.axis : 0;
    const int order[4] = {0, 1 << a, (1 << a) | (1 << b), 1 << b};
    std::array<glm::dvec3, 4> c;
    for (int i = 0; i < 4; ++i) c[i] = fr.corner[base | order[i]];
    return c;
}

// Outward unit normal of face k, from its corners (independent of the plane extraction).
glm::dvec3 outward_normal(const Frustum& fr, int k, glm::dvec3* centre) {
    const auto c = face_corners(fr, k);
    *centre = (c[0] + c[1] + c[2] + c[3]) / 4.0;
    // Newell-style: robust for a slightly non-planar quad from rounding.
    glm::dvec3 nrm = glm::cross(c[2] - c[0], c[3] - c[1]);
    nrm = glm::normalize(nrm);
    if (glm::dot(nrm, *centre - fr.centroid) < 0) nrm = -nrm;
    return nrm;
}

bool inside_clip(const Frustum& fr, glm::dvec3 p) {
    const glm::dvec4 q = fr.clip * glm::dvec4(p, 1);
    return q.w > 0 && std::abs(q.x) <= q.w && std::abs(q.y) <= q.w && std::abs(q.z) <= q.w;
}

TEST(Culling, PlanesMatchTheFrustumGeometry) {
    Gen g(11u);
    for (int t = 0; t < 500; ++t) {
        const Frustum fr = g.frustum(t % 5 == 0);
        const auto planes = dsr::frustum_planes(fr.view_proj);
        for (int k = 0; k < 6; ++k) {
            const Plane& p = planes[k];
            EXPECT_NEAR(glm::length(p.n), 1.0, 1e-6);
            glm::dvec3 centre;
            const glm::dvec3 out = outward_normal(fr, k, &centre);
            // Inward-facing: the normal is minus the face's outward normal.
            EXPECT_NEAR(glm::dot(glm::dvec3(p.n), -out), 1.0, 1e-4) << "plane " << k;
            // The face's corners lie on the plane; the centroid is inside.
            for (const auto& c : face_corners(fr, k))
                EXPECT_NEAR(glm::dot(glm::dvec3(p.n), c) + p.d, 0.0,
                            2e-4 * (fr.size + glm::length(c)))
                    << "plane " << k;
            EXPECT_GT(glm::dot(glm::dvec3(p.n), fr.centroid) + p.d, 0) << "plane " << k;
        }
    }
    EXPECT_THROW(dsr::frustum_planes(glm::mat4(0.0f)), dsr::Error);
}

// For each face: a sphere just beyond its plane (a gap of eps) must be culled; one reaching eps
// past it, into the frustum at the face's centre, must not.
TEST(Culling, JustInsideAndJustOutsideEachPlane) {
    Gen g(12u);
    int culled_out = 0, kept_in = 0, cases = 0;
    for (int t = 0; t < 2000; ++t) {
        const Frustum fr = g.frustum(t % 5 == 0);
        const auto planes = dsr::frustum_planes(fr.view_proj);
        for (int k = 0; k < 6; ++k) {
            glm::dvec3 centre;
            const glm::dvec3 out = outward_normal(fr, k, &centre);
            const double r = fr.size * g.log_uni(1e-4, 2);
            // Float plane and centre carry ~1e-7 relative error of the coordinates involved.
            const double eps = 1e-5 * (glm::length(centre) + fr.size + r);
            const glm::vec3 c_out(centre + out * (r + eps));
            const glm::vec3 c_in(centre + out * (r - eps));
            // The point of the inner sphere deepest into the frustum really is inside.
            ASSERT_TRUE(inside_clip(fr, glm::dvec3(c_in) - out * (double)(float)r))
                << "test setup, face " << k;
            ++cases;
            const bool o = dsr::sphere_outside(planes, c_out, (float)r);
            const bool i = dsr::sphere_outside(planes, c_in, (float)r);
            culled_out += o;
            kept_in += !i;
            if (!o && cases - culled_out <= 3)
                ADD_FAILURE() << "sphere " << eps << " beyond face " << k << " not culled";
            if (i && cases - kept_in <= 3)
                ADD_FAILURE() << "sphere reaching " << eps << " into face " << k << " culled";
        }
    }
    std::printf("[ culling  ] %d faces: %d just-outside spheres culled, %d just-inside kept\n",
                cases, culled_out, kept_in);
    EXPECT_EQ(culled_out, cases);
    EXPECT_EQ(kept_in, cases);
}

// Random spheres: one with any sample point inside the frustum must never be culled; one wholly
// beyond a face's plane (by geometry from the corners) must be culled; the rest (near corners
// and edges) may go either way.
TEST(Culling, NeverCullsAVisibleSphere) {
    Gen g(13u);
    int visible = 0, beyond_plane = 0, corner_kept = 0, corner_cases = 0;
    for (int t = 0; t < 1000; ++t) {
        const Frustum fr = g.frustum(t % 5 == 0);
        const auto planes = dsr::frustum_planes(fr.view_proj);
        glm::dvec3 centre[6], out[6];
        for (int k = 0; k < 6; ++k) out[k] = outward_normal(fr, k, &centre[k]);
        const glm::dmat4 inv = glm::inverse(fr.clip);
        for (int s = 0; s < 40; ++s) {
            const float r = (float)(fr.size * g.log_uni(1e-3, 0.5));
            glm::vec3 c;
            if (s % 2) {
                c = glm::vec3(fr.centroid + g.vec(1.5 * fr.size));
            } else {  // near the frustum: a point inside it, moved up to 2r in any direction
                const glm::dvec4 p = inv * glm::dvec4(g.vec(1), 1);
                c = glm::vec3(glm::dvec3(p) / p.w + g.vec(2 * r / std::sqrt(3.0)));
            }
            const bool culled = dsr::sphere_outside(planes, c, r);
            // Brute force: is some point of the sphere inside the frustum?
            bool any_inside = inside_clip(fr, glm::dvec3(c));
            for (int i = 0; i < 200 && !any_inside; ++i) {
                glm::dvec3 d = g.vec(1);
                const double len = glm::length(d);
                if (len < 1e-9) continue;
                const double k = i % 2 ? 1.0 : std::cbrt(g.uni(0, 1));  // surface and interior
                any_inside = inside_clip(fr, glm::dvec3(c) + d * (k * r / len) * (1 - 1e-7));
            }
            // Sample the point of the sphere closest to each face's frustum-side, too.
            for (int k = 0; k < 6 && !any_inside; ++k)
                any_inside = inside_clip(fr, glm::dvec3(c) - out[k] * (double)r * (1 - 1e-7));
            bool wholly_beyond = false;
            for (int k = 0; k < 6; ++k) {
                const double dist = glm::dot(glm::dvec3(c) - centre[k], out[k]);
                const double eps = 1e-5 * (glm::length(centre[k]) + fr.size + r);
                wholly_beyond |= dist > r + eps;
            }
            if (any_inside) {
                ++visible;
                EXPECT_FALSE(culled) << "a sphere with a point inside the frustum was culled";
            }
            if (wholly_beyond) {
                ++beyond_plane;
                EXPECT_TRUE(culled) << "a sphere wholly beyond a face plane was kept";
            }
            if (!any_inside && !wholly_beyond) {
                ++corner_cases;
                corner_kept += !culled;
            }
        }
    }
    std::printf("[ culling  ] random spheres: %d with a point inside (none culled), %d wholly "
                "beyond a plane (all culled), %d others near edges/corners (%d kept)\n",
                visible, beyond_plane, corner_cases, corner_kept);
    EXPECT_GT(visible, 1000);
    EXPECT_GT(beyond_plane, 1000);
}

// Hand-checked spheres in eye space (view = identity).
TEST(Culling, KnownSpheres) {
    const glm::mat4 vp = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
    const auto planes = dsr::frustum_planes(vp);  // eye space: camera at origin looking down -z
    EXPECT_FALSE(dsr::sphere_outside(planes, {0, 0, -0.05f}, 0.1f));   // straddles near
    EXPECT_TRUE(dsr::sphere_outside(planes, {0, 0, -0.05f}, 0.04f));   // between eye and near plane
    EXPECT_TRUE(dsr::sphere_outside(planes, {0, 0, -101}, 0.5f));      // beyond far
    EXPECT_FALSE(dsr::sphere_outside(planes, {0, 0, -101}, 1.5f));
    EXPECT_FALSE(dsr::sphere_outside(planes, {0, 0, -50}, 1.0f));
    EXPECT_TRUE(dsr::sphere_outside(planes, {100, 0, -50}, 1.0f));     // far to the right
}

}  // namespace
