#include "viewer/scissor_overlay.h"

#include "deferred/culling.h"

namespace dsr {

std::vector<LightRect> light_scissor_rects(const Scene& scene, const glm::mat4& view, const glm::mat4& proj, int w, int h,
                                           bool scissors, bool skip_empty) {
    std::vector<LightRect> out;
    const auto frustum = frustum_planes(proj * view);
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        if (sphere_outside(frustum, light.pos, light.radius)) continue;
        if (skip_empty && light.color.r <= 0 && light.color.g <= 0 && light.color.b <= 0) continue;
        const glm::vec3 eye = glm::vec3(view * glm::vec4(light.pos, 1.0f));
        ScissorRect r = light_scissor(eye, light.radius, proj[0][0], proj[1][1], scene.camera.near_plane, w, h);
        if (r.empty()) {
            if (skip_empty) continue;
            r = ScissorRect{0, 0, w, h};
        }
        if (!scissors) r = ScissorRect{0, 0, w, h};
        out.push_back({int(i), r});
    }
    return out;
}

}  // namespace dsr
