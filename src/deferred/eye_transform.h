// A camera's view matrix in float and in double, made once a frame. Each light's eye-space
// position and volume are moved by it (in double, rounded once, as Camera::to_eye) rather than
// by a lookAt composed again per light: at 4096 lights, four lookAts a light were most of
// make_frame's CPU time.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace dsr {

struct EyeTransform {
    glm::mat4 view;
    glm::dmat4 view_d;
    explicit EyeTransform(const Camera& c) : view(c.view()), view_d(c.view_d()) {}
    // Camera::to_eye's arithmetic exactly.
    glm::vec3 to_eye(glm::vec3 world) const { return glm::vec3(view_d * glm::dvec4(glm::dvec3(world), 1.0)); }
};

}  // namespace dsr
