// The per-frame value every stage reads (deferred/frame.h), the matrices through the state door
// (gl/state.h set_camera) and the shader table (deferred/shader_table.h).
#include <gtest/gtest.h>

#include <set>

#include <glm/gtc/type_ptr.hpp>

#include "deferred/frame.h"
#include "deferred/reconstruct.h"
#include "deferred/shader_table.h"
#include "gl/state.h"
#include "render_fixture.h"
#include "shader_configs.h"

namespace dsr {
namespace {

FrameSetup setup(int w, int h) {
    FrameSetup s;
    s.width = w;
    s.height = h;
    return s;
}

// Listing 17 on the frame: every light counted once, culled or drawn, with its rectangle.
TEST(FrameDef, LightsCulledOrDrawnWithTheirRectangles) {
    Scene scene = test::default_scene();
    Light behind = scene.lights[0];
    behind.pos = scene.camera.pos + 3.0f * glm::normalize(scene.camera.pos - scene.camera.target);
    behind.radius = 0.5f;  // wholly behind the eye
    scene.lights.push_back(behind);
    Light dark = scene.lights[0];
    dark.color = glm::vec3(0);  // adds nothing
    scene.lights.push_back(dark);
    const FrameDef f = make_frame(scene.camera, scene.lights, setup(200, 150));
    EXPECT_EQ(f.lights_total, int(scene.lights.size()));
    EXPECT_EQ(f.lights_culled, 2);
    ASSERT_EQ(f.lights.size() + size_t(f.lights_culled), scene.lights.size());
    long long area = 0;
    for (const LightDraw& l : f.lights) {
        EXPECT_EQ(l.light, &scene.lights[l.index]);
        EXPECT_FALSE(l.rect.empty());
        EXPECT_GE(l.rect.x0, 0);
        EXPECT_LE(l.rect.x1, 200);
        EXPECT_LE(l.rect.y1, 150);
        area += l.rect.area();
    }
    EXPECT_EQ(area, f.scissor_pixels);
    // Without scissors every light covers the viewport.
    FrameSetup off = setup(200, 150);
    off.scissors = false;
    const FrameDef g = make_frame(scene.camera, scene.lights, off);
    ASSERT_EQ(g.lights.size(), f.lights.size());
    for (const LightDraw& l : g.lights) EXPECT_TRUE(l.full && l.rect.area() == 200 * 150);
}

// The renderer makes the frame in two steps, the camera before the G-buffer and the lights while
// the GPU fills it: the same frame as make_frame's, light by light, shadowed lights numbered alike.
TEST(FrameDef, LightsAddedLaterGiveTheSameFrame) {
    Scene scene = test::default_scene();
    Light dark = scene.lights[0];
    dark.color = glm::vec3(0);
    scene.lights.push_back(dark);
    scene.lights[1].shadow.on = true;
    for (const bool shadows : {false, true}) {
        FrameSetup s = setup(200, 150);
        s.shadows = shadows;
        const FrameDef whole = make_frame(scene.camera, scene.lights, s);
        FrameDef later = make_frame(scene.camera, {}, s);
        EXPECT_TRUE(later.lights.empty());
        add_visible_lights(later, scene.lights, s);
        EXPECT_EQ(later.lights_total, whole.lights_total);
        EXPECT_EQ(later.lights_culled, whole.lights_culled);
        EXPECT_EQ(later.scissor_pixels, whole.scissor_pixels);
        EXPECT_EQ(later.shadowed_lights, whole.shadowed_lights);
        EXPECT_EQ(later.shadowed_lights, shadows ? 1 : 0);
        ASSERT_EQ(later.lights.size(), whole.lights.size());
        for (size_t i = 0; i < whole.lights.size(); ++i) {
            const LightDraw &a = later.lights[i], &b = whole.lights[i];
            EXPECT_EQ(a.index, b.index);
            EXPECT_TRUE(a.rect.x0 == b.rect.x0 && a.rect.y0 == b.rect.y0 && a.rect.x1 == b.rect.x1 && a.rect.y1 == b.rect.y1);
            EXPECT_EQ(a.full, b.full);
            EXPECT_EQ(a.shadow, b.shadow);
            EXPECT_EQ(a.params.pos, b.params.pos);
            EXPECT_EQ(a.params.color, b.params.color);
        }
        EXPECT_THROW(add_visible_lights(later, scene.lights, s), Error) << "a frame's lights are added once";
    }
}

// The camera's values: the projection at the buffers' aspect, §3.4.3's planes, the corner rays,
// and the ray map the light shaders evaluate at gl_FragCoord.
TEST(FrameDef, CameraValues) {
    const Scene scene = test::default_scene();
    const FrameDef f = make_frame(scene.camera, {}, setup(320, 200));
    EXPECT_TRUE(f.lights.empty());
    EXPECT_EQ(f.proj, scene.camera.projection(320.0f / 200.0f));
    EXPECT_EQ(f.view, scene.camera.view());
    EXPECT_EQ(f.planes, planes_uniform(scene.camera.near_plane, scene.camera.far_plane));
    const auto rays = corner_rays(f.proj[0][0], f.proj[1][1]);
    const float xs[4] = {0, 320, 320, 0}, ys[4] = {0, 0, 200, 200};
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(f.view_ray_at(xs[i], ys[i]), rays[size_t(i)]) << "corner " << i;
        const glm::vec2 mapped = glm::vec2(xs[i], ys[i]) * glm::vec2(f.ray_map) + glm::vec2(f.ray_map.z, f.ray_map.w);
        EXPECT_NEAR(mapped.x, rays[size_t(i)].x, 1e-6f);
        EXPECT_NEAR(mapped.y, rays[size_t(i)].y, 1e-6f);
    }
}

// set_camera loads both matrices and leaves GL_MODELVIEW current; the pixel camera is glOrtho's
// own matrix, value for value (the image-space passes drew through glOrtho before).
TEST(FrameDef, SetCameraLoadsGlOrthosMatrix) {
    auto ctx = create_context(ContextDesc{"osmesa", 16, 16});
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 512, 0, 384, -1, 1);
    glm::mat4 ortho;
    glGetFloatv(GL_PROJECTION_MATRIX, glm::value_ptr(ortho));
    EXPECT_EQ(pixel_ortho(512, 384), ortho);
    const glm::mat4 mv = glm::mat4(2.0f);
    gl_state().set_camera(pixel_ortho(64, 32), mv);
    glm::mat4 p, m;
    glGetFloatv(GL_PROJECTION_MATRIX, glm::value_ptr(p));
    glGetFloatv(GL_MODELVIEW_MATRIX, glm::value_ptr(m));
    EXPECT_EQ(p, pixel_ortho(64, 32));
    EXPECT_EQ(m, mv);
    GLint mode = 0;
    glGetIntegerv(GL_MATRIX_MODE, &mode);
    EXPECT_EQ(mode, GL_MODELVIEW);
}

