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

// The distance law at distance d (0 at and beyond the radius).
double distance_factor(const Light& light, double d);

// At world-space point p: the unit vector towards the light (l of Equations 3-5) and the factor
// that multiplies I_diff + I_spec (distance law x spot). p at the light's position: factor 0.
struct LightAt {
    glm::dvec3 l{0};
    double factor = 0;
};
LightAt light_at(const Light& light, glm::dvec3 p);

}  // namespace dsr
