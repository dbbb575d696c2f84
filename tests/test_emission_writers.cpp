// Emission and occlusion of metallic-roughness materials whichever pass writes the ambient term
// (deferred/ambient_writer.h, deferred/emission_pass.h; docs/metal_rough.md, "Where the ambient,
// occlusion and emission go"): a scene with emissive and occluded surfaces, rendered through the
// configurations that give each writer its frame, matches the material pass's render within 1 LSB.
// The same configurations without emission or occlusion are checked to reach every writer, so each
// is the path that frame would have taken.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <string>

#include "deferred/ambient_writer.h"
#include "render_fixture.h"

using namespace dsr;
using namespace dsr::test;

namespace {
constexpr int kSize = 128;

// A 4x4 occlusion map (red) from 0.1 to 1 in steps, repeated over the surface.
Image occlusion_map() {
    Image img;
    img.width = img.height = 4;
    img.rgba.assign(4 * 4 * 4, 1.0f);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) img.at(i, j)[0] = 0.1f + 0.06f * float(j * 4 + i);
    return img;
}

// A floor occluded by a map, an emissive sphere occluded at strength 0.7, an emissive metal and a
// Phong box, under a bright ambient term so that occlusion shows; a point light, and where `sun`
// a directional light, a light over the whole screen (the fold's).
Scene emissive_scene(bool sun, bool emission = true) {
    Scene s;
    s.camera.pos = {0, 2, 6};
    s.camera.target = {0, 0.5f, 0};
    s.camera.fov_deg = 50;
    s.camera.near_plane = 0.5f;
    s.camera.far_plane = 20;
    s.ambient = glm::vec3(0.35f);
    s.background = {0.05f, 0.04f, 0.03f};
    s.textures.push_back(occlusion_map());
    Material floor = metal_rough("floor", {0.6f, 0.6f, 0.6f}, 0.0f, 0.7f);
    floor.occlusion_map = 0;
    floor.tile = 4;
    Material glow = metal_rough("glow", {0.8f, 0.3f, 0.2f}, 0.5f, 0.75f);
    glow.emissive = {0.3f, 0.2f, 0.1f};
    glow.occlusion_map = 0;
    glow.occlusion_strength = 0.7f;
    Material gold = metal_rough("gold", {1.0f, 0.77f, 0.34f}, 1.0f, 0.7f);
    gold.emissive = {0.05f, 0.1f, 0.4f};
    Material phong;
    phong.name = "phong";
    phong.diffuse = glm::vec3(0.5f, 0.6f, 0.4f);
    phong.specular = glm::vec3(0.25f);
    phong.shininess = 32;
    if (!emission) {
        for (Material* m : {&floor, &glow, &gold}) {
            m->emissive = glm::vec3(0);
            m->occlusion_map = -1;
        }
    }
    s.materials = {floor, glow, gold, phong};
    add_plane(s, 10, {0, 0, 0}, 0);
    add_sphere(s, 1.0f, {-1.2f, 1, 0}, 1);
    add_sphere(s, 0.6f, {1.4f, 0.6f, 0.8f}, 2);
    add_box(s, {0.6f, 0.6f, 0.6f}, {0.3f, 0.3f, -1.5f}, 3);
    Light point;
    point.pos = {-2.5f, 2.0f, 0.5f};  // its rectangle short of the screen: not a light over the whole screen
    point.color = {1.2f, 1.1f, 1.0f};
    point.radius = 3.0f;
    s.lights.push_back(point);
    if (sun) {
        Light l;
        l.type = Light::Type::directional;
        l.dir = glm::normalize(glm::vec3(0.5f, -1.0f, -0.4f));
        l.color = {0.4f, 0.45f, 0.5f};
        s.lights.push_back(l);
    }
    return s;
}

struct Case {
    const char* name;
    bool sun;
    ShaderOptions opts;
    std::vector<std::string> caps;
};

ShaderOptions geometry(LightGeometry g, bool target, bool ambient_skip = true) {
    ShaderOptions o;
    o.light_geometry = g;
    o.skip.ambient_target = target;
    o.skip.ambient_pass = ambient_skip;
    return o;
}

