// Spot, directional and attenuated lights (docs/light_geometry.md) in the deferred light pass and the forward
// renderers, checked by hand-made geometry (which pixels a cone reaches, the plane a directional
// light gives) and against the analytic trace, which writes the laws again from their
// definitions (src/analysis/analytic_reference.cpp).
#include <cmath>
#include <cstdio>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "analysis/analytic_reference.h"
#include "forward_fixture.h"
#include "render_fixture.h"
#include "scene/light_law.h"

namespace dsr::test {
namespace {

constexpr double kLsb = 1.0 / 255.0;
constexpr int kN = 65;  // odd: the centre pixel's ray is the view axis

// A 6 x 6 plane seen from straight above (render_fixture.h plane_from_above), with no light.
Scene plane_scene(float spec) {
    Scene s = plane_from_above(6);
    s.lights.clear();
    s.materials[0].diffuse = glm::vec3(0.5f, 0.6f, 0.7f);
    s.materials[0].specular = glm::vec3(spec);
    return s;
}

// The point of y = 0 seen through pixel (i, j)'s centre, written from the camera above.
glm::dvec3 plane_point(int i, int j) {
    const double t = std::tan(glm::radians(30.0));
    const double x = ((i + 0.5) / kN * 2 - 1) * t * 5, y = ((j + 0.5) / kN * 2 - 1) * t * 5;
    return {x, 0, -y};  // up is -z: window y grows towards -z
}

// Half a pixel's footprint on the plane, in world units, as an angle margin seen from a light at
// height h straight above: pixels within it of the cone's edge are left out of the inside/outside
// checks.
double pixel_world() { return 2 * std::tan(glm::radians(30.0)) * 5 / kN; }

TEST(LightTypes, SpotLightsInsideItsConeOnly) {
    Scene s = plane_scene(0.25f);
    Light l;
    l.type = Light::Type::spot;
    l.pos = {0.3f, 2.5f, 0.2f};
    l.dir = glm::normalize(glm::vec3(0.2f, -1, 0.1f));
    l.radius = 6;
    l.angle_deg = 30;
    l.exponent = 2;
    l.color = {1, 0.9f, 0.8f};
    s.lights.push_back(l);
    auto def = render_scene(s, kN, kN, ShaderOptions{});
    auto fwd = render_forward(s, kN, kN, forward_mode(ForwardMode::single));
    const Image tr = analytic_trace(s, kN, kN).image;
    const double ambient[3] = {0.1 * 0.5, 0.1 * 0.6, 0.1 * 0.7};
    int inside = 0, outside = 0;
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
            const glm::dvec3 p = plane_point(i, j);
            const glm::dvec3 d = p - glm::dvec3(l.pos);
            const double theta = std::acos(glm::dot(glm::normalize(d), glm::dvec3(l.dir)));
            const double margin = std::atan(pixel_world() / glm::length(d)) * 1.5;
            const float* px = def.image.at(i, j);
            const float* fx = fwd.image.at(i, j);
            if (theta > glm::radians(30.0) + margin) {  // outside: the ambient term alone
                ++outside;
                for (int k = 0; k < 3; ++k) {
                    ASSERT_NEAR(px[k], ambient[k], 0.75 * kLsb) << "deferred lit outside the cone at " << i << "," << j;
                    ASSERT_NEAR(fx[k], ambient[k], 0.75 * kLsb) << "forward lit outside the cone at " << i << "," << j;
                }
            } else if (theta < glm::radians(30.0 * 0.8) - margin) {  // inside the soft edge
                ++inside;
                ASSERT_GT(px[0], ambient[0] + 20 * kLsb) << "unlit inside the cone at " << i << "," << j;
            }
        }
    std::printf("[ stats    ] spot: %d pixels checked inside, %d outside\n", inside, outside);
    EXPECT_GT(inside, 300);
    EXPECT_GT(outside, 1500);
    const ImageDiff d = compare_logged("spot: deferred vs analytic", def.image, tr, 2 * kLsb);
    const ImageDiff f = compare_logged("spot: forward vs analytic", fwd.image, tr, kLsb);
    EXPECT_LE(d.max_lsb(), 3.0);
    EXPECT_LE(d.mean_lsb(), 0.5);
    EXPECT_LE(f.max_lsb(), 1.0);
}

// A directional light on a plane without specular: the same colour on every plane pixel,
// M_amb + M_diff * S * dot(-dir, n), computed here by hand; no scissor, nothing culled.
TEST(LightTypes, DirectionalMatchesTheAnalyticPlane) {
    Scene s = plane_scene(0);
    Light l;
    l.type = Light::Type::directional;
    l.dir = glm::normalize(glm::vec3(0.3f, -1, 0.2f));
    l.color = {0.9f, 0.8f, 0.7f};
    s.lights.push_back(l);
    const double cosn = -l.dir.y;
    const double want[3] = {0.1 * 0.5 + 0.5 * 0.9 * cosn, 0.1 * 0.6 + 0.6 * 0.8 * cosn, 0.1 * 0.7 + 0.7 * 0.7 * cosn};
    auto def = render_scene(s, kN, kN, ShaderOptions{});
    auto fwd = render_forward(s, kN, kN, forward_mode(ForwardMode::multi));
    EXPECT_EQ(def.stats.lights.drawn, 1);
    EXPECT_EQ(def.stats.lights.scissor_pixels, (long long)kN * kN);
    int plane = 0;
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
            const glm::dvec3 p = plane_point(i, j);
            if (std::abs(p.x) > 3 - pixel_world() || std::abs(p.z) > 3 - pixel_world()) continue;
            ++plane;
            for (int k = 0; k < 3; ++k) {
                ASSERT_NEAR(def.image.at(i, j)[k], want[k], 1.0 * kLsb) << "deferred at " << i << "," << j;
                ASSERT_NEAR(fwd.image.at(i, j)[k], want[k], 0.6 * kLsb) << "forward at " << i << "," << j;
            }
        }
    EXPECT_GT(plane, 2000);
    // With a highlight: against the trace.
    Scene g = plane_scene(0.5f);
    g.lights = s.lights;
    const ImageDiff d = compare_logged("directional: deferred vs analytic",
                                       render_scene(g, kN, kN, ShaderOptions{}).image, analytic_trace(g, kN, kN).image,
                                       2 * kLsb);
    EXPECT_LE(d.max_lsb(), 3.0);
}

