// One light as the five vec4s lighting.glsl's light_contribution() takes (its comment says what
// each holds), in eye space. Pure: no GL; the deferred light pass, the multi-light passes and the
// forward renderers all fill their uniforms from it, so they shade the same light the same way.
#pragma once
#include <glm/glm.hpp>

#include "deferred/eye_transform.h"
#include "scene/scene.h"

namespace dsr {

struct LightParams {
    glm::vec4 pos{0};    // eye-space position, radius
    glm::vec4 color{0};  // colour, type (0 point, 1 spot, 2 directional)
    glm::vec4 dir{0};    // eye-space unit direction the light travels, cos(half-angle)
    glm::vec4 spot{0};   // cos of the soft edge's inner angle, exponent; physical: scale, offset
    glm::vec4 att{0};    // KC, KL, KQ, law (0 Equation 2, 1 attenuation); physical: 1 / range^2, -, -, 2
};

// `view`: the camera's view matrix (rotation + translation).
LightParams light_params(const Light& light, const glm::mat4& view);
// The same with the position moved to eye space in double (Camera::to_eye, rounded once), so a
// light far from the origin keeps its position: what the renderers use.
LightParams light_params(const Light& light, const Camera& camera);
LightParams light_params(const Light& light, const EyeTransform& eye);
// With the eye-space position given (make_frame has it from the light's volume: the same double
// arithmetic, not done twice).
LightParams light_params(const Light& light, const glm::mat4& view, glm::vec3 eye_pos);

}  // namespace dsr