std::vector<Case> cases() {
    std::vector<Case> c;
    c.push_back({"Listing 15's pass", true, geometry(LightGeometry::quad, false, false), {}});
    c.push_back({"the fold into the directional light's pass", true, geometry(LightGeometry::quad, false), {}});
    c.push_back({"the screen geometry's first batch", true, geometry(LightGeometry::screen, true), {}});
    ShaderOptions handoff = geometry(LightGeometry::volume, false);
    handoff.depth_handoff = DepthHandoff::pass;
    c.push_back({"the depth hand-off's pass", false, handoff, {}});
    c.push_back({"the tiles' plan read back", true, geometry(LightGeometry::tiles, false, false), {}});
    c.push_back({"no MRT", true, geometry(LightGeometry::quad, true), {"no-mrt"}});
    ShaderOptions half = geometry(LightGeometry::quad, true);
    half.gbuffer_half = true;
    c.push_back({"half-float G-buffer", true, half, {}});
    ShaderOptions packed = geometry(LightGeometry::stencil, false);
    packed.depth = DepthPath::packed;
    c.push_back({"packed depth, stencil", true, packed, {}});
    ShaderOptions ssao = geometry(LightGeometry::quad, true);
    ssao.ssao.on = true;
    ssao.ssao.strength = 0;  // ao = 1: Listing 15's pass scaled by 1
    c.push_back({"SSAO of strength 0", true, ssao, {}});
    return c;
}
}  // namespace

// The configurations reach every writer of a frame without emission or occlusion.
TEST(EmissionWriters, TheCasesReachEveryWriter) {
    std::set<std::string> seen;
    for (const Case& c : cases()) {
        const RenderResult r = render_scene(emissive_scene(c.sun, false), kSize, kSize, c.opts, c.caps);
        std::printf("[ writer   ] without emission, %s: %s\n", c.name, ambient_writer_name(r.stats.passes.ambient));
        seen.insert(ambient_writer_name(r.stats.passes.ambient));
    }
    const RenderResult m = render_scene(emissive_scene(true, false), kSize, kSize, ShaderOptions{});
    seen.insert(ambient_writer_name(m.stats.passes.ambient));
    for (int w = 0; w < 6; ++w) EXPECT_EQ(seen.count(ambient_writer_name(AmbientWriter(w))), 1u) << ambient_writer_name(AmbientWriter(w));
}

// Each configuration's render of the emissive and occluded scene within 1 LSB of the material
// pass's, whose ambient target writes ambient x base x occlusion + emission in one rounding, beyond
// the configuration's own difference from it on the scene without them (0 where it gives the same
// bytes; the screen geometry's one rounding of its sum, the half-float G-buffer's values).
TEST(EmissionWriters, EveryWriterAddsEmissionAndOcclusion) {
    for (const bool sun : {true, false}) {
        const RenderResult ref = render_scene(emissive_scene(sun), kSize, kSize, ShaderOptions{});
        ASSERT_EQ(ref.stats.passes.ambient, AmbientWriter::material_pass) << "this GL writes the ambient term elsewhere";
        // Emission and occlusion show: the reference differs from the scene without them.
        const RenderResult plain = render_scene(emissive_scene(sun, false), kSize, kSize, ShaderOptions{});
        EXPECT_GT(compare_images(ref.image, plain.image, 1.0 / 255).failing, kSize * kSize / 10);
        ASSERT_EQ(plain.stats.passes.ambient, AmbientWriter::material_pass);
        for (const Case& c : cases()) {
            if (c.sun != sun) continue;
            const RenderResult r = render_scene(emissive_scene(sun), kSize, kSize, c.opts, c.caps);
            const AmbientWriter w = r.stats.passes.ambient;
            std::printf("[ writer   ] with emission, %s: %s\n", c.name, ambient_writer_name(w));
            EXPECT_TRUE(w == AmbientWriter::pass_before_plan || w == AmbientWriter::pass_after_plan) << c.name;
            const RenderResult own = render_scene(emissive_scene(sun, false), kSize, kSize, c.opts, c.caps);
            const double own_lsb = compare_images(own.image, plain.image, 1.0 / 255).max_lsb(), bound = own_lsb + 1;
            const ImageDiff d = compare_logged(std::string("emission, ") + c.name + " vs the material pass", r.image,
                                               ref.image, bound / 255);
            std::printf("[ image    ] (without emission and occlusion this configuration is %.0f LSB from it)\n", own_lsb);
            EXPECT_LE(d.max_lsb(), bound + 1e-3) << c.name;
            if (d.max_lsb() > bound + 1e-3) write_failure_images(std::string("emission_") + c.name, r.image, ref.image);
        }
    }
}
