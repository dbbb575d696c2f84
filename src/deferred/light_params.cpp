#include "deferred/light_params.h"

#include <cmath>

#include "scene/light_law.h"

namespace dsr {

LightParams light_params(const Light& light, const glm::mat4& view) {
    return light_params(light, view, glm::vec3(view * glm::vec4(light.pos, 1.0f)));
}

LightParams light_params(const Light& light, const glm::mat4& view, glm::vec3 eye_pos) {
    LightParams p;
    p.pos = glm::vec4(eye_pos, light.radius);
    const float type = light.type == Light::Type::point ? 0.0f : light.type == Light::Type::spot ? 1.0f : 2.0f;
    p.color = glm::vec4(light.color, type);
    if (light.type != Light::Type::point) {
        const glm::vec3 d = glm::normalize(glm::mat3(view) * light.dir);
        const float c = light.type == Light::Type::spot ? float(std::cos(glm::radians(double(light.angle_deg)))) : -1.0f;
        p.dir = glm::vec4(d, c);
    }
    if (light.physical) {
        // KHR_lights_punctual: the window's 1 / range^2 (0: none), law 2; a spot's scale and offset.
        const double range = light.range;
        p.att = glm::vec4(range > 0 ? float(1.0 / (range * range)) : 0.0f, 0, 0, 2.0f);
        if (light.type == Light::Type::spot)
            p.spot = glm::vec4(glm::vec2(spot_scale_offset(light.inner_deg, light.angle_deg)), 0, 0);
        return p;
    }
    if (light.type == Light::Type::spot)
        p.spot = glm::vec4(float(spot_inner_cos(light.angle_deg)), light.exponent, 0, 0);
    if (light.attenuation) p.att = glm::vec4(light.kc, light.kl, light.kq, 1.0f);
    return p;
}

LightParams light_params(const Light& light, const Camera& camera) { return light_params(light, EyeTransform(camera)); }

LightParams light_params(const Light& light, const EyeTransform& eye) {
    return light_params(light, eye.view, eye.to_eye(light.pos));
}

}  // namespace dsr
