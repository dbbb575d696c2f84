// Bounding spheres of a scene's objects, in world space: what decides which lights reach an
// object (the forward renderers, the transparent pass) and the back-to-front order of
// transparent objects. Pure, no GL.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace dsr {

struct ObjectBounds {
    glm::vec3 centre{0};
    float radius = 0;
};

// One per Scene::objects entry: the mesh's bounding-box centre and the radius to its farthest
// vertex, moved by the object's transform in double (rigid with a uniform scale: the radius
// scales by the length of the model's first column), widened for float rounding so it stays
// conservative.
std::vector<ObjectBounds> object_bounds(const Scene& scene);

}  // namespace dsr
