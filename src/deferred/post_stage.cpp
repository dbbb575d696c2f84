// The post-processing stage (post_stage.h).
#include "deferred/post_stage.h"

#include <vector>

#include "deferred/screen_quad.h"
#include "dsr_error.h"
#include "gl/check.h"
#include "gl/state.h"

namespace dsr {

namespace {
// A post pass through `program`: one full-screen quad, every test off, no blending.
RenderState post_pass_state(GLuint program) {
    RenderState s = fixed_function_2d();
    s.program = program;
    return s;
}
}  // namespace

PostStage::PostStage(const ShaderConfig& c, ProgramSet& programs)
    : p_(c.opts.post), depth_target_(depth_target(c.opts.depth)) {
    if (programs.has("bloom_blur")) {
        blur_[0] = programs.take("bloom_blur");
        blur_[1] = programs.take("bloom_select");
    }
    aa_[0] = programs.take("anti_alias");
    aa_[1] = programs.take("aa_factor");
}

// Offsets are one destination pixel apart, so the first pass also downsamples (bilinear taps)
// and the kernel's reach is in bloom pixels.
void PostStage::blur(RenderTargets& t, int src, int dst, glm::vec2 dir, bool select) {
    Program& prog = blur_[select ? 1 : 0];
    if (!prog.id()) throw Error("the bloom blur needs bloom enabled");
    t.fb_bind_render(dst);
    const PBuffer& s = t.pbuffer(src);
    const int dw = t.pbuffer(dst).width(), dh = t.pbuffer(dst).height();
    gl_state().set_camera(pixel_ortho(float(dw), float(dh)));
    gl_state().apply(post_pass_state(prog.id()));
    prog.set("source", 0);
    const int n = p_.bloom_taps;
    const float sx = s.tex_scale_x(), sy = s.tex_scale_y();
    std::vector<glm::vec2> offs(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        const float k = float(i - (n - 1) / 2);
        offs[size_t(i)] = glm::vec2(k * dir.x * sx / float(dw), k * dir.y * sy / float(dh));
    }
    glUniform2fv(glGetUniformLocation(prog.id(), "offset"), n, &offs[0].x);
    prog.set("uv_clamp", uv_clamp(s));
    if (select) prog.set("threshold", p_.bloom_threshold);  // SELECT_THRESHOLD (float accumulation) reads it
    t.fb_bind_texture(src, 0);
    draw_quad(float(dw), float(dh), sx, sy);
    t.fb_unbind_texture(src, 0);
    t.fb_unbind_render(dst);
    check_gl_stage("post stage: bloom blur");
}

// Appendix A: the bloom added to P-buffer 0 by fixed function (additive blend, texture
// modulated by the strength, no shader).
void PostStage::draw_bloom(RenderTargets& t) {
    blur(t, P_ACCUM, P_BLOOM_H, {1, 0}, true);
    blur(t, P_BLOOM_H, P_BLOOM_V, {0, 1}, false);
    const int w = t.width(), h = t.height();
    t.pbuffer(P_ACCUM).bind_render(true);  // blends onto the lit image
    gl_state().set_camera(pixel_ortho(float(w), float(h)));
    RenderState add = textured_2d(GL_MODULATE);
    add.blend = true;
    add.blend_src = add.blend_dst = GL_ONE;
    gl_state().apply(add);
    const float s = p_.bloom_strength;
    glColor4f(s, s, s, 1.0f);
    t.fb_bind_texture(P_BLOOM_V, 0);
    draw_quad_clamped(float(w), float(h), t.pbuffer(P_BLOOM_V));
    t.fb_unbind_texture(P_BLOOM_V, 0);
    glColor4f(1, 1, 1, 1);
    t.fb_unbind_render(P_ACCUM);
    check_gl_stage("post stage: bloom add");
}

// Appendix A: anti-alias into P-buffer 1, then swap P-buffers 0 and 1.
void PostStage::draw_anti_alias(const FrameDef& f, RenderTargets& t, bool factor_only) {
    t.fb_bind_render(P_AA);
    gl_state().set_camera(f.pixels());
    Program& prog = aa_[factor_only ? 1 : 0];
    gl_state().apply(post_pass_state(prog.id()));
    prog.set("normal_map", 0);
    prog.set("color_map", 1);
    prog.set("depth_map", 2);
    const PBuffer& accum = t.pbuffer(P_ACCUM);
    prog.set("pixel_size", glm::vec2(1.0f / float(accum.texture_width()), 1.0f / float(accum.texture_height())));
    prog.set("weight", p_.aa_weight);
    prog.set("planes", f.planes);
    prog.set("zrange", f.zrange);
    prog.set("depth_scale", p_.aa_depth_scale);
    prog.set("uv_clamp", uv_clamp(accum));  // G-buffer and P-buffer 0 share their size
    t.mrt_bind_texture(G_NORMAL, 0);
    t.fb_bind_texture(P_ACCUM, 1);
    t.mrt_bind_texture(depth_target_, 2);
    draw_quad(float(f.width), float(f.height), accum.tex_scale_x(), accum.tex_scale_y());
    t.mrt_unbind_texture(depth_target_, 2);
    t.fb_unbind_texture(P_ACCUM, 1);
    t.mrt_unbind_texture(G_NORMAL, 0);
    t.fb_unbind_render(P_AA);
    check_gl_stage("post stage: anti-alias");
    if (!factor_only) t.swap_accumulation();
}

}  // namespace dsr
