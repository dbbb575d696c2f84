// The shadow maps' memory budget: every map of a run together, in bytes, checked before any is
// allocated (docs/scene-format.md, "Budgets"). A scene file's light lines are checked as they are
// read, at the most a texel can take on any path (the path is chosen only once the GL is known);
// `--lights N-shadow` and `own-shadow` are checked by the command that adds them, and the shadow
// stage checks the maps it is about to make with its own texel size. Pure and header-only (the
// scene reader's sanitizer and fuzz builds link no other file for it).
#pragma once
#include <algorithm>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace dsr {

// All shadow maps together: 1 GiB.
constexpr long long kMaxShadowBytes = 1LL << 30;

// A spot cone of half-angle above this (degrees) is mapped by six cube faces, not one frustum
// (deferred/shadow_math.h kSpotCubeAngle is this).
constexpr float kShadowCubeSpotAngle = 75.0f;

// Bytes a texel of a map takes as the shadow stage allocates it (deferred/shadow_stage.cpp): on
// the depth-texture path a GL_DEPTH_COMPONENT24 texture (stored in 32 bits); on the packed path a
// GL_RGB8 texture (stored in 32 bits: RGBX) and, with framebuffer objects, a GL_DEPTH_COMPONENT24
// renderbuffer for its depth test.
constexpr int shadow_texel_bytes(bool packed, bool fbo) { return packed && fbo ? 8 : 4; }
constexpr int kMaxShadowTexelBytes = shadow_texel_bytes(true, true);

// Whether `light`'s map is a cube's six faces (3 x 2 in one texture), as shadow_layout lays it out.
inline bool shadow_map_is_cube(const Light& light) {
    return light.type == Light::Type::point ||
           (light.type == Light::Type::spot && light.angle_deg > kShadowCubeSpotAngle);
}

// The texels of `light`'s map (0 without `shadow`): light.shadow.size a side, a cube's face
// clamped to max_texture / 3 and a single map to max_texture as shadow_layout clamps them
// (max_texture 0: not clamped).
inline long long shadow_map_texels(const Light& light, int max_texture = 0) {
    if (!light.shadow.on) return 0;
    const bool cube = shadow_map_is_cube(light);
    long long face = light.shadow.size;
    if (max_texture > 0) face = std::min<long long>(face, cube ? max_texture / 3 : max_texture);
    return (cube ? 6 : 1) * face * face;
}

inline long long shadow_map_bytes(const Light& light, int texel_bytes, int max_texture = 0) {
    return shadow_map_texels(light, max_texture) * texel_bytes;
}

// The lights' maps added in order against the budget: the first light that takes the total past
// it (over), the bytes of the maps before it and its own.
struct ShadowBudgetUse {
    bool over = false;
    size_t light = 0;        // index of the first light over the budget
    long long before = 0;    // bytes of the maps before it (all of them when not over)
    long long bytes = 0;     // its map's bytes
};

inline ShadowBudgetUse shadow_budget_use(const std::vector<Light>& lights, int texel_bytes, int max_texture = 0,
                                         long long budget = kMaxShadowBytes) {
    ShadowBudgetUse u;
    for (size_t i = 0; i < lights.size(); ++i) {
        const long long b = shadow_map_bytes(lights[i], texel_bytes, max_texture);
        if (b == 0) continue;
        if (b > budget - u.before) {
            u.over = true, u.light = i, u.bytes = b;
            return u;
        }
        u.before += b;
    }
    return u;
}

// What a refusal says after "expected ": the budget and the light that broke it, e.g.
// "shadow maps within the budget of 1073741824 bytes (1 GiB), got a point light's 6 faces of
// 8192 x 8192 texels (3221225472 bytes at 8 a texel) after 0 bytes".
inline std::string shadow_budget_text(const Light& light, long long before, int texel_bytes, int max_texture = 0) {
    const bool cube = shadow_map_is_cube(light);
    long long face = light.shadow.size;
    if (max_texture > 0) face = std::min<long long>(face, cube ? max_texture / 3 : max_texture);
    const char* kind = light.type == Light::Type::point ? "a point light's"
                       : light.type == Light::Type::spot ? "a spot light's"
                                                         : "a directional light's";
    const std::string side = std::to_string(face) + " x " + std::to_string(face);
    return "shadow maps within the budget of " + std::to_string(kMaxShadowBytes) + " bytes (1 GiB), got " + kind + " " +
           (cube ? "6 faces of " + side : "map of " + side) + " texels (" +
           std::to_string(shadow_map_bytes(light, texel_bytes, max_texture)) + " bytes at " +
           std::to_string(texel_bytes) + " a texel) after " + std::to_string(before) + " bytes";
}

}  // namespace dsr
