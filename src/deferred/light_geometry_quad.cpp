// Light geometry `quad` (§3.4.2, Listings 16-17): the tutorial's screen-aligned quad per light,
// limited to the light's scissor rectangle; every pixel of the rectangle enters the light
// shader. With EXT_depth_bounds_test (`--depth-bounds on`), pixels whose scene depth (handed to
// P-buffer 0 by hand_off_depth) lies outside the sphere's depth span are rejected before the
// shader runs.
#include <algorithm>

#include "deferred/deferred_shader.h"
#include "deferred/light_queries.h"
#include "gl/state.h"

namespace dsr {

namespace {

// Window depth of eye-space z (glm::perspective's mapping, §3.4.3's `planes` inverted).
float window_depth(float z, glm::vec2 planes) { return (planes.x * z + planes.y) / -z; }

}  // namespace

void DeferredShader::draw_light_quad(const LightDraw& l, LightQueries& q) {
    // The tutorial's point lights take the variant without type and law selection (deferred_shader.h).
    Program& prog = tutorial_light(*l.light) ? light_prog_ : light_any_prog_;
    RenderState s = light_pass_state(prog.id(), !l.full);
    if (!l.full) glScissor(l.rect.x0, l.rect.y0, l.rect.x1 - l.rect.x0, l.rect.y1 - l.rect.y0);  // set_light_scissor
    if (paths_.depth_bounds && l.eye.kind != LightVolume::Kind::full_screen) {
        // The depth span of the volume's bounding sphere (a cone's lies inside its apex sphere's).
        const BoundingSphere b = bounding_sphere(l.eye);
        const float n = zrange_.x, f = zrange_.y;
        const float z_near = std::min(-n, b.centre.z + b.radius), z_far = std::max(-f, b.centre.z - b.radius);
        s.depth_bounds_test = true;
        s.depth_test = true;  // the bounds test reads the depth buffer; GL_ALWAYS keeps the rest as it was
        s.depth_func = GL_ALWAYS;
        s.depth_write = false;
        glDepthBoundsEXT(std::max(0.0f, window_depth(z_near, planes_)), std::min(1.0f, window_depth(z_far, planes_)));
    }
    gl_state().apply(s);
    set_light_params(prog, l.params);
    q.begin();
    draw_rect(0, 0, float(w_), float(h_), true);
    q.end();
    ++light_passes_drawn_;
}

void DeferredShader::draw_lights_quad(const std::vector<LightDraw>& lights, FrameStats& stats) {
    set_light_uniforms(light_any_prog_);
    set_light_uniforms(light_prog_);
    LightQueries q(counting_ && paths_.count_fragments, counting_ && caps_.pipeline_statistics);
    light_passes_drawn_ = 0;
    for (const LightDraw& l : lights) draw_light_quad(l, q);
    q.collect(stats);
    stats.light_passes = light_passes_drawn_;
}

}  // namespace dsr
