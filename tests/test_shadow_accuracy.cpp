// Shadow maps against the analytic reference's shadow rays (docs/shadow_accuracy.md), on
// data/shadow.scene: a box resting on a floor under a spot, a directional and a point light, each
// with `shadow` at the default map size, bias and slope. On both depth paths (depth textures with
// ARB_shadow, and the RGB8-packed maps `--caps no-depth-texture` forces). The measures are
// src/analysis/shadow_metrics.h's; every number is printed.
//   - edge: each pixel the renderer and the trace classify differently is within 1.5 pixels of
//     the traced shadow's edge;
//   - acne: no pixel darker than the reference by more than 8 LSB outside a 2-pixel band of the
//     traced edges (and silhouettes);
//   - peter-panning: of the traced shadow's pixels within 3 pixels of the box (its contact with
//     the floor, and the box's edges seen from the camera), at most 5% lit by the renderer;
//   - the two depth paths classify at most 1% of the considered pixels differently.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "analysis/analytic_reference.h"
#include "analysis/shadow_metrics.h"
#include "render_fixture.h"

using namespace dsr;
using namespace dsr::test;

namespace {
constexpr int kSize = 256;
constexpr double kMinContrast = 24.0 / 255.0;  // a light's term that makes "shadowed" meaningful

Scene shadow_scene() { return load_scene(resource_dir("data") + "/shadow.scene"); }

struct DepthPathCase {
    const char* name;
    std::vector<std::string> caps_off;  // probe_caps' force_off
};
const std::vector<DepthPathCase>& depth_paths() {
    static const std::vector<DepthPathCase> p = {{"depth texture", {}}, {"packed (no-depth-texture)", {"no-depth-texture"}}};
    return p;
}

// The options RenderOptions::resolved gives a scene with shadowed lights; without depth textures
// the G-buffer is packed too (as `dsr render --caps no-depth-texture` chooses).
ShaderOptions shadowed_options(const Scene& s, bool shadows, const DepthPathCase& path) {
    ShaderOptions o;
    if (!path.caps_off.empty()) o.depth = DepthPath::packed;
    o.shadows.on = shadows;
    for (const Light& l : s.lights) o.shadow_lights = o.shadow_lights || (shadows && l.shadow.on);
    return o;
}

Scene with_lights(Scene s, std::vector<Light> lights) {
    s.lights = std::move(lights);
    return s;
}

Mask mesh_mask(const AnalyticTrace& t, int mesh) {
    Mask m(t.mesh.size());
    for (size_t p = 0; p < m.size(); ++p) m[p] = t.mesh[p] == mesh;
    return m;
}

const char* light_name(const Light& l) {
    return l.type == Light::Type::spot ? "spot" : l.type == Light::Type::directional ? "directional" : "point";
}

// Skips (with the reason) while the renderer draws no shadow maps for a scene that asks for them.
bool renderer_has_shadows(const Scene& s) {
    const RenderResult r = render_scene(s, 64, 64, shadowed_options(s, true, depth_paths()[0]));
    return r.stats.shadows.maps > 0;
}
#define SKIP_WITHOUT_SHADOW_MAPS(scene)                                                                  \
    if (!renderer_has_shadows(scene))                                                                    \
    GTEST_SKIP() << "the renderer draws no shadow maps yet (ShadowCounts::maps is 0 for a scene " \
                    "with shadowed lights); this test runs once it does"

struct LightResult {
    ShadowEdgeError edge;
    ContactLeak leak;
    Mask got, considered;
};

// Light k of the scene alone: the renderer's shadow class against the trace's.
LightResult measure_light(const Scene& full, size_t k, const DepthPathCase& path) {
    const Scene one = with_lights(full, {full.lights[k]}), none = with_lights(full, {});
    const AnalyticTrace tr = analytic_trace(one, kSize, kSize);
    AnalyticOptions no_shadows;
    no_shadows.shadows = false;
    const Image ref_lit = analytic_trace(one, kSize, kSize, no_shadows).image;
    const Image ref_dark = analytic_trace(none, kSize, kSize).image;
    LightResult r;
    const Mask interior = interior_mask(tr, kSize, kSize);
    r.considered = shadow_considered(ref_lit, ref_dark, interior, kMinContrast);
    const Image on = render_scene(one, kSize, kSize, shadowed_options(one, true, path), path.caps_off).image;
    const Image off = render_scene(one, kSize, kSize, shadowed_options(one, false, path), path.caps_off).image;
    const Image dark = render_scene(none, kSize, kSize, shadowed_options(none, false, path), path.caps_off).image;
    r.got = shadow_class(on, off, dark);
    r.edge = shadow_edge_error(tr.occluded[0], r.got, r.considered, kSize, kSize, &interior);
    r.leak = contact_leak(tr.occluded[0], r.got, r.considered, mesh_mask(tr, 0), mesh_mask(tr, 1), kSize, kSize, 3);
    std::printf("[ shadow   ] %-26s %-11s considered %6lld, traced shadow %5lld, rendered %5lld; wrong %4lld, "
                "max %.2f px (mean %.2f) from the traced edge, %lld beyond 1.5 px; contact %lld px, %lld lit (%.1f%%)\n",
                path.name, light_name(full.lights[k]), r.edge.considered, r.edge.ref_shadowed, r.edge.got_shadowed,
                r.edge.mismatched, r.edge.max_px, r.edge.mean_px, r.edge.beyond(1.5), r.leak.contact, r.leak.leaked,
                100 * r.leak.fraction());
    for (size_t i = 0; i < r.edge.pixels.size(); ++i)
        if (r.edge.distances[i] > 1.5)
            std::printf("[ shadow   ]   wrong at (%zu, %zu), %.2f px from the traced edge, %s in the trace\n",
                        r.edge.pixels[i] % kSize, r.edge.pixels[i] / kSize, r.edge.distances[i],
                        tr.occluded[0][r.edge.pixels[i]] ? "shadowed" : "lit");
    if (r.edge.max_px > 1.5 || r.leak.fraction() > 0.05) {
        write_failure_images(std::string("shadow_") + light_name(full.lights[k]) + (path.caps_off.empty() ? "" : "_packed"),
                             on, analytic_trace(one, kSize, kSize).image);
    }
    return r;
}
}  // namespace

