#include "scene/light_law.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "dsr_error.h"

namespace dsr {

double attenuation_radius(double kc, double kl, double kq, double threshold, double i_max) {
    if (!std::isfinite(kc) || !std::isfinite(kl) || !std::isfinite(kq) || kc < 0 || kl < 0 || kq < 0)
        throw Error("attenuation: KC, KL and KQ must be finite and >= 0");
    if (!std::isfinite(threshold) || !(threshold > 0))
        throw Error("attenuation: the threshold must be > 0, got " + std::to_string(threshold));
    const double c = i_max / threshold - kc;
    if (!(c > 0)) return 0.0;  // under the threshold at d = 0 already: it lights nothing
    if (kl == 0 && kq == 0)
        throw Error("attenuation: with KL = KQ = 0 the light never falls under the threshold");
    return 2.0 * c / (kl + std::sqrt(kl * kl + 4.0 * kq * c));
}

double spot_inner_cos(double angle_deg) { return std::cos(glm::radians((1.0 - kSpotSoftEdge) * angle_deg)); }

double spot_factor(double cos_theta, double angle_deg, double exponent) {
    const double c_out = std::cos(glm::radians(angle_deg));
    if (!(cos_theta > c_out)) return 0.0;  // GL_SPOT_CUTOFF: nothing on or outside the cone
    const double c_in = spot_inner_cos(angle_deg);
    const double t = std::clamp((cos_theta - c_out) / (c_in - c_out), 0.0, 1.0);
    const double edge = t * t * (3.0 - 2.0 * t);  // GLSL smoothstep
    return (exponent > 0 ? std::pow(cos_theta, exponent) : 1.0) * edge;
}

double physical_distance_factor(double d, double range) {
    if (!(d > 0)) return 0.0;
    const double window = range > 0 ? std::clamp(1.0 - std::pow(d / range, 4.0), 0.0, 1.0) : 1.0;
    return window / (d * d);
}

glm::dvec2 spot_scale_offset(double inner_deg, double outer_deg) {
    const double ci = std::cos(glm::radians(inner_deg)), co = std::cos(glm::radians(outer_deg));
    const double scale = 1.0 / std::max(0.001, ci - co);
    return {scale, -co * scale};
}

double physical_spot_factor(double cos_theta, double inner_deg, double outer_deg) {
    const glm::dvec2 so = spot_scale_offset(inner_deg, outer_deg);
    const double t = std::clamp(cos_theta * so.x + so.y, 0.0, 1.0);
    return t * t;
}

double physical_radius(double i_max, double range, double threshold, double response) {
    if (!std::isfinite(i_max) || !std::isfinite(range) || i_max < 0 || range < 0)
        throw Error("physical light: the intensity and the range must be finite and >= 0");
    if (!std::isfinite(threshold) || !std::isfinite(response) || !(threshold > 0) || !(response > 0))
        throw Error("physical light: the threshold and the response must be finite and > 0");
    if (range > 0) return range;
    return std::sqrt(i_max * response / threshold);
}

double distance_factor(const Light& light, double d) {
    const double r = light.radius;
    if (!(d < r)) return 0.0;
    if (light.physical) return physical_distance_factor(d, light.range);
    if (!light.attenuation) return std::max(0.0, 1.0 - d / r);  // Equation 2
    return 1.0 / (double(light.kc) + double(light.kl) * d + double(light.kq) * d * d);
}

LightAt light_at(const Light& light, glm::dvec3 p) {
    LightAt a;
    if (light.type == Light::Type::directional) {
        a.l = -glm::normalize(glm::dvec3(light.dir));
        a.factor = 1.0;
        return a;
    }
    const glm::dvec3 v = glm::dvec3(light.pos) - p;
    const double d = glm::length(v);
    if (!(d > 0)) return a;
    a.l = v / d;
    a.factor = distance_factor(light, d);
    if (light.type == Light::Type::spot && a.factor > 0 && light.physical)
        a.factor *= physical_spot_factor(glm::dot(-a.l, glm::normalize(glm::dvec3(light.dir))), light.inner_deg,
                                         light.angle_deg);
    else if (light.type == Light::Type::spot && a.factor > 0)
        a.factor *= spot_factor(glm::dot(-a.l, glm::normalize(glm::dvec3(light.dir))), light.angle_deg,
                                light.exponent);
    return a;
}

}  // namespace dsr