// Every row of the table is used by some configuration, and the programs a configuration uses
// compile and link (ProgramSet throws naming the one that does not).
TEST(ShaderTable, EveryRowCompilesWhereItIsUsed) {
    auto ctx = create_context(ContextDesc{"osmesa", 64, 64});
    const Caps caps = probe_caps();
    std::set<std::string> used;
    auto build = [&](ShaderOptions o, const std::vector<std::string>& off = {}) {
        const ShaderConfig c = shader_config(off.empty() ? caps : probe_caps(off), o);
        const ProgramSet set(resource_dir("glsl120"), c);
        EXPECT_EQ(set.size(), shader_programs(c).size());
        for (const ProgramSpec& p : shader_programs(c)) used.insert(p.name.substr(0, p.name.find('/')));
    };
    for (const test::TableConfig& t : test::common_table_configs()) build(t.options, t.off);
    ShaderOptions hdr;  // the final stage's program and auto exposure's reduction (docs/hdr.md)
    hdr.hdr.accum = AccumFormat::half;
    hdr.hdr.tonemap = ToneMap::aces;
    hdr.hdr.exposure_auto = hdr.hdr.output_srgb = true;
    build(hdr);
    for (const ShaderRow& r : shader_rows()) EXPECT_TRUE(used.count(r.name)) << r.name << " is used by none";
}

// What the rows decide: without MRT a program per target; without the variants skip only the full
// material shader; the stencil pass's shader without the in-shader rejections.
TEST(ShaderTable, RowsFollowThePathsAndOptions) {
    auto ctx = create_context(ContextDesc{"osmesa", 64, 64});
    auto names = [](const ShaderConfig& c) {
        std::set<std::string> n;
        for (const ProgramSpec& p : shader_programs(c)) n.insert(p.name);
        return n;
    };
    ShaderOptions o;
    const std::set<std::string> mrt = names(shader_config(probe_caps(), o));
    EXPECT_TRUE(mrt.count("material") && mrt.count("material_flat") && !mrt.count("material/0"));
    const ShaderConfig per_target = shader_config(probe_caps({"no-mrt"}), o);
    for (int t = 0; t < per_target.paths.gbuffer_targets; ++t)
        EXPECT_TRUE(names(per_target).count("material/" + std::to_string(t))) << t;
    o.skip.material_variants = false;
    const std::set<std::string> full = names(shader_config(probe_caps(), o));
    EXPECT_TRUE(full.count("material") && !full.count("material_flat") && !full.count("material_no_specular"));
    ShaderOptions s;
    s.light_geometry = LightGeometry::stencil;
    int stencil_programs = 0;
    for (const ProgramSpec& p : shader_programs(shader_config(probe_caps(), s))) {
        if (p.name != "light_stencil") continue;
        ++stencil_programs;
        for (const std::string& d : p.defines) {
            EXPECT_NE(d, "LIGHT_DEPTH_TEST");
            EXPECT_NE(d, "LIGHT_SPHERE_TEST");
        }
    }
    EXPECT_EQ(stencil_programs, 1);
}

}  // namespace
}  // namespace dsr
