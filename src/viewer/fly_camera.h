// The viewer's camera control (WASD + mouse look) as pure math, so it can be tested without a
// window: yaw about the scene camera's up vector, pitch about the camera's right vector, kept
// short of straight up or down so the look-at basis stays defined.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace dsr {

struct FlyCamera {
    glm::vec3 pos{0}, forward{0, 0, -1}, world_up{0, 1, 0};  // forward and world_up unit length
    float speed = 1.0f;                                      // world units per second

    // Looking as `c` does, at a speed of half the distance to its target per second.
    static FlyCamera from(const Camera& c);
    // Turns by yaw (about world_up, positive to the left) and pitch (positive up), in radians;
    // the angle to world_up stays within [1, 179] degrees.
    void look(float yaw, float pitch);
    // Circles `centre` at the current distance from it: turns as look(yaw, pitch) does, then puts
    // pos where forward points at `centre` (the viewer's left-drag: a model seen from any side).
    void orbit(glm::vec3 centre, float yaw, float pitch);
    // Moves along right (x), world_up (y) and forward (z) for dt seconds at speed * scale.
    void move(glm::vec3 dir, float dt, float scale);
    // `base` (fov, near, far) placed where this camera is: target = pos + forward.
    Camera apply(const Camera& base) const;
};

}  // namespace dsr
