// Shadow maps through the whole renderer (shadow_stage.h, glsl120/shadow.glsl): a box floating
// over a plane under a spot, a point and a directional light darkens the plane where the light is
// blocked and nowhere else; the depth-texture maps and the packed ones agree; every light geometry
// gives the same image; a scene whose lights say no `shadow` (or --shadows off) is untouched; the
// stage draws only the maps and objects it needs; without framebuffer objects the maps drawn in
// the main frame buffer, piece by piece, are the framebuffer objects' maps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "shadow_fixture.h"

using namespace dsr;
using namespace dsr::test;

namespace {

constexpr int kSize = 96;

ShaderOptions shadowed(LightGeometry g = LightGeometry::quad) {
    ShaderOptions o;
    o.depth = DepthPath::texture;
    o.light_geometry = g;
    o.shadow_lights = true;  // what RenderOptions::resolved sets for such a scene
    return o;
}

// The red channel (0..255) where world point p shows (GL rows: 0 at the bottom).
float lsb_at(const Image& img, const Scene& s, glm::vec3 p) {
    const glm::vec4 c = s.camera.projection(1.0f) * s.camera.view() * glm::vec4(p, 1);
    const int x = int((c.x / c.w * 0.5f + 0.5f) * float(img.width));
    const int y = int((c.y / c.w * 0.5f + 0.5f) * float(img.height));
    return img.at(x, y)[0] * 255.0f;
}

float max_lsb(const Image& a, const Image& b) {
    float m = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i) m = std::max(m, std::fabs(a.rgba[i] - b.rgba[i]) * 255.0f);
    return m;
}

}  // namespace

// Under the box the plane gets only the ambient term; away from it, exactly the unshadowed light.
TEST(Shadows, TheBoxShadowsThePlaneUnderEveryLightType) {
    for (Light::Type t : {Light::Type::spot, Light::Type::point, Light::Type::directional}) {
        const Scene s = box_scene(t);
        Scene unshadowed = s;
        unshadowed.lights[0].shadow.on = false;
        const Image lit = render_scene(unshadowed, kSize, kSize, shadowed()).image;
        const RenderResult r = render_scene(s, kSize, kSize, shadowed());
        // The directional light leans +x: its shadow falls 0.3 x 1.5 off the centre.
        const glm::vec3 under = t == Light::Type::directional ? glm::vec3(0.45f, 0, 0) : glm::vec3(0);
        const float ambient = 0.1f * 0.8f * 255.0f;
        EXPECT_GT(lsb_at(lit, s, under), ambient + 40) << int(t);
        EXPECT_NEAR(lsb_at(r.image, s, under), ambient, 1.5f) << int(t);
        for (glm::vec3 p : {glm::vec3(2.5f, 0, 1.5f), glm::vec3(-2.2f, 0, 2), glm::vec3(1, 0, 3)})
            EXPECT_NEAR(lsb_at(r.image, s, p), lsb_at(lit, s, p), 1.0f) << int(t) << " at " << p.x << " " << p.z;
        EXPECT_EQ(r.stats.shadows.maps, t == Light::Type::point ? 6 : 1);
    }
}

// Only the objects inside the light's views are drawn into its map: the spot's cone holds the
// plane (2 triangles) and the box (12), not the far sphere.
TEST(Shadows, OnlyTheObjectsInTheLightsVolumeAreDrawn) {
    const RenderResult r = render_scene(box_scene(Light::Type::spot), kSize, kSize, shadowed());
    EXPECT_EQ(r.stats.shadows.maps, 1);
    EXPECT_EQ(r.stats.shadows.triangles, 14);
}

// The packed RGB8 maps (no depth textures) compare in the shader what ARB_shadow compares in the
// texture unit: the same image within 1 LSB; and every light geometry draws the same pixels.
TEST(Shadows, DepthPathsAndGeometriesAgree) {
    const Scene s = box_scene(Light::Type::spot);
    const Image ref = render_scene(s, kSize, kSize, shadowed()).image;
    ShaderOptions no_depth = shadowed();
    no_depth.depth = DepthPath::packed;
    const RenderResult packed = render_scene(s, kSize, kSize, no_depth, {"no-depth-texture"});
    EXPECT_LE(max_lsb(ref, packed.image), 1.0f);
    const RenderResult maps_only = render_scene(s, kSize, kSize, shadowed(), {"no-shadow"});  // depth G-buffer, packed maps
    EXPECT_LE(max_lsb(ref, maps_only.image), 1.0f);
    for (LightGeometry g : {LightGeometry::volume, LightGeometry::stencil, LightGeometry::tiles, LightGeometry::automatic})
        EXPECT_EQ(max_lsb(ref, render_scene(s, kSize, kSize, shadowed(g)).image), 0.0f) << light_geometry_name(g);
}

