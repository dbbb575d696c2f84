// Light frustum culling (§3.4.3, Listing 17 lines 11-20) as pure math.
#pragma once
#include <array>
#include <vector>

#include <glm/glm.hpp>

namespace dsr {

// Inward-facing, normalised: distance(p) = dot(n, p) + d, >= 0 inside.
struct Plane {
    glm::vec3 n;
    float d;
};

// Gribb-Hartmann extraction from the GL clip matrix (projection * view, or any clip-from-space
// matrix: the planes come out in that space), normalised so distance() is a true distance.
// Order: left, right, bottom, top, near, far. Throws dsr::Error for a matrix with a degenerate
// (zero-length or non-finite) plane.
std::array<Plane, 6> frustum_planes(const glm::mat4& view_proj);

// True when the sphere lies wholly outside one of the planes (distance < -radius), the test of
// Listing 17 with a 3-component dot (docs/errata.md #6: a 4-component one adds pos.w*plane.w, and pos.w
// holds the radius). Conservative: a sphere near a frustum corner, outside the frustum but not
// wholly outside any single plane, is kept.
bool sphere_outside(const std::array<Plane, 6>& planes, glm::vec3 center, float radius);

// sphere_outside over many spheres against one frustum: the planes widened to double once, not at
// every sphere, where the widening is a visible share of make_frame at thousands of lights. Double,
// so that the near and far planes' distances keep what the float matrix holds.
class FrustumTest {
public:
    explicit FrustumTest(const std::array<Plane, 6>& planes);
    bool sphere_outside(glm::vec3 center, float radius) const {
        const glm::dvec3 c(center);
        for (const glm::dvec4& p : planes_)  // xyz only (docs/errata.md #6)
            if (glm::dot(glm::dvec3(p), c) + p.w < -double(radius)) return true;
        return false;
    }

    // Whether every point lies outside one and the same plane (distance < 0): a convex hull of
    // them is then outside the frustum (light_volume.h volume_outside's mesh test). False for none.
    bool all_outside_one_plane(const std::vector<glm::dvec3>& points) const {
        if (points.empty()) return false;
        for (const glm::dvec4& p : planes_) {
            bool all_out = true;
            for (const glm::dvec3& q : points)
                if (glm::dot(glm::dvec3(p), q) + p.w >= 0) {
                    all_out = false;
                    break;
                }
            if (all_out) return true;
        }
        return false;
    }

private:
    std::array<glm::dvec4, 6> planes_;
};

}  // namespace dsr
