// The bench's generated light sets (src/analysis/bench_scenes.h, docs/light_geometry.md), checked without GL:
// in N-overlap every lit point lies inside at least 8 lights; in N-large every light's sphere
// covers most of the screen; --lights items parse as documented.
#include <cmath>
#include <cstdlib>
#include <cstdio>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "analysis/bench_scenes.h"
#include "analysis/ideal_fragments.h"
#include "deferred/light_volume.h"
#include "dsr_error.h"
#include "platform/resources.h"
#include "scene/light_law.h"

namespace {

using namespace dsr;

TEST(BenchScenes, OverlapPutsEveryLitPointInsideAtLeastEightLights) {
    const Scene base = load_scene(resource_dir("data") + "/default.scene");
    const Scene s = with_overlapping_lights(base, 1024);
    ASSERT_EQ(s.lights.size(), 1024u);
    long long lit = 0, sum = 0;
    int min_lit = 1 << 30;
    // Points over the floor and up the walls' height, on a grid.
    for (int i = 0; i < 60; ++i)
        for (int k = 0; k < 60; ++k)
            for (float y : {0.0f, 0.5f, 1.5f}) {
                const glm::dvec3 p(-6 + 12 * (i + 0.5) / 60, y, -6 + 12 * (k + 0.5) / 60);
                int n = 0;
                for (const Light& l : s.lights) n += l.color != glm::vec3(0) && inside_volume(light_volume(l), p);
                if (n == 0) continue;
                ++lit, sum += n;
                min_lit = std::min(min_lit, n);
            }
    std::printf("[ stats    ] 1024-overlap: %lld lit sample points, each in %d..., mean %.1f lights\n", lit, min_lit,
                double(sum) / double(lit));
    EXPECT_GT(lit, 5000);
    EXPECT_GE(min_lit, 8);
    EXPECT_GT(double(sum) / double(lit), 12.0);
    EXPECT_THROW(with_overlapping_lights(base, 1020), Error);
}

TEST(BenchScenes, LargeLightsEachCoverMostOfTheScreen) {
    const Scene s = large_lights_scene(32);
    ASSERT_EQ(s.lights.size(), 32u);
    EXPECT_EQ(s.objects.size(), 9u);
    const int w = 800, h = 600;
    const glm::mat4 view = s.camera.view(), proj = s.camera.projection(float(w) / h);
    double min_frac = 1, rmin = 1e9, rmax = 0;
    for (const Light& l : s.lights) {
        EXPECT_TRUE(l.attenuation);
        rmin = std::min(rmin, double(l.radius)), rmax = std::max(rmax, double(l.radius));
        const ScissorRect r = volume_scissor(transformed(light_volume(l), view), proj[0][0], proj[1][1],
                                             s.camera.near_plane, w, h);
        min_frac = std::min(min_frac, double(r.area()) / (w * h));
    }
    std::printf("[ stats    ] 32-large: radii %.2f..%.2f, smallest rectangle %.0f%% of the screen\n", rmin, rmax,
                100 * min_frac);
    EXPECT_GT(min_frac, 0.5);
    EXPECT_GT(rmin, 3.0);
}

// The law goal's twin: the same lights with Equation 2's law at the same radius, so each light's
// volume (and so every pixel-light pair) is the scene's, and only the law's value differs.
TEST(BenchScenes, LinearLawTwinKeepsEveryVolume) {
    const Scene s = large_lights_scene(32);
    const Scene t = linear_law_twin(s);
    ASSERT_EQ(t.lights.size(), s.lights.size());
    int differs = 0;
    for (size_t i = 0; i < s.lights.size(); ++i) {
        const Light &a = s.lights[i], &b = t.lights[i];
        EXPECT_TRUE(a.attenuation);
        EXPECT_FALSE(b.attenuation);
        EXPECT_EQ(a.pos, b.pos);
        EXPECT_EQ(a.color, b.color);
        const LightVolume va = light_volume(a), vb = light_volume(b);
        EXPECT_EQ(va.pos, vb.pos);
        EXPECT_EQ(va.radius, vb.radius);
        // Equation 2 at half the radius is 1/2; the attenuation law there is not.
        const double d = 0.5 * a.radius;
        EXPECT_DOUBLE_EQ(distance_factor(b, d), 0.5);
        differs += std::abs(distance_factor(a, d) - 0.5) > 0.01;
        EXPECT_EQ(distance_factor(b, 1.001 * b.radius), 0.0);
    }
    EXPECT_EQ(differs, 32);
    EXPECT_EQ(t.objects.size(), s.objects.size());
}

// N-large is LearnOpenGL's demo as its source sets it up: its object positions, its camera, and its
// lights from srand(13) in the order it draws them (x, y, z, r, g, b per light from rand() % 100),
// the same on every platform. The first light worked by hand from glibc's first six rand() % 100
// after srand(13) (90 81 79 91 64 24); on glibc every light against the C library itself.
TEST(BenchScenes, LargeIsLearnOpenGLsDemo) {
    const Scene s = large_lights_scene(32);
    ASSERT_EQ(s.objects.size(), 9u);
    EXPECT_EQ(s.camera.pos, glm::vec3(0, 0, 5));
    EXPECT_EQ(s.camera.fov_deg, 45.0f);
    EXPECT_EQ(s.ambient, glm::vec3(0.1f));  // the demo's `lighting = Diffuse * 0.1`
    for (const Object& o : s.objects) {
        const glm::dvec3 at(o.model[3]);
        EXPECT_EQ(at.y, -0.5);
        EXPECT_TRUE(std::abs(at.x) == 3.0 || at.x == 0.0) << at.x;
        EXPECT_TRUE(std::abs(at.z) == 3.0 || at.z == 0.0) << at.z;
    }
    const Light& first = s.lights[0];
    EXPECT_FLOAT_EQ(first.pos.x, 0.90f * 6 - 3);
    EXPECT_FLOAT_EQ(first.pos.y, 0.81f * 6 - 4);
    EXPECT_FLOAT_EQ(first.pos.z, 0.79f * 6 - 3);
    EXPECT_FLOAT_EQ(first.color.r, 91 / 200.0f + 0.5f);
    EXPECT_FLOAT_EQ(first.color.g, 64 / 200.0f + 0.5f);
    EXPECT_FLOAT_EQ(first.color.b, 24 / 200.0f + 0.5f);
    for (const Light& l : s.lights) {
        EXPECT_TRUE(l.attenuation);
        EXPECT_EQ(l.kc, 1.0f);
        EXPECT_EQ(l.kl, 0.7f);
        EXPECT_EQ(l.kq, 1.8f);
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(l.color[c], 0.5f);
            EXPECT_LT(l.color[c], 1.0f);
        }
        EXPECT_GE(l.pos.y, -4.0f);
        EXPECT_LT(l.pos.y, 2.0f);
    }
#ifdef __GLIBC__
    std::srand(13);
    for (const Light& l : s.lights) {
        glm::vec3 pos, colour;
        for (int k = 0; k < 3; ++k) pos[k] = float((std::rand() % 100) / 100.0 * 6.0 - (k == 1 ? 4.0 : 3.0));
        for (int k = 0; k < 3; ++k) colour[k] = float(std::rand() % 100) / 200.0f + 0.5f;
        EXPECT_EQ(l.pos, pos);
        EXPECT_EQ(l.color, colour);
    }
#endif
    // More lights continue the same sequence.
    const Scene more = large_lights_scene(64);
    for (size_t i = 0; i < s.lights.size(); ++i) EXPECT_EQ(more.lights[i].pos, s.lights[i].pos);
}