// Without framebuffer objects (--caps no-fbo) each map is drawn in the main frame buffer and copied
// into its texture, in pieces where the window is smaller than the map: 256-texel maps in a 96 x 96
// window are 3 x 3 pieces (the last row and column 64 wide), a point light's 768 x 512 atlas 8 x 6,
// on both depth paths. The copy render target draws the G-buffer and P-buffers the same way with
// framebuffer-object maps: the image must be the same to the byte (a piece left uncopied, or one
// drawn a texel off, is not). Against the framebuffer-object path the copied G-buffer alone differs,
// by at most 1 LSB (docs/shadows_no_fbo.md measured data/shadow.scene at 320x240, 1200x1100, 3100x2100).
TEST(Shadows, WithoutFramebufferObjectsTheMapsAreCopiedInPieces) {
    for (Light::Type t : {Light::Type::spot, Light::Type::point}) {
        Scene s = box_scene(t);
        s.lights[0].shadow.size = 256;
        for (bool packed : {false, true}) {
            ShaderOptions o = shadowed();
            std::vector<std::string> off;
            if (packed) o.depth = DepthPath::packed, off = {"no-depth-texture"};
            const std::string what = std::string(t == Light::Type::spot ? "spot" : "point") + (packed ? " packed" : " texture");
            const RenderResult fbo = render_scene(s, kSize, kSize, o, off);
            ShaderOptions copy = o;
            copy.render_target = RenderTarget::copy;
            const RenderResult copied = render_scene(s, kSize, kSize, copy, off);
            off.push_back("no-fbo");
            const RenderResult r = render_scene(s, kSize, kSize, o, off);
            EXPECT_EQ(r.paths.render_target, "copy") << what;
            EXPECT_EQ(max_lsb(r.image, copied.image), 0.0f) << what;
            EXPECT_LE(max_lsb(r.image, fbo.image), 1.0f) << what;
            EXPECT_EQ(r.stats.shadows.maps, fbo.stats.shadows.maps) << what;
            // The spot's view spans every piece: its 14 triangles are drawn 9 times.
            if (t == Light::Type::spot) {
                EXPECT_EQ(r.stats.shadows.triangles, 9 * fbo.stats.shadows.triangles) << what;
            }
            if (max_lsb(r.image, copied.image) > 0)
                write_failure_images("shadows_no_fbo_" + std::to_string(int(t)) + (packed ? "_packed" : ""), r.image, copied.image);
        }
    }
}

// More shadowed lights than a batch holds maps (ShaderConfig::shadow_slots: 8 on llvmpipe): the
// tiles and auto shade them inside their batches, each through its own map, and give quad's image
// to the byte on both map formats; screen, which rounds its sum once, stays within a few LSB. The
// tiles' passes are their batches', not a quad per shadowed light.
// The box under 12 lights of every type, 10 of them shadowed: more than a batch holds maps.
Scene many_shadowed_lights() {
    Scene s = box_scene(Light::Type::spot);
    s.lights[0].color = glm::vec3(0.3f);
    const Light::Type types[] = {Light::Type::spot, Light::Type::point, Light::Type::spot, Light::Type::directional};
    for (int i = 0; i < 11; ++i) {
        Light l = s.lights[0];
        l.type = types[i % 4];
        const float a = 0.6f * float(i);
        l.pos = {2.5f * std::cos(a), 4 + 0.2f * float(i % 3), 2.5f * std::sin(a)};
        l.dir = glm::normalize(glm::vec3(-0.2f * std::cos(a), -1, -0.2f * std::sin(a)));
        l.color = glm::vec3(0.12f + 0.01f * float(i), 0.1f, 0.15f);
        l.shadow.on = i % 5 != 4;  // two without
        s.lights.push_back(l);
    }
    return s;
}

