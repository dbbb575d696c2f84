// Post-processing stage (§3.5, Figure 7, Appendix A step 3): bloom, then anti-alias, each
// only when enabled, on the four ping-pong P-buffers. With both off this costs nothing.
#include <algorithm>
#include <utility>
#include <vector>

#include "deferred/deferred_shader.h"
#include "deferred/screen_quad.h"
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

void DeferredShader::post_stage(FrameStats& stats) {
    const PostOptions& p = opts_.post;
    if (p.bloom) {
        timer_.begin(S_BLOOM);
        draw_bloom();
        timer_.end();
    }
    if (p.aa) {
        timer_.begin(S_AA);
        draw_anti_alias();
        timer_.end();
    }
}

// Listing 22 from P-buffer src into dst. Offsets are one destination pixel apart, so the
// first pass also downsamples (bilinear taps) and the kernel's reach is in bloom pixels.
void DeferredShader::blur(int src, int dst, glm::vec2 dir, bool select) {
    fb_bind_render(dst);
    int dw = pbuf(dst).width(), dh = pbuf(dst).height();
    set_ortho(dw, dh);
    Program& prog = blur_prog_[select ? 1 : 0];
    gl_state().apply(post_pass_state(prog.id()));
    prog.set("source", 0);
    const int n = opts_.post.bloom_taps;
    const float sx = pbuf(src).tex_scale_x(), sy = pbuf(src).tex_scale_y();
    std::vector<GLfloat> offs(size_t(n) * 2);
    for (int i = 0; i < n; ++i) {
        float k = float(i - (n - 1) / 2);
        offs[2 * i] = k * dir.x * sx / float(dw);
        offs[2 * i + 1] = k * dir.y * sy / float(dh);
    }
    glUniform2fv(glGetUniformLocation(prog.id(), "offset"), n, offs.data());
    prog.set("uv_clamp", uv_clamp(pbuf(src)));
    fb_bind_texture(src, 0);
    draw_quad(float(dw), float(dh), sx, sy);
    fb_unbind_texture(src, 0);
    fb_unbind_render(dst);
    check_gl_stage("post stage: bloom blur");
}

// §3.5.2 / Appendix A: horizontal blur 0 -> 2, vertical 2 -> 3, then P-buffer 3 added to 0
// by fixed function (additive blend, texture modulated by the strength, no shader).
void DeferredShader::draw_bloom() {
    blur(P_ACCUM, P_BLOOM_H, {1, 0}, true);
    blur(P_BLOOM_H, P_BLOOM_V, {0, 1}, false);
    pbuf(P_ACCUM).bind_render(true);  // blends onto the lit image
    set_ortho(w_, h_);
    RenderState add = textured_2d(GL_MODULATE);
    add.blend = true;
    add.blend_src = add.blend_dst = GL_ONE;
    gl_state().apply(add);
    float s = opts_.post.bloom_strength;
    glColor4f(s, s, s, 1.0f);
    fb_bind_texture(P_BLOOM_V, 0);
    draw_quad_clamped(float(w_), float(h_), pbuf(P_BLOOM_V));
    fb_unbind_texture(P_BLOOM_V, 0);
    glColor4f(1, 1, 1, 1);
    fb_unbind_render(P_ACCUM);
    check_gl_stage("post stage: bloom add");
}

// §3.5.1 / Appendix A: anti-alias P-buffer 0 into P-buffer 1, then swap so 0 holds the
// result. factor_only writes the blur factor instead (Figure 8) and does not swap.
void DeferredShader::draw_anti_alias(bool factor_only) {
    fb_bind_render(P_AA);
    set_ortho(w_, h_);
    Program& prog = aa_prog_[factor_only ? 1 : 0];
    gl_state().apply(post_pass_state(prog.id()));
    prog.set("normal_map", 0);
    prog.set("color_map", 1);
    prog.set("depth_map", 2);
    const PBuffer& accum = pbuf(P_ACCUM);
    prog.set("pixel_size", glm::vec2(1.0f / float(accum.texture_width()), 1.0f / float(accum.texture_height())));
    prog.set("weight", opts_.post.aa_weight);
    prog.set("planes", planes_);
    prog.set("zrange", zrange_);
    prog.set("depth_scale", opts_.post.aa_depth_scale);
    prog.set("uv_clamp", uv_clamp(accum));  // G-buffer and P-buffer 0 share their size
    mrt_bind_texture(G_NORMAL, 0);
    fb_bind_texture(P_ACCUM, 1);
    mrt_bind_texture(depth_target(), 2);
    draw_quad(float(w_), float(h_), accum.tex_scale_x(), accum.tex_scale_y());
    mrt_unbind_texture(depth_target(), 2);
    fb_unbind_texture(P_ACCUM, 1);
    mrt_unbind_texture(G_NORMAL, 0);
    fb_unbind_render(P_AA);
    check_gl_stage("post stage: anti-alias");
    if (!factor_only) targets_->swap_accumulation();
}

}  // namespace dsr
