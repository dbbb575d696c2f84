// Lighting stage (§3.4, Listings 14-20): image space, into P-buffer 0. A fixed-function
// ambient pass (Eq. 6), then every visible light added by the light geometry the options
// ask for (issue 12): the tutorial's scissored screen-aligned quad per light, the light's
// volume mesh, the volume masked by a stencil pass, or screen tiles shading up to N lights
// per pass. Each geometry has its own file, light_geometry_*.cpp.

#include <glm/gtc/type_ptr.hpp>

#include "deferred/culling.h"
#include "deferred/deferred_shader.h"
#include "deferred/light_params.h"
#include "deferred/light_volume.h"
#include "deferred/reconstruct.h"
#include "deferred/scissor.h"
#include "gl/check.h"
#include "gl/state.h"

namespace dsr {

// Listing 14.
void DeferredShader::draw_lights(const Scene& scene, bool scissors, FrameStats& stats) {
    if (opts_.ssao.on) {  // issue 13: the AO buffer the ambient pass multiplies by (ssao_stage.cpp)
        timer_.begin(S_SSAO);
        draw_ssao();
        timer_.end();
    }
    timer_.begin(S_AMBIENT);
    fb_bind_render(P_ACCUM);
    set_ortho(w_, h_);
    draw_ambient(scene);
    if (opts_.ssao.on) modulate_ambient_by_ssao();
    check_gl_stage("lighting stage: ambient pass");
    timer_.end();

    const int units[4] = {0, 1, 2, 3};
    const int targets[4] = {G_NORMAL, G_DIFFUSE, G_SPECULAR, depth_target()};
    for (int i = 0; i < 4; ++i) mrt_bind_texture(targets[i], units[i]);  // mrt_bind_texture(ALL)
    if (paths_.accum_depth) {
        timer_.begin(S_DEPTH_COPY);
        hand_off_depth();
        check_gl_stage("lighting stage: depth hand-off");
        timer_.end();
    }
    timer_.begin(S_LIGHTS);
    draw_lighting(scene, scissors, stats);
    for (int i = 3; i >= 0; --i) mrt_unbind_texture(targets[i], units[i]);
    check_gl_stage("lighting stage: light passes");
    if (paths_.forward_stage) {  // issue 13: markers and transparent surfaces (forward_stage.cpp)
        timer_.end();
        timer_.begin(S_FORWARD);
        forward_stage(scene, stats);
        check_gl_stage("forward stage");
    }
    fb_unbind_render(P_ACCUM);
    timer_.end();
}

// Listing 15's fixed-function modulate: unit 0 textured by the G-buffer's diffuse target,
// scaled by the ambient colour; the alpha test keeps the background where there is no surface.
// Listing 7 disabled GL_TEXTURE_2D; the modulate needs it back (docs/errata.md).
RenderState DeferredShader::ambient_pass_state() {
    RenderState s = textured_2d(GL_MODULATE);
    s.alpha_test = true;
    s.alpha_func = GL_GREATER;
    s.alpha_ref = 0.5f;
    return s;
}

// Listing 16-17: additive, through the light shader, limited to the light's scissor rectangle.
RenderState DeferredShader::light_pass_state(GLuint program, bool scissor) {
    RenderState s;
    s.blend = true;
    s.blend_src = s.blend_dst = GL_ONE;
    s.scissor = scissor;
    s.program = program;
    return s;
}

// Listing 15, with the background kept: P-buffer 0 starts as the background colour and
// the alpha test keeps it where the G-buffer holds no surface (diffuse alpha 0).
void DeferredShader::draw_ambient(const Scene& scene) {
    gl_state().apply(ambient_pass_state());  // before the clear: colour writes on, no scissor
    glClearColor(scene.background.r, scene.background.g, scene.background.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(scene.ambient.r, scene.ambient.g, scene.ambient.b, 1.0f);
    mrt_bind_texture(G_DIFFUSE, 0);
    draw_rect(0, 0, float(w_), float(h_), false);
    mrt_unbind_texture(G_DIFFUSE, 0);
    glColor4f(1, 1, 1, 1);
}

// The uniforms every light program shares (bind_light()).
void DeferredShader::set_light_uniforms(Program& prog) {
    gl_state().use_program(prog.id());
    prog.set("normal_map", 0);
    prog.set("diffuse_map", 1);
    prog.set("specular_map", 2);
    prog.set("depth_map", 3);
    prog.set("planes", planes_);
    prog.set("zrange", zrange_);
    // Texture coordinates from gl_FragCoord (the G-buffer may be padded to powers of two).
    prog.set("uv_scale", gbuffer_uv_scale());
    // The view ray through window point (x, y): the corner rays' bilinear map, which is affine.
    prog.set("ray_map", ray_map());
}

// set_light_params: one light as lighting.glsl's five vec4s (light_params.h).
void DeferredShader::set_light_params(Program& prog, const LightParams& lp) {
    prog.set("lightpos", lp.pos);
    prog.set("lightcolor", lp.color);
    prog.set("lightdir", lp.dir);
    prog.set("lightspot", lp.spot);
    prog.set("lightatt", lp.att);
}

// Listing 17 lines 11-31: frustum culling, the empty-light skip and each light's scissor
// rectangle (Listing 16), whatever geometry then draws the light. Culling and the rectangle come
// from the light's volume (light_volume.h): a sphere as in the tutorial, a spot's cone, or a
// directional light's full screen (never culled, never scissored).
std::vector<DeferredShader::LightDraw> DeferredShader::visible_lights(const Scene& scene, bool scissors,
                                                                     FrameStats& stats) {
    const auto frustum = frustum_planes(proj_ * view_);
    const float near_plane = scene.camera.near_plane;
    const bool skip_empty = opts_.skip.empty_lights;
    std::vector<LightDraw> out;
    stats.lights_total = int(scene.lights.size());
    for (const Light& light : scene.lights) {
        const LightVolume volume = light_volume(light);
        if (volume_outside(frustum, volume)) {
            ++stats.lights_culled;
            continue;
        }
        if (skip_empty && light.color.r <= 0 && light.color.g <= 0 && light.color.b <= 0) {
            ++stats.lights_culled;  // adds nothing
            continue;
        }
        // In double, rounded once (Camera::to_eye): far from the origin, view_ * pos in float would
        // lose the light's position to the world coordinates' rounding (stress case coords).
        const LightVolume eye = to_eye(volume, scene.camera);
        ScissorRect r = volume_scissor(eye, proj_[0][0], proj_[1][1], near_plane, w_, h_);
        long long n = r.area();
        if (n <= 0) {
            if (skip_empty) {  // the volume reaches no visible pixel: Listing 17 line 31
                ++stats.lights_culled;
                continue;
            }
            r = ScissorRect{0, 0, w_, h_};  // without the skip: shade the screen for nothing
            n = (long long)w_ * h_;
        }
        const bool full = !scissors || n == (long long)w_ * h_;
        if (full) r = ScissorRect{0, 0, w_, h_};
        stats.scissor_pixels += r.area();
        ++stats.lights_drawn;
        out.push_back(LightDraw{&light, light_params(light, scene.camera), eye, r, full});
    }
    return out;
}

// Listing 17: cull against the view frustum, then the light geometry.
void DeferredShader::draw_lighting(const Scene& scene, bool scissors, FrameStats& stats) {
    const auto rays = corner_rays(proj_[0][0], proj_[1][1]);
    for (int i = 0; i < 4; ++i) corner_rays_[i] = rays[i];
    frame_lights_ = visible_lights(scene, scissors, stats);
    const std::vector<LightDraw>& lights = frame_lights_;
    switch (paths_.light_geometry) {
        case LightGeometry::quad: draw_lights_quad(lights, stats); break;
        case LightGeometry::volume: draw_lights_volume(lights, stats); break;
        case LightGeometry::stencil: draw_lights_stencil(lights, stats); break;
        case LightGeometry::tiles: draw_lights_tiles(lights, stats); break;
    }
    // unbind_light(): nothing to restore, the next pass states what it needs.
}

}  // namespace dsr
