// Shadows in the forward reference renderers (src/forward, docs/shadows.md): Listing 3's single
// pass adds each shadowed light by a pass of its own, Listing 4's pass of a shadowed light takes
// forward.frag's SHADOW form, both with the deferred renderer's shadow stage's maps. Against the
// deferred renderer (quad geometry) with shadows, and against the analytic reference's shadow rays.
// Every measured number is printed.
#include <gtest/gtest.h>

#include <cstdio>

#include "analysis/analytic_reference.h"
#include "analysis/shadow_metrics.h"
#include "forward_fixture.h"
#include "shadow_fixture.h"

using namespace dsr;
using namespace dsr::test;

namespace {
constexpr double kLsb = 1.0 / 255.0;

Scene shadow_scene() { return load_scene(resource_dir("data") + "/shadow.scene"); }

// The deferred renderer as RenderOptions::resolved sets it up for a scene with `shadow` lights;
// without depth textures the G-buffer is packed too, as `dsr render --caps no-depth-texture` chooses.
ShaderOptions deferred_options(const Scene& s, bool packed = false) {
    ShaderOptions o;
    o.light_geometry = LightGeometry::quad;
    if (packed) o.depth = DepthPath::packed;
    for (const Light& l : s.lights) o.shadow_lights = o.shadow_lights || l.shadow.on;
    return o;
}

struct Path {
    const char* name;
    std::vector<std::string> caps_off;
};
const std::vector<Path> kPaths = {{"depth-texture maps", {}}, {"packed maps (no-depth-texture)", {"no-depth-texture"}}};

const char* mode_name(ForwardMode m) { return m == ForwardMode::single ? "single" : "multi"; }

const char* light_name(const Light& l) {
    return l.type == Light::Type::spot ? "spot" : l.type == Light::Type::directional ? "directional" : "point";
}

Scene with_lights(Scene s, std::vector<Light> lights) {
    s.lights = std::move(lights);
    return s;
}

// box_scene with a glass slab on the plane under the box: a transparent surface receiving the shadow.
Scene with_glass(Scene s) {
    Material glass;
    glass.name = "glass";
    glass.diffuse = {0.3f, 0.5f, 0.9f};
    glass.opacity = 0.6f;
    s.materials.push_back(glass);
    add_box(s, {6, 0.2f, 1}, {0, 0.1f, 0}, int(s.materials.size()) - 1);
    return s;
}

// Forward against deferred, with shadows and without (ShadowOptions::on false in both): at most
// max_lsb apart, and on average no further apart than the unshadowed pair (their shading's own
// difference: the 8-bit G-buffer's normals) plus 0.05 LSB. The image pair written on failure.
void expect_close(const std::string& name, ForwardMode m, const Scene& s, int n, const ShaderOptions& deferred,
                  const std::vector<std::string>& caps_off, double max_lsb) {
    ShaderOptions d_off = deferred;
    d_off.shadow_lights = false;
    ForwardOptions f_on = forward_mode(m), f_off = forward_mode(m);
    f_off.shadows.on = false;
    const Image def = render_scene(s, n, n, deferred, caps_off).image;
    const Image fwd = render_forward(s, n, n, f_on, false, caps_off).image;
    const ImageDiff off = compare_logged("  unshadowed " + name, render_forward(s, n, n, f_off, false, caps_off).image,
                                         render_scene(s, n, n, d_off, caps_off).image, 2 * kLsb);
    const ImageDiff d = compare_logged(name, fwd, def, 2 * kLsb);
    if (d.max_lsb() > max_lsb || d.mean_lsb() > off.mean_lsb() + 0.05) write_failure_images(name, fwd, def);
    EXPECT_LE(d.max_lsb(), max_lsb) << name;
    EXPECT_LE(d.mean_lsb(), off.mean_lsb() + 0.05) << name;
}
}  // namespace