TEST(Shadows, BatchedGeometriesShadeShadowedLightsInTheirBatches) {
    const Scene s = many_shadowed_lights();
    int shadowed_lights = 0;
    for (const Light& l : s.lights) shadowed_lights += l.shadow.on;
    ASSERT_GT(shadowed_lights, 8);
    for (bool packed : {false, true}) {
        const std::vector<std::string> caps = packed ? std::vector<std::string>{"no-shadow"} : std::vector<std::string>{};
        const Image ref = render_scene(s, kSize, kSize, shadowed(), caps).image;
        Scene none = s;
        for (Light& l : none.lights) l.shadow.on = false;
        EXPECT_GT(max_lsb(ref, render_scene(none, kSize, kSize, shadowed(), caps).image), 20.0f) << "no shadow to see";
        for (LightGeometry g : {LightGeometry::tiles, LightGeometry::automatic}) {
            const RenderResult r = render_scene(s, kSize, kSize, shadowed(g), caps);
            EXPECT_EQ(max_lsb(ref, r.image), 0.0f) << light_geometry_name(g) << (packed ? " packed" : "");
            if (g == LightGeometry::tiles) {
                EXPECT_LE(r.stats.lights.passes, 3) << "a quad a shadowed light?";
            }
        }
        const RenderResult screen = render_scene(s, kSize, kSize, shadowed(LightGeometry::screen), caps);
        EXPECT_LE(max_lsb(ref, screen.image), 6.0f) << (packed ? "packed" : "");
        // 12 lights, 10 shadowed: two batches (cut before the 9th shadowed). The unshadowed light
        // whose sphere holds the camera is one of a batch's, not the ambient fold's pass of its own;
        // the first batch writes the ambient term itself.
        EXPECT_EQ(screen.stats.lights.passes, 2);
        EXPECT_TRUE(screen.stats.passes.ambient_folded());
    }
}

// The batches' maps in one atlas each (shadow_atlas.h): with framebuffer objects the tiles and
// screen copy them (shadow_atlas_texels) and read them there, giving the if-chain's image (quad's,
// to the byte, for tiles: a region a texel off is not); a still frame copies nothing, a moved
// light's map alone is copied again, --shadow-reuse off copies every map every frame. Without
// framebuffer objects the batches read their maps through the chain, still quad's image. Both depth paths.
TEST(Shadows, BatchesReadTheirMapsFromOneAtlas) {
    Scene s = many_shadowed_lights();
    for (Light& l : s.lights) l.shadow.size = 128;
    for (bool packed : {false, true}) {
        const std::vector<std::string> caps = packed ? std::vector<std::string>{"no-shadow"} : std::vector<std::string>{};
        const std::string what = packed ? "packed" : "depth texture";
        const RenderResult quad = render_scene(s, kSize, kSize, shadowed(), caps);
        for (LightGeometry g : {LightGeometry::tiles, LightGeometry::screen}) {
            const RenderResult r = render_scene(s, kSize, kSize, shadowed(g), caps);
            EXPECT_GT(r.stats.shadows.atlas_texels, 0) << what;
            if (g == LightGeometry::tiles) {
                EXPECT_EQ(max_lsb(quad.image, r.image), 0.0f) << what;
            }
        }
        std::vector<std::string> no_fbo = caps;
        no_fbo.push_back("no-fbo");
        const RenderResult chain = render_scene(s, kSize, kSize, shadowed(LightGeometry::tiles), no_fbo);
        EXPECT_EQ(chain.stats.shadows.atlas_texels, 0) << what;
        EXPECT_EQ(max_lsb(render_scene(s, kSize, kSize, shadowed(), no_fbo).image, chain.image), 0.0f) << what;
        for (bool reuse : {true, false}) {
            auto ctx = create_context(ContextDesc{"osmesa", kSize, kSize});
            ShaderOptions o = shadowed(LightGeometry::tiles);
            o.shadows.reuse = reuse;
            DeferredShader ds(probe_caps(caps), kSize, kSize, o, resource_dir("glsl120"));
            ds.set_scene(s);
            const long long all = ds.render(s, kSize, kSize).shadows.atlas_texels;
            EXPECT_GT(all, 0) << what;
            const Image first = read_pixels(kSize, kSize);
            EXPECT_EQ(ds.render(s, kSize, kSize).shadows.atlas_texels, reuse ? 0 : all) << what;
            EXPECT_EQ(read_pixels(kSize, kSize).rgba, first.rgba) << what;
            Scene moved = s;
            moved.lights[1].pos.x += 0.25f;  // a spot: its 128 x 128 map
            EXPECT_EQ(ds.render(moved, kSize, kSize).shadows.atlas_texels, reuse ? 128 * 128 : all) << what;
        }
    }
}