// The ideal count over cones and full-screen volumes: the tiled count equals the brute-force one,
// a cone counts only points within its angle, a directional light every surface point.
TEST(BenchScenes, IdealCountsUseTheVolumes) {
    SurfacePoints sp;
    sp.width = 64, sp.height = 48;
    for (int y = 0; y < sp.height; ++y)
        for (int x = 0; x < sp.width; ++x) {  // a tilted floor under the camera, a hole of background
            const double px = (x - 32) * 0.1, pz = -2 - y * 0.1;
            sp.p.push_back({px, -1 + 0.02 * y, pz});
            sp.surface.push_back(!(x > 40 && y > 30));
        }
    long long surface = 0;
    for (uint8_t v : sp.surface) surface += v;
    EyeVolume sphere, cone, all;
    sphere.pos = cone.pos = {0.3, 0.5, -4};
    sphere.radius = cone.radius = 2.5;
    cone.kind = LightVolume::Kind::cone;
    cone.axis = glm::normalize(glm::dvec3(0.2, -1, -0.3));
    cone.cos_angle = std::cos(glm::radians(30.0));
    all.kind = LightVolume::Kind::full_screen;
    for (const auto& set : {std::vector<EyeVolume>{sphere}, {cone}, {all}, {sphere, cone, all}})
        EXPECT_EQ(ideal_fragments(sp, set), ideal_fragments_brute(sp, set));
    const long long ns = ideal_fragments(sp, {sphere}), nc = ideal_fragments(sp, {cone});
    std::printf("[ stats    ] ideal: sphere %lld, its 30-degree cone %lld, directional %lld of %lld surface\n", ns, nc,
                ideal_fragments(sp, {all}), surface);
    EXPECT_GT(nc, 0);
    EXPECT_LT(nc, ns / 2);
    EXPECT_EQ(ideal_fragments(sp, {all}), surface);
}

