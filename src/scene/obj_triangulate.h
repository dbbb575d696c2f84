// Internal to the OBJ loader (obj_geometry.cpp): faces of more than three corners as triangles.
//   quads     split along the shorter diagonal, in float, as tinyobjloader split them (so models
//             of quads triangulate as they always did); where that diagonal lies outside a
//             concave quad, along the other one
//   polygons  ear clipping in double on the polygon projected onto the plane of its Newell
//             normal; corners that add no area (a repeated corner, one on a straight edge, the
//             tip of a spike of zero width) are dropped from the ring without a triangle; a
//             polygon without area (its Newell normal zero), one ear clipping gets stuck on (not
//             simple) or one past the work budget becomes a fan from its first remaining corner,
//             and the caller warns
// Triangles keep the polygon's winding.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace dsr::obj {

// tinyobjloader's quad split: true for (0 1 2)(0 2 3), false for (0 1 3)(1 2 3).
bool quad_splits_02(const std::array<glm::vec3, 4>& p);

// The quad's two triangles as corner numbers, appended to `out` (six numbers).
void triangulate_quad(const std::array<glm::vec3, 4>& p, std::vector<uint32_t>& out);

enum class Polygon { ear_clipped, fan_no_area, fan_not_simple, fan_over_budget };

// Triangles of the polygon `p` (corners in order, at least 3) as corner numbers appended to
// `out`, three per triangle. `work` counts point-in-triangle tests across calls; past
// kMaxEarClipWork the remaining ring becomes a fan.
Polygon triangulate_polygon(const std::vector<glm::dvec3>& p, std::vector<uint32_t>& out, size_t& work);

// Point-in-triangle tests one load may spend on ear clipping (ear clipping is quadratic in a
// polygon's corners): past it, the polygons left become fans.
constexpr size_t kMaxEarClipWork = size_t(100) << 20;

}  // namespace dsr::obj