// data/shadow.scene at 256x256 (three shadowed lights: spot, directional, point), both map formats;
// the maps are the same (counts equal). Measured on llvmpipe, single and multi, both paths: max 2
// LSB, mean 0.460 LSB; the unshadowed pair max 2, mean 0.477. Forward ignoring the shadows: max
// 115 LSB, mean 3.82. Bound: max 3 LSB, mean within the unshadowed pair's + 0.05 (expect_close).
TEST(ForwardShadows, MatchDeferredOnTheShadowScene) {
    constexpr int n = 256;
    const Scene s = shadow_scene();
    for (const Path& p : kPaths) {
        const ShaderOptions o = deferred_options(s, !p.caps_off.empty());
        const RenderResult def = render_scene(s, n, n, o, p.caps_off);
        for (ForwardMode m : {ForwardMode::single, ForwardMode::multi}) {
            const ForwardResult fwd = render_forward(s, n, n, forward_mode(m), false, p.caps_off);
            EXPECT_EQ(fwd.stats.shadow_maps, def.stats.shadows.maps) << p.name;
            EXPECT_EQ(fwd.stats.shadow_triangles, def.stats.shadows.triangles) << p.name;
            expect_close(std::string("forward_") + mode_name(m) + "_vs_deferred_shadow_scene" +
                             (p.caps_off.empty() ? "" : "_packed"),
                         m, s, n, o, p.caps_off, 3);
        }
    }
}

// The floating box under a spot, a point (six faces) and a directional light, and the spot's shadow
// on a glass slab (transparent surfaces get their maps through TransparentPass), at 96x96.
// Measured on llvmpipe, single and multi: max 1 LSB; mean 0.18, 0.22, 0.56, 0.18 LSB (spot,
// point, directional, glass), each below the unshadowed pair's (0.19, 0.23, 0.56, 0.18). Forward
// ignoring the shadows: max 102 LSB. Bound: max 2 LSB, mean as expect_close.
TEST(ForwardShadows, MatchDeferredOnTheBoxScenes) {
    constexpr int n = 96;
    std::vector<std::pair<std::string, Scene>> scenes;
    for (Light::Type t : {Light::Type::spot, Light::Type::point, Light::Type::directional})
        scenes.emplace_back(light_name(box_scene(t).lights[0]), box_scene(t));
    scenes.emplace_back("spot_glass", with_glass(box_scene(Light::Type::spot)));
    for (const auto& [name, s] : scenes) {
        ShaderOptions o = deferred_options(s);
        o.forward_surfaces = s.objects.size() > 3;  // the glass
        for (ForwardMode m : {ForwardMode::single, ForwardMode::multi})
            expect_close("forward_" + std::string(mode_name(m)) + "_vs_deferred_box_" + name, m, s, n, o, {}, 2);
    }
}

