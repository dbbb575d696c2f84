// Shared by tests/test_shadows.cpp and tests/test_forward_shadows.cpp: the box floating over a
// plane under one shadowed light of each type.
#pragma once
#include "render_fixture.h"

namespace dsr::test {

// A grey plane, a box floating over its centre (bottom at y = 1), a small sphere far off to the
// side, and one light of `type` with a shadow.
inline Scene box_scene(Light::Type type) {
    Scene s;
    s.camera.pos = {0, 6, 6};
    s.camera.target = {0, 0, 0};
    s.camera.near_plane = 0.1f;
    s.camera.far_plane = 60;
    s.ambient = glm::vec3(0.1f);
    Material m;
    m.name = "grey";
    m.diffuse = glm::vec3(0.8f);
    s.materials.push_back(m);
    add_plane(s, 8, {0, 0, 0}, 0);
    add_box(s, {1, 1, 1}, {0, 1.5f, 0}, 0);
    add_sphere(s, 0.5f, {30, 0, 0}, 0, 8, 4);  // outside every map but the directional one's scene box
    Light l;
    l.type = type;
    l.pos = {0, 5, 0};
    l.dir = {0, -1, 0};
    l.angle_deg = 40;
    l.radius = 10;
    if (type == Light::Type::directional) l.dir = glm::normalize(glm::vec3(0.3f, -1, 0));
    l.shadow.on = true;
    s.lights.push_back(l);
    return s;
}

}  // namespace dsr::test
