// How much of a light reaches a point: the CPU twin, in double, of lighting.glsl's
// light_contribution factors (no GL). The analytic reference, the ideal counts and the tests use it.
//   distance   Equation 2: max(0, 1 - d / S_radius) (the tutorial's default), or with
//              `attenuation`: 1 / (KC + KL d + KQ d^2) for d < radius, 0 beyond (LearnOpenGL's law,
//              cut where it falls under the threshold, as LearnOpenGL's shader does)
//   spot       GL_SPOT_CUTOFF semantics: 0 unless the angle theta between the axis and the
//              direction from the apex to the point is below the half-angle a; inside,
//              cos(theta)^E (GL_SPOT_EXPONENT) times a smooth edge,
//              smoothstep(cos a, cos((1 - kSpotSoftEdge) a), cos theta), which rises from 0 at the
//              cone's edge to 1 at kSpotSoftEdge of the half-angle inside it (C1, no visible rim)
//   directional l = -dir everywhere, factor 1 (no attenuation)
//   physical   KHR_lights_punctual (its README, "Range Property" and "Inner and Outer Cone
//              Angles"; docs/metal_rough.md): max(min(1 - (d / range)^4, 1), 0) / d^2 for
//              d < radius (1 / d^2 without a range), and a spot's
//              clamp(cos theta * scale + offset, 0, 1)^2 (spot_scale_offset); a directional
//              light's factor is 1, its colour being in lux
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace dsr {

constexpr double kSpotSoftEdge = 0.2;

// LearnOpenGL's light-volume radius: the distance d >= 0 where I_max / (kc + kl d + kq d^2) equals
// `threshold` (I_max: the colour's largest component), i.e. the positive root of
// kq d^2 + kl d + kc - I_max / threshold = 0, computed in the cancellation-free form
// 2c / (kl + sqrt(kl^2 + 4 kq c)) with c = I_max / threshold - kc. 0 when the light is under the
// threshold everywhere (c <= 0). Throws dsr::Error for negative or non-finite coefficients, a
// threshold <= 0, or kl = kq = 0 with c > 0 (the light never falls under the threshold).
double attenuation_radius(double kc, double kl, double kq, double threshold, double i_max);

// cos((1 - kSpotSoftEdge) * a) for a half-angle a in degrees: where the spot's soft edge ends.
double spot_inner_cos(double angle_deg);

// The spot factor for cos(theta) (theta from the axis), half-angle a in degrees, exponent e.
double spot_factor(double cos_theta, double angle_deg, double exponent);

// The distance law at distance d (0 at and beyond the radius; a physical light's 0 at d = 0,
// where 1 / d^2 has no value).
double distance_factor(const Light& light, double d);

// Physical lights' bound (docs/metal_rough.md, "Bounds"): their contribution is counted as
// colour x kPhysicalResponse x factor, and it is negligible under half a step of the 8-bit output.
constexpr double kPhysicalThreshold = 0.5 / 255.0;
constexpr double kPhysicalResponse = 2.0;

// KHR_lights_punctual's range window times the inverse square at d > 0; range <= 0: no window.
double physical_distance_factor(double d, double range);

// The extension's lightAngleScale and lightAngleOffset for cone half-angles in degrees:
// scale = 1 / max(0.001, cos inner - cos outer), offset = -cos outer * scale.
glm::dvec2 spot_scale_offset(double inner_deg, double outer_deg);

// Its angular attenuation: clamp(cos_theta * scale + offset, 0, 1)^2.
double physical_spot_factor(double cos_theta, double inner_deg, double outer_deg);

// The radius beyond which a physical point or spot light adds nothing: the range where there is
// one (the window is 0 from there on), else the d where i_max x response / d^2 = threshold,
// sqrt(i_max x response / threshold); 0 for i_max = 0. Throws dsr::Error for a negative or
// non-finite argument, or a threshold or response <= 0.
double physical_radius(double i_max, double range, double threshold = kPhysicalThreshold,
                       double response = kPhysicalResponse);

// At world-space point p: the unit vector towards the light (l of Equations 3-5) and the factor
// that multiplies I_diff + I_spec (distance law x spot). p at the light's position: factor 0.
struct LightAt {
    glm::dvec3 l{0};
    double factor = 0;
};
LightAt light_at(const Light& light, glm::dvec3 p);

}  // namespace dsr
