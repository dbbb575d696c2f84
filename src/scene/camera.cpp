#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene.h"

namespace dsr {

glm::mat4 Camera::view() const { return glm::lookAt(pos, target, up); }

// glm's default clip space is OpenGL's (z in [-1, 1]), which the depth codec assumes.
glm::mat4 Camera::projection(float aspect) const {
    return glm::perspective(glm::radians(fov_deg), aspect, near_plane, far_plane);
}

}  // namespace dsr
