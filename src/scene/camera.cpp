#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene.h"

namespace dsr {

glm::mat4 Camera::view() const { return glm::lookAt(pos, target, up); }

glm::dmat4 Camera::view_d() const {
    return glm::lookAt(glm::dvec3(pos), glm::dvec3(target), glm::dvec3(up));
}

glm::vec3 Camera::to_eye(glm::vec3 world) const {
    return glm::vec3(view_d() * glm::dvec4(glm::dvec3(world), 1.0));
}

// glm's default clip space is OpenGL's (z in [-1, 1]), which the depth codec assumes.
glm::mat4 Camera::projection(float aspect) const {
    return glm::perspective(glm::radians(fov_deg), aspect, near_plane, far_plane);
}

}  // namespace dsr