// Each light of data/shadow.scene alone, classified shadowed or lit as shadow_metrics.h does
// (three renders: shadows on, off, no light) against the trace's shadow rays: the forward images'
// shadow boundary is as good as the deferred one's. Measured on llvmpipe at 256x256, single and
// multi alike: spot 6 pixels classified wrong (deferred 6), directional 26 (25), point 34 (34),
// every one on the traced edge (0 px from it). Forward ignoring the shadows: 1155-2654 wrong, up
// to 26 px off. Bound: within 1.5 px of the edge (ShadowAccuracy's), or deferred's max if more;
// at most 10% + 5 more wrong pixels than deferred.
TEST(ForwardShadows, EdgeAsGoodAsDeferred) {
    constexpr int n = 256;
    constexpr double kMinContrast = 24.0 / 255.0;  // as tests/test_shadow_accuracy.cpp
    const Scene full = shadow_scene();
    AnalyticOptions no_shadows;
    no_shadows.shadows = false;
    ForwardOptions off_opts;
    off_opts.shadows.on = false;
    for (size_t k = 0; k < full.lights.size(); ++k) {
        const Scene one = with_lights(full, {full.lights[k]}), none = with_lights(full, {});
        const AnalyticTrace tr = analytic_trace(one, n, n);
        const Mask interior = interior_mask(tr, n, n);
        const Mask considered = shadow_considered(analytic_trace(one, n, n, no_shadows).image,
                                                  analytic_trace(none, n, n).image, interior, kMinContrast);
        ShaderOptions d_off = deferred_options(one);
        d_off.shadow_lights = false;
        const Image d_on = render_scene(one, n, n, deferred_options(one)).image;
        const Image d_unshadowed = render_scene(one, n, n, d_off).image;
        const Image d_dark = render_scene(none, n, n, ShaderOptions{}).image;
        const ShadowEdgeError def =
            shadow_edge_error(tr.occluded[0], shadow_class(d_on, d_unshadowed, d_dark), considered, n, n, &interior);
        std::printf("[ shadow   ] %-11s deferred:       %4lld wrong, max %.2f px from the traced edge\n",
                    light_name(full.lights[k]), def.mismatched, def.max_px);
        for (ForwardMode m : {ForwardMode::single, ForwardMode::multi}) {
            ForwardOptions on_opts = forward_mode(m);
            off_opts.mode = m;
            const Image on = render_forward(one, n, n, on_opts).image;
            const Image unshadowed = render_forward(one, n, n, off_opts).image;
            const Image dark = render_forward(none, n, n, on_opts).image;
            const ShadowEdgeError fwd =
                shadow_edge_error(tr.occluded[0], shadow_class(on, unshadowed, dark), considered, n, n, &interior);
            std::printf("[ shadow   ] %-11s forward %-6s: %4lld wrong, max %.2f px from the traced edge\n",
                        light_name(full.lights[k]), mode_name(m), fwd.mismatched, fwd.max_px);
            EXPECT_GT(fwd.boundary, 100) << light_name(full.lights[k]);
            EXPECT_LE(fwd.max_px, std::max(1.5, def.max_px)) << light_name(full.lights[k]) << " " << mode_name(m);
            EXPECT_LE(fwd.mismatched, def.mismatched + def.mismatched / 10 + 5)
                << light_name(full.lights[k]) << " " << mode_name(m);
        }
    }
}

// The stats count the extra passes: on data/shadow.scene (a floor and a box, three shadowed lights
// reaching both) single draws each object once and adds 2 x 3 shadowed passes; multi its depth
// pre-pass, 2 ambient passes and 2 x 3 light passes. --shadows off (ShadowOptions::on false):
// no map, the lights in the single pass, and the image of the scene without `shadow`, byte for byte.
TEST(ForwardShadows, StatsCountTheShadowedPassesAndOffIgnoresThem) {
    constexpr int n = 64;
    const Scene s = shadow_scene();
    const ForwardResult single = render_forward(s, n, n, forward_mode(ForwardMode::single));
    EXPECT_EQ(single.stats.passes, 2 + 6);
    EXPECT_EQ(single.stats.light_object_pairs, 6);
    EXPECT_EQ(single.stats.shadow_maps, 1 + 1 + 6);  // spot, directional, the point light's six faces
    const ForwardResult multi = render_forward(s, n, n, forward_mode(ForwardMode::multi));
    EXPECT_EQ(multi.stats.passes, 1 + 2 + 6);
    EXPECT_EQ(multi.stats.light_object_pairs, 6);
    EXPECT_EQ(multi.stats.shadow_maps, 8);
    Scene none = s;
    for (Light& l : none.lights) l.shadow.on = false;
    for (ForwardMode m : {ForwardMode::single, ForwardMode::multi}) {
        ForwardOptions off = forward_mode(m);
        off.shadows.on = false;
        const ForwardResult a = render_forward(s, n, n, off);
        const ForwardResult b = render_forward(none, n, n, forward_mode(m));
        EXPECT_EQ(a.image.rgba, b.image.rgba) << mode_name(m);
        EXPECT_EQ(a.stats.shadow_maps, 0);
        EXPECT_EQ(a.stats.passes, m == ForwardMode::single ? 2 : 9);
    }
}