// --shadows off (shadow_lights false) ignores the scene's `shadow`: the image of the scene without
// it, byte for byte, and no map drawn.
TEST(Shadows, OffIgnoresTheScene) {
    const Scene s = box_scene(Light::Type::spot);
    Scene none = s;
    none.lights[0].shadow.on = false;
    ShaderOptions off = shadowed();
    off.shadow_lights = false;
    const RenderResult a = render_scene(s, kSize, kSize, off);
    const RenderResult b = render_scene(none, kSize, kSize, off);
    EXPECT_EQ(a.image.rgba, b.image.rgba);
    EXPECT_EQ(a.stats.shadows.maps, 0);
}

// A still frame keeps the last frame's map (nothing drawn, the same image); --shadow-reuse off
// draws it again; moving the light draws it again.
TEST(Shadows, StillFramesReuseTheMaps) {
    Scene s = box_scene(Light::Type::spot);
    for (bool reuse : {true, false}) {
        auto ctx = create_context(ContextDesc{"osmesa", kSize, kSize});
        ShaderOptions o = shadowed();
        o.shadows.reuse = reuse;
        DeferredShader ds(probe_caps(), kSize, kSize, o, resource_dir("glsl120"));
        ds.set_scene(s);
        EXPECT_EQ(ds.render(s, kSize, kSize).shadows.maps, 1);
        const Image first = read_pixels(kSize, kSize);
        const FrameStats again = ds.render(s, kSize, kSize);
        EXPECT_EQ(again.shadows.maps, reuse ? 0 : 1);
        EXPECT_EQ(again.shadows.triangles, reuse ? 0 : 14);
        EXPECT_EQ(read_pixels(kSize, kSize).rgba, first.rgba);
        Scene moved = s;
        moved.lights[0].pos.x += 0.25f;
        EXPECT_EQ(ds.render(moved, kSize, kSize).shadows.maps, 1);
    }
}

// Transparent surfaces (the forward stage) receive shadows: a glass slab on the plane under the
// box is darker there with the shadow than without it, and unchanged where the light reaches it.
TEST(Shadows, TransparentSurfacesReceiveThem) {
    Scene s = box_scene(Light::Type::spot);
    Material glass;
    glass.name = "glass";
    glass.diffuse = {0.3f, 0.5f, 0.9f};
    glass.opacity = 0.6f;
    s.materials.push_back(glass);
    add_box(s, {6, 0.2f, 1}, {0, 0.1f, 0}, 1);
    // The plane behind the glass black, so the glass alone makes the pixel: what it blends over
    // is the same with the shadow and without.
    Material black;
    black.name = "black";
    black.diffuse = glm::vec3(0);
    s.materials.push_back(black);
    s.objects[0].material = 2;
    Scene unshadowed = s;
    unshadowed.lights[0].shadow.on = false;
    ShaderOptions o = shadowed();
    o.forward_surfaces = true;
    const RenderResult lit = render_scene(unshadowed, kSize, kSize, o);
    const RenderResult r = render_scene(s, kSize, kSize, o);
    EXPECT_EQ(r.stats.forward.transparent_passes, 2);  // the ambient pass, then the shadowed light's
    EXPECT_LT(lsb_at(r.image, s, {0, 0.2f, 0}), lsb_at(lit.image, s, {0, 0.2f, 0}) - 20);
    EXPECT_NEAR(lsb_at(r.image, s, {2.5f, 0.2f, 0}), lsb_at(lit.image, s, {2.5f, 0.2f, 0}), 1.0f);
}