// The scene is what the tests assume: three shadowed lights, the box's shadow in view for each.
TEST(ShadowAccuracy, SceneCastsAShadowForEachLight) {
    const Scene s = shadow_scene();
    ASSERT_EQ(s.lights.size(), 3u);
    const AnalyticTrace t = analytic_trace(s, kSize, kSize);
    for (size_t k = 0; k < s.lights.size(); ++k) {
        EXPECT_TRUE(s.lights[k].shadow.on);
        const long n = std::count(t.occluded[k].begin(), t.occluded[k].end(), 1);
        std::printf("[ shadow   ] %s: %ld traced pixels in shadow\n", light_name(s.lights[k]), n);
        EXPECT_GT(n, 1000);
    }
}

// Edge and peter-panning, per light, on both depth paths; and the two paths against each other.
TEST(ShadowAccuracy, EdgeWithinOnePointFivePixelsAndNoLeakAtTheContact) {
    const Scene s = shadow_scene();
    SKIP_WITHOUT_SHADOW_MAPS(s);
    std::printf("[ renderer ] %s\n", render_scene(s, 8, 8, ShaderOptions{}).renderer.c_str());
    for (size_t k = 0; k < s.lights.size(); ++k) {
        std::vector<LightResult> per_path;
        for (const DepthPathCase& path : depth_paths()) {
            LightResult r = measure_light(s, k, path);
            EXPECT_GT(r.edge.boundary, 100) << light_name(s.lights[k]);
            EXPECT_LE(r.edge.max_px, 1.5) << path.name << ", " << light_name(s.lights[k]);
            EXPECT_GT(r.leak.contact, 20) << light_name(s.lights[k]);
            EXPECT_LE(r.leak.fraction(), 0.05) << path.name << ", " << light_name(s.lights[k]);
            per_path.push_back(std::move(r));
        }
        long long differ = 0, considered = 0;
        for (size_t p = 0; p < per_path[0].got.size(); ++p) {
            if (!per_path[0].considered[p]) continue;
            ++considered;
            differ += (per_path[0].got[p] != 0) != (per_path[1].got[p] != 0);
        }
        std::printf("[ shadow   ] %s: the two depth paths classify %lld of %lld considered pixels differently\n",
                    light_name(s.lights[k]), differ, considered);
        EXPECT_LE(differ, considered / 100);
    }
}

// Acne: the whole scene (all three lights) against the whole trace; no pixel darker by more than
// 8 LSB away from every traced edge and silhouette.
TEST(ShadowAccuracy, NoAcneAwayFromTheEdges) {
    const Scene s = shadow_scene();
    SKIP_WITHOUT_SHADOW_MAPS(s);
    const AnalyticTrace tr = analytic_trace(s, kSize, kSize);
    Mask edges(size_t(kSize) * kSize, 0);
    for (const Mask& occ : tr.occluded) {
        const Mask e = occlusion_edges(occ, kSize, kSize);
        for (size_t p = 0; p < e.size(); ++p) edges[p] = edges[p] || e[p];
    }
    const Mask band = dilate(edges, kSize, kSize, 2), interior = interior_mask(tr, kSize, kSize);
    Mask where(band.size());
    for (size_t p = 0; p < where.size(); ++p) where[p] = interior[p] && !band[p] && tr.mesh[p] >= 0;
    for (const DepthPathCase& path : depth_paths()) {
        const RenderResult r = render_scene(s, kSize, kSize, shadowed_options(s, true, path), path.caps_off);
        const AcneCount a = acne(r.image, tr.image, where, 8);
        const ImageDiff d = compare_images_masked(r.image, tr.image, where, 2.0 / 255);
        std::printf("[ shadow   ] %s: %lld pixels away from the edges, %lld darker than the trace by more than 8 LSB "
                    "(most %.2f LSB darker); against the trace there: max %.2f, mean %.3f LSB; %d maps, %lld triangles\n",
                    path.name, a.pixels, a.darker, a.max_darker_lsb, d.max_lsb(), d.mean_lsb(), r.stats.shadows.maps,
                    r.stats.shadows.triangles);
        if (a.darker) write_failure_images(std::string("shadow_acne") + (path.caps_off.empty() ? "" : "_packed"), r.image, tr.image);
        EXPECT_GT(a.pixels, kSize * kSize / 2);
        EXPECT_EQ(a.darker, 0) << path.name;
    }
}