// The attenuation law: nothing beyond the radius where it falls under the threshold, the law
// inside (against the trace), the same through deferred and forward.
TEST(LightTypes, AttenuationLawAndItsRadius) {
    Scene s = plane_scene(0);
    Light l;
    l.pos = {0, 0.5f, 0};
    l.color = {1, 1, 1};
    l.attenuation = true;
    l.kc = 1, l.kl = 0.7f, l.kq = 1.8f;
    l.threshold = 0.08f;
    l.radius = float(attenuation_radius(l.kc, l.kl, l.kq, l.threshold, 1.0));
    s.lights.push_back(l);
    ASSERT_GT(l.radius, 1.5f);
    ASSERT_LT(l.radius, 2.9f);  // the cut lies on the plane
    auto def = render_scene(s, kN, kN, ShaderOptions{});
    int beyond = 0, within = 0;
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
            const glm::dvec3 p = plane_point(i, j);
            if (std::abs(p.x) > 2.9 || std::abs(p.z) > 2.9) continue;
            const double dist = glm::length(p - glm::dvec3(l.pos));
            const float r = def.image.at(i, j)[0];
            if (dist > l.radius + pixel_world()) {
                ++beyond;
                ASSERT_NEAR(r, 0.05, 0.75 * kLsb) << "lit beyond the radius at " << i << "," << j;
            } else if (dist < l.radius - pixel_world()) {
                ++within;  // at least the threshold's share: 0.05 * M_diff * cos
                const double cosn = 0.5 / dist;
                ASSERT_GT(r, 0.05 + 0.05 * 0.5 * cosn - 1.5 * kLsb) << "under the threshold within it at " << i << "," << j;
            }
        }
    EXPECT_GT(beyond, 100);
    EXPECT_GT(within, 500);
    const ImageDiff d = compare_logged("attenuation: deferred vs analytic", def.image, analytic_trace(s, kN, kN).image,
                                       2 * kLsb);
    EXPECT_LE(d.max_lsb(), 3.0);
}

// data/lights.scene (spots, a directional light, both distance laws): deferred against the forward
// reference and both against the analytic trace.
TEST(LightTypes, DeferredMatchesForwardOnTheLightsScene) {
    const Scene s = load_scene(resource_dir("data") + "/lights.scene");
    const int n = 96;
    auto def = render_scene(s, n, n, ShaderOptions{});
    auto fwd = render_forward(s, n, n, forward_mode(ForwardMode::single));
    auto multi = render_forward(s, n, n, forward_mode(ForwardMode::multi));
    const AnalyticTrace tr = analytic_trace(s, n, n);
    const auto mask = interior_mask(tr, n, n);
    const ImageDiff d = compare_logged("lights.scene: deferred vs forward", def.image, fwd.image, 2 * kLsb);
    const ImageDiff m = compare_logged("lights.scene: forward multi vs single", multi.image, fwd.image, kLsb);
    const ImageDiff a = compare_images_masked(fwd.image, tr.image, mask, 2 * kLsb);
    std::printf("[ stats    ] forward vs analytic (interior): max %.2f LSB, mean %.3f\n", a.max_lsb(), a.mean_lsb());
    if (d.max_lsb() > 8) write_failure_images("lights_deferred_vs_forward", def.image, fwd.image);
    EXPECT_EQ(def.stats.lights.total, 5);
    EXPECT_LE(d.mean_lsb(), 0.3);
    EXPECT_LE(d.failing_fraction(), 0.003);
    EXPECT_LE(d.max_lsb(), 8.0);
    EXPECT_LE(m.max_lsb(), 1.0);
    EXPECT_LE(a.mean_lsb(), 0.3);
    // Not a dark image passing by default: the spots light a good part of it.
    double sum = 0;
    for (size_t p = 0; p < def.image.rgba.size(); p += 4) sum += def.image.rgba[p];
    EXPECT_GT(sum / (n * n), 0.08);
}

}  // namespace
}  // namespace dsr::test

namespace dsr::test {
namespace {

// The general light_contribution shades the tutorial's point light exactly as the LIGHT_POINT_ONLY
// variant does: a dark directional light in the scene switches the forward renderer to the
// general shader and must change no pixel.
TEST(LightTypes, GeneralShaderMatchesThePointOnlyVariant) {
    Scene s = default_scene();
    const int n = 96;
    auto point_only = render_forward(s, n, n, forward_mode(ForwardMode::single));
    Light dark;
    dark.type = Light::Type::directional;
    dark.dir = {0, -1, 0};
    dark.color = glm::vec3(0);
    s.lights.push_back(dark);
    auto general = render_forward(s, n, n, forward_mode(ForwardMode::single));
    const ImageDiff d = compare_logged("forward: general shader vs point-only variant", general.image, point_only.image, kLsb);
    EXPECT_EQ(d.max_lsb(), 0.0);
}

}  // namespace
}  // namespace dsr::test
