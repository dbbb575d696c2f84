#include "viewer/fly_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace dsr {

FlyCamera FlyCamera::from(const Camera& c) {
    FlyCamera f;
    f.pos = c.pos;
    const glm::vec3 d = c.target - c.pos;
    const float len = glm::length(d);
    f.forward = len > 0 ? d / len : glm::vec3(0, 0, -1);
    f.world_up = glm::length(c.up) > 0 ? glm::normalize(c.up) : glm::vec3(0, 1, 0);
    f.speed = len > 0 ? 0.5f * len : 1.0f;
    return f;
}

void FlyCamera::look(float yaw, float pitch) {
    glm::vec3 f = glm::vec3(glm::rotate(glm::mat4(1), yaw, world_up) * glm::vec4(forward, 0));
    // Pitch, clamped so the angle between forward and world_up stays in [1, 179] degrees.
    const float angle = std::acos(std::clamp(glm::dot(glm::normalize(f), world_up), -1.0f, 1.0f));
    const float lo = glm::radians(1.0f), hi = glm::radians(179.0f);
    const float target_angle = std::clamp(angle - pitch, lo, hi);
    const glm::vec3 right = glm::cross(f, world_up);
    if (glm::length(right) > 1e-6f) {
        f = glm::vec3(glm::rotate(glm::mat4(1), angle - target_angle, glm::normalize(right)) * glm::vec4(f, 0));
    }
    forward = glm::normalize(f);
}

void FlyCamera::orbit(glm::vec3 centre, float yaw, float pitch) {
    const float d = glm::length(centre - pos);
    look(yaw, pitch);
    pos = centre - forward * d;
}

void FlyCamera::move(glm::vec3 dir, float dt, float scale) {
    const glm::vec3 right = glm::normalize(glm::cross(forward, world_up));
    pos += (right * dir.x + world_up * dir.y + forward * dir.z) * (speed * scale * dt);
}

Camera FlyCamera::apply(const Camera& base) const {
    Camera c = base;
    c.pos = pos;
    c.target = pos + forward;
    c.up = world_up;
    return c;
}

}  // namespace dsr
