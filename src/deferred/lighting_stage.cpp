// Lighting stage (§3.4, Listings 14-20): image space, into P-buffer 0. A fixed-function
// ambient pass (Eq. 6), then one additive screen-aligned quad per visible light, limited
// to the light's scissor rectangle.

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
    timer_.begin(S_AMBIENT);
    fb_bind_render(P_ACCUM);
    set_ortho(w_, h_);
    draw_ambient(scene);
    check_gl_stage("lighting stage: ambient pass");
    timer_.end();

    timer_.begin(S_LIGHTS);
    const int units[4] = {0, 1, 2, 3};
    const int targets[4] = {G_NORMAL, G_DIFFUSE, G_SPECULAR, depth_target()};
    for (int i = 0; i < 4; ++i) mrt_bind_texture(targets[i], units[i]);  // mrt_bind_texture(ALL)
    draw_lighting(scene, scissors, stats);
    for (int i = 3; i >= 0; --i) mrt_unbind_texture(targets[i], units[i]);
    check_gl_stage("lighting stage: light passes");
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

// Listing 17: cull against the view frustum, scissor, one quad per light. Culling and the
// rectangle come from the light's volume (light_volume.h): a sphere as in the tutorial, a spot's
// cone, or a directional light's full screen (never culled, never scissored).
void DeferredShader::draw_lighting(const Scene& scene, bool scissors, FrameStats& stats) {
    const auto frustum = frustum_planes(proj_ * view_);
    const auto rays = corner_rays(proj_[0][0], proj_[1][1]);
    for (int i = 0; i < 4; ++i) corner_rays_[i] = rays[i];
    const float near_plane = scene.camera.near_plane;

    // bind_light(): the frame's uniforms on both light programs (deferred_shader.h: the
    // tutorial's point lights take the variant without the type and law selection).
    for (Program* prog : {&light_prog_, &light_any_prog_}) {
        gl_state().apply(light_pass_state(prog->id(), false));
        prog->set("normal_map", 0);
        prog->set("diffuse_map", 1);
        prog->set("specular_map", 2);
        prog->set("depth_map", 3);
        prog->set("planes", planes_);
        prog->set("zrange", zrange_);
    }

    const bool count = paths_.count_fragments;
    const bool invocations = caps_.pipeline_statistics;
    stats.fragments_counted = count;
    std::vector<GLuint> queries, inv_queries;
    stats.lights_total = int(scene.lights.size());
    for (const Light& light : scene.lights) {
        const LightVolume volume = light_volume(light);
        if (volume_outside(frustum, volume)) {
            ++stats.lights_culled;
            continue;
        }
        const bool skip_empty = opts_.skip.empty_lights;
        if (skip_empty && light.color.r <= 0 && light.color.g <= 0 && light.color.b <= 0) {
            ++stats.lights_culled;  // adds nothing
            continue;
        }
        // In double, rounded once (Camera::to_eye): far from the origin, view_ * pos in float would
        // lose the light's position to the world coordinates' rounding (stress case coords).
        ScissorRect r = volume_scissor(to_eye(volume, scene.camera), proj_[0][0], proj_[1][1], near_plane, w_, h_);
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
        if (full) n = (long long)w_ * h_;
        else glScissor(r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0);  // set_light_scissor (Listing 16)
        Program& prog = tutorial_light(light) ? light_prog_ : light_any_prog_;
        gl_state().apply(light_pass_state(prog.id(), !full));
        stats.scissor_pixels += n;
        ++stats.lights_drawn;
        const LightParams lp = light_params(light, scene.camera);  // set_light_params
        prog.set("lightpos", lp.pos);
        prog.set("lightcolor", lp.color);
        prog.set("lightdir", lp.dir);
        prog.set("lightspot", lp.spot);
        prog.set("lightatt", lp.att);
        if (count) {
            queries.push_back(0);
            glGenQueries(1, &queries.back());
            glBeginQuery(GL_SAMPLES_PASSED, queries.back());
        }
        if (invocations) {  // beside the occlusion query: every fragment that ran the shader
            inv_queries.push_back(0);
            glGenQueries(1, &inv_queries.back());
            glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, inv_queries.back());
        }
        draw_rect(0, 0, float(w_), float(h_), true);
        if (invocations) glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
        if (count) glEndQuery(GL_SAMPLES_PASSED);
    }
    // unbind_light(): nothing to restore, the next pass states what it needs.
    // Results are read after the loop so no light waits on the one before it.
    for (GLuint q : queries) {
        GLuint samples = 0;
        glGetQueryObjectuiv(q, GL_QUERY_RESULT, &samples);
        stats.light_fragments += samples;
        glDeleteQueries(1, &q);
    }
    if (invocations) {
        long long n = 0;
        for (GLuint q : inv_queries) {
            GLuint fragments = 0;  // one pass: at most w x h, fits 32 bits
            glGetQueryObjectuiv(q, GL_QUERY_RESULT, &fragments);
            n += fragments;
            glDeleteQueries(1, &q);
        }
        stats.light_invocations = n;
    }
}

}  // namespace dsr
