// Shadow maps as pure math (no GL): each shadowed light's projections, what its map stores, where
// a point falls in it, and which objects can cast into it. The shadow stage (shadow_stage.h) draws
// what these describe; glsl120/shadow.glsl looks the maps up with the same formulas (the CPU
// twins here are what the tests check against brute force).
//   spot         one perspective map down the cone (its angle and radius set the projection);
//                cones wider than kSpotCubeAngle take the point light's six faces instead
//   directional  one orthographic map over the view frustum's part of the scene's bounds, its
//                extent rounded up a ladder and its corner snapped to whole texels, so the texel
//                grid stays put while the camera moves (docs/shadows.md)
//   point        six 90-degree faces (+X, -X, +Y, -Y, +Z, -Z, in world axes) packed 3 x 2 in one
//                2D texture: GL 2.x has no cube depth textures, and one layout serves both depth paths
#pragma once
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "scene/bounds.h"
#include "scene/scene.h"
#include "scene/shadow_budget.h"

namespace dsr {

// A spot cone of half-angle above this (degrees) is mapped by six faces, not one frustum (the
// shadow budget counts maps by the same rule: scene/shadow_budget.h).
constexpr float kSpotCubeAngle = kShadowCubeSpotAngle;
// The slope-scaled bias's tangent is capped here (a surface edge-on to the light).
constexpr float kMaxShadowTangent = 8.0f;

enum class ShadowKind { perspective, ortho, cube };

// One rendered view of a map (a whole map, or one cube face).
struct ShadowView {
    glm::dmat4 view{1};  // world -> the light's view space (looking down -Z)
    glm::dmat4 proj{1};  // view space -> clip, GL conventions
};

// A light's map: its views, the texture's size, and what the lookup needs. With q a point in the
// light's space (its view space; for a cube the world axes about the light):
//   stored depth = depth.x * |q| + depth.y * (-q.z) + depth.z        in [0, 1]
//   one texel's world size at q = texel.x + texel.y * a, a = -q.z (a cube: the largest |q_i|)
struct ShadowLayout {
    ShadowKind kind = ShadowKind::perspective;
    std::vector<ShadowView> views;  // 1, or 6 for a cube (face order above)
    int width = 0, height = 0;      // texels: size x size, or 3 size x 2 size for a cube
    int face = 0;                   // texels per side of one view
    glm::dmat4 light{1};            // world -> q's space (the cube's: a translation)
    glm::vec3 depth{0};
    glm::vec2 texel{0};
};

// The directional fit's inputs: the camera's frustum and the scene's bounds, in world space.
struct ShadowFit {
    std::array<glm::dvec3, 8> frustum{};  // the view frustum's corners
    glm::dvec3 lo{0}, hi{0};              // the scene's bounding box (object_bounds' spheres)
    bool empty = true;                    // no objects
};
ShadowFit shadow_fit(const Camera& camera, float aspect, const std::vector<ObjectBounds>& objects);

// `face` texels a side, clamped so the texture fits in max_texture (a cube: 3 x face across).
ShadowLayout shadow_layout(const Light& light, int size, const ShadowFit& fit, int max_texture);

// The stored depth of world point p as the map's own view would write it (CPU twin of
// shadow_caster.frag), and where p falls in the map: texture coordinates in [0, 1] of the whole
// texture (a cube: its face's tile). Off the map: outside [0, 1].
double shadow_depth(const ShadowLayout& s, const glm::dvec3& p);
glm::dvec2 shadow_uv(const ShadowLayout& s, const glm::dvec3& p);
// The cube face whose view holds direction d (largest |d_i|; ties to the lower face), and the
// face's texture coordinates in [0, 1] (shadow.glsl's cube_lookup).
int cube_face(const glm::dvec3& d);
glm::dvec2 cube_face_uv(const glm::dvec3& d, int face);
glm::dvec3 cube_face_axis(int face);
glm::dvec3 cube_face_up(int face);

// The depth the lookup compares against the map at world point p with unit normal n, l the unit
// direction from p towards the light: the stored depth less the constant and slope-scaled bias
// (scene.h LightShadow).
double shadow_receiver_depth(const ShadowLayout& s, const LightShadow& sh, const glm::dvec3& p,
                             const glm::dvec3& n, const glm::dvec3& l);

// True when an object of these bounds cannot cast into view v (its sphere wholly outside one of
// the view's clip planes): the shadow stage leaves it out of that view's map.
bool shadow_view_culls(const ShadowView& v, const ObjectBounds& b);

}  // namespace dsr