TEST(BenchScenes, LightSpecs) {
    EXPECT_EQ(parse_light_spec("own")->count, -1);
    EXPECT_EQ(parse_light_spec("256")->count, 256);
    EXPECT_EQ(parse_light_spec("256")->set, LightSet::spread);
    EXPECT_EQ(parse_light_spec("1024-overlap")->set, LightSet::overlap);
    EXPECT_EQ(parse_light_spec("32-large")->set, LightSet::large);
    EXPECT_EQ(parse_light_spec("32-large")->count, 32);
    for (const char* bad : {"", "-overlap", "12-overlap", "x-large", "-5", "65537", "32-big", "own-large"})
        EXPECT_FALSE(parse_light_spec(bad).has_value()) << bad;
    EXPECT_EQ(bench_scene_name("default", *parse_light_spec("1024-overlap")), "default-overlap");
    EXPECT_EQ(bench_scene_name("default", *parse_light_spec("32-large")), "large");
}

}  // namespace

// The shadow rows' sets: N spot lights casting shadows down on the floor, or the scene's own.
TEST(BenchScenes, ShadowSets) {
    const auto s8 = dsr::parse_light_spec("8-shadow");
    ASSERT_TRUE(s8);
    EXPECT_EQ(s8->count, 8);
    EXPECT_EQ(s8->set, dsr::LightSet::shadow);
    const auto own = dsr::parse_light_spec("own-shadow");
    ASSERT_TRUE(own);
    EXPECT_EQ(own->count, -1);
    EXPECT_EQ(own->set, dsr::LightSet::shadow);
    EXPECT_FALSE(dsr::parse_light_spec("-shadow"));
    EXPECT_FALSE(dsr::parse_light_spec("x-shadow"));
    const dsr::Scene base = dsr::load_scene(dsr::resource_dir("data") + "/default.scene");
    const dsr::Scene spots = dsr::bench_scene(base, *s8);
    ASSERT_EQ(spots.lights.size(), 8u);
    const dsr::Scene plain = dsr::with_generated_lights(base, 8);
    for (size_t i = 0; i < spots.lights.size(); ++i) {
        EXPECT_EQ(spots.lights[i].type, dsr::Light::Type::spot);
        EXPECT_TRUE(spots.lights[i].shadow.on);
        EXPECT_FLOAT_EQ(spots.lights[i].pos.y, plain.lights[i].pos.y + 0.5f * plain.lights[i].radius);
    }
    const dsr::Scene mine = dsr::bench_scene(base, *own);
    ASSERT_EQ(mine.lights.size(), base.lights.size());
    for (const dsr::Light& l : mine.lights) {
        EXPECT_TRUE(l.shadow.on);
        EXPECT_EQ(l.type, dsr::Light::Type::point);
    }
    EXPECT_EQ(dsr::bench_scene_name("default", *own), "default-shadow");
}
