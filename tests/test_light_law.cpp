// The light laws of scene/light_law.h: the attenuation radius is where LearnOpenGL's law crosses
// the threshold (checked by evaluating the law, and against LearnOpenGL's own formula); the spot
// factor follows GL_SPOT_CUTOFF (nothing outside) with a smooth, monotone edge.
#include <cmath>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "dsr_error.h"
#include "scene/light_law.h"

namespace {

double law(double kc, double kl, double kq, double d) { return kc + kl * d + kq * d * d; }

TEST(LightLaw, AttenuationRadiusIsWhereTheLawCrossesTheThreshold) {
    const double cases[][5] = {  // kc, kl, kq, threshold, i_max
        {1, 0.7, 1.8, 5.0 / 256, 1},   {1, 0.09, 0.032, 5.0 / 256, 1}, {1, 0.0014, 0.000007, 5.0 / 256, 0.8},
        {1, 0, 0.5, 0.01, 2},          {1, 0.5, 0, 0.01, 1},           {0.5, 1e-6, 1e-9, 1.0 / 256, 1}};
    for (const auto& c : cases) {
        const double r = dsr::attenuation_radius(c[0], c[1], c[2], c[3], c[4]);
        ASSERT_GT(r, 0);
        // The light I_max / law(d) is the threshold at r, above it just inside, below just beyond.
        EXPECT_NEAR(c[4] / law(c[0], c[1], c[2], r) / c[3], 1.0, 1e-12);
        EXPECT_GT(c[4] / law(c[0], c[1], c[2], r * (1 - 1e-6)), c[3]);
        EXPECT_LT(c[4] / law(c[0], c[1], c[2], r * (1 + 1e-6)), c[3]);
        if (c[2] > 0) {  // LearnOpenGL's expression, in double
            const double lo = (-c[1] + std::sqrt(c[1] * c[1] - 4 * c[2] * (c[0] - c[4] / c[3]))) / (2 * c[2]);
            EXPECT_NEAR(r / lo, 1.0, 1e-9);
        }
    }
    // LearnOpenGL's demo light (1, 0.7, 1.8) of colour 1, worked by hand: 1.8 d^2 + 0.7 d - 50.2 = 0.
    EXPECT_NEAR(dsr::attenuation_radius(1, 0.7, 1.8, 5.0 / 256, 1), 5.0901, 1e-4);
    EXPECT_EQ(dsr::attenuation_radius(60, 1, 1, 5.0 / 256, 1), 0.0);  // under the threshold everywhere
    EXPECT_THROW(dsr::attenuation_radius(1, 0, 0, 5.0 / 256, 1), dsr::Error);
    EXPECT_THROW(dsr::attenuation_radius(1, -1, 1, 5.0 / 256, 1), dsr::Error);
    EXPECT_THROW(dsr::attenuation_radius(1, 1, 1, 0, 1), dsr::Error);
}

TEST(LightLaw, SpotFactorIsZeroOutsideAndSmoothInside) {
    for (double a : {5.0, 30.0, 60.0, 90.0}) {
        const double ca = std::cos(glm::radians(a));
        EXPECT_EQ(dsr::spot_factor(ca, a, 0), 0.0);
        EXPECT_EQ(dsr::spot_factor(std::cos(glm::radians(a * 1.01)), a, 0), 0.0);
        EXPECT_EQ(dsr::spot_factor(1.0, a, 0), 1.0);
        EXPECT_EQ(dsr::spot_factor(std::cos(glm::radians(a * (1 - dsr::kSpotSoftEdge) * 0.99)), a, 0), 1.0);
        double last = 0;
        for (int i = 1; i <= 100; ++i) {  // rises monotonically from the edge inwards, continuously
            const double f = dsr::spot_factor(std::cos(glm::radians(a * (1 - i / 100.0))), a, 0);
            EXPECT_GE(f, last);
            EXPECT_LE(f - last, 0.1);
            last = f;
        }
        // The exponent: cos(theta)^E inside the soft edge, as GL_SPOT_EXPONENT.
        const double c = std::cos(glm::radians(a * 0.5));
        EXPECT_NEAR(dsr::spot_factor(c, a, 8), std::pow(c, 8), 1e-12);
    }
}

TEST(LightLaw, LightAtByType) {
    dsr::Light d;
    d.type = dsr::Light::Type::directional;
    d.dir = glm::normalize(glm::vec3(1, -2, 0.5f));
    const dsr::LightAt a = dsr::light_at(d, glm::dvec3(100, -40, 7));
    EXPECT_NEAR(glm::length(a.l + glm::dvec3(d.dir)), 0, 1e-7);
    EXPECT_EQ(a.factor, 1.0);
    dsr::Light p;  // Equation 2 by default
    p.pos = {0, 0, 0}, p.radius = 4;
    EXPECT_NEAR(dsr::light_at(p, {1, 0, 0}).factor, 0.75, 1e-12);
    EXPECT_EQ(dsr::light_at(p, {4, 0, 0}).factor, 0.0);
    p.attenuation = true, p.kc = 1, p.kl = 0.5f, p.kq = 0.25f;
    EXPECT_NEAR(dsr::light_at(p, {0, 2, 0}).factor, 1.0 / 3.0, 1e-7);
    EXPECT_EQ(dsr::light_at(p, {0, 5, 0}).factor, 0.0);
}

}  // namespace
