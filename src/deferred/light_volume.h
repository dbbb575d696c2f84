// A light is its volume (docs/light_geometry.md): the region of space a light can
// reach, as one pure description (no GL) that feeds frustum culling, the scissor rectangle, the
// ideal fragment counts and the meshes the volume / stencil light passes draw.
//   sphere       point light: every point within `radius` of the centre (Equation 2's S_radius,
//                or where the attenuation law falls under its threshold)
//   cone         spot light: the spherical sector of points within `radius` of the apex and within
//                the half-angle of the axis (GL_SPOT_CUTOFF: nothing outside it), half-angle in (0, 90]
//   full_screen  directional light: everything (no culling, no scissor, a screen quad)
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "deferred/culling.h"
#include "deferred/eye_transform.h"
#include "deferred/scissor.h"
#include "scene/scene.h"

namespace dsr {

struct LightVolume {
    enum class Kind { sphere, cone, full_screen };
    Kind kind = Kind::sphere;
    glm::vec3 pos{0};        // sphere centre, cone apex (world space unless said otherwise)
    float radius = 0;        // sphere radius, cone slant length (range)
    glm::vec3 axis{0, 0, -1};  // cone: unit direction the light travels
    float half_angle = 0;    // cone: radians, in (0, pi/2]
};

// The light's volume, in world space. Throws dsr::Error for a light whose fields are out of range
// (radius < 0, a zero direction, a spot angle outside (0, 90]).
LightVolume light_volume(const Light& light);

// The same volume moved by a rigid transform (e.g. the view matrix: eye space). Directions are
// transformed by its rotation part; the matrix must be a rotation + translation.
LightVolume transformed(const LightVolume& v, const glm::mat4& rigid);

// The volume in the camera's eye space, its position moved in double and rounded once
// (Camera::to_eye): what the renderers pass to volume_scissor.
LightVolume to_eye(const LightVolume& v, const Camera& camera);
LightVolume to_eye(const LightVolume& v, const EyeTransform& eye);

struct BoundingSphere {
    glm::vec3 centre{0};
    float radius = 0;  // infinite for full_screen
};

// The smallest sphere holding the volume: the sphere itself; for a cone of half-angle a and
// range R, centred on the axis at R/(2 cos a) with that radius when a < 45 degrees, else at
// R cos a with radius R sin a; full_screen: radius +infinity.
BoundingSphere bounding_sphere(const LightVolume& v);

// Whether the light can add anything to a surface inside the sphere (centre, radius), both in
// the same space: Equation 2 (and the attenuation cut, and a spot's cone) makes a light exactly
// zero outside its volume, so a sphere its bounding sphere does not meet gets nothing; a
// directional light reaches everything. The forward renderers' and the transparent pass's
// light-object culling.
bool volume_reaches(const LightVolume& v, glm::vec3 centre, float radius);

// True when the volume lies wholly outside the frustum (Listing 17 on the volume): the sphere's
// test; a cone is outside when its bounding sphere is, or when its enclosing mesh (below) lies
// wholly outside one plane; full_screen is never outside. Conservative: never true for a volume
// that reaches inside the frustum.
bool volume_outside(const std::array<Plane, 6>& planes, const LightVolume& v);
// The same against planes widened once (culling.h FrustumTest), for a loop over many lights.
bool volume_outside(const FrustumTest& frustum, const LightVolume& v);

// The scissor rectangle of a volume given in EYE space (transformed(v, view)), same conventions as
// light_scissor (scissor.h): the pixels that can hold a visible surface point of the volume,
// clamped to the viewport, rounded outward.
//   sphere       exactly light_scissor
//   cone         the bounding box of the projected enclosing mesh clipped to z <= -near, intersected
//                with the bounding sphere's light_scissor: never larger than the sphere's rectangle,
//                and it contains the projection of every cone point at z <= -near
//   full_screen  the whole viewport
ScissorRect volume_scissor(const LightVolume& eye_volume, float p00, float p11, float near_plane,
                           int width, int height);

// A closed, convex triangle mesh that encloses the volume (every volume point is inside or on it),
// for drawing the volume. Triangles are counter-clockwise seen from outside (GL's default front
// face is outward), indices into `vertices`. Same space as the volume it was made from.
struct VolumeMesh {
    std::vector<glm::vec3> vertices;
    std::vector<uint32_t> indices;  // 3 per triangle
    size_t triangles() const { return indices.size() / 3; }
};

// `segments` (>= 3; the default suits drawing) is the number of edges around the sphere's equator
// or the cone's axis; the sphere has segments / 2 stacks (at least 2), the cone's cap as many rings
// as its angle needs. Every face plane lies on or outside the volume (the sphere's UV mesh and the
// cone's cap are scaled out until each face clears the true surface; the cone's side faces are
// tangent to the circular cone; a 90-degree cone is a hemisphere over a flat disc), then the
// whole mesh grown by a relative 1e-6 or so, so its float vertices enclose the volume's boundary
// too. full_screen: an empty mesh (draw a screen quad instead).
// Throws dsr::Error for segments < 3.
constexpr int kVolumeSegments = 24;
VolumeMesh volume_mesh(const LightVolume& v, int segments = kVolumeSegments);

// True when `p` lies strictly inside the volume, the set of points the light can add to: the
// linear law and the attenuation cut are zero on and beyond the radius, the spot's falloff is zero
// on and outside the cone (lighting.glsl). The membership the ideal counts and the tests use.
bool inside_volume(const LightVolume& v, glm::dvec3 p);

}  // namespace dsr
