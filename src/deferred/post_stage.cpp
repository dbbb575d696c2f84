// Post-processing stage (§3.5, Figure 7, Appendix A step 3): bloom, then anti-alias, each
// only when enabled, on the four ping-pong P-buffers. With both off this costs nothing.
#include <utility>
#include <vector>

#include "dsr_clock.h"
#include "deferred/deferred_shader.h"
#include "gl/check.h"

namespace dsr {

namespace {
// [0,w]x[0,h] in the current ortho camera, texture coordinates 0..(sx,sy): the source's
// content extent (less than 1 when padded to powers of two).
void draw_quad(float w, float h, float sx, float sy) {
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(0, 0);
    glTexCoord2f(sx, 0); glVertex2f(w, 0);
    glTexCoord2f(sx, sy); glVertex2f(w, h);
    glTexCoord2f(0, sy); glVertex2f(0, h);
    glEnd();
}

// Texel centres of a buffer's content in texture coordinates: what CLAMP_TO_EDGE gives on
// an unpadded texture, so padded (power-of-two) buffers sample the same.
glm::vec4 uv_clamp(const PBuffer& b) {
    float tw = float(b.texture_width()), th = float(b.texture_height());
    return {0.5f / tw, 0.5f / th, (b.width() - 0.5f) / tw, (b.height() - 0.5f) / th};
}

void post_states() {
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_TEXTURE_2D);
}
}  // namespace

void DeferredShader::post_stage(FrameStats& stats) {
    const PostOptions& p = opts_.post;
    if (p.bloom) {
        double t0 = now_ms();
        draw_bloom();
        glFinish();
        stats.ms.bloom = now_ms() - t0;
    }
    if (p.aa) {
        double t0 = now_ms();
        draw_anti_alias();
        glFinish();
        stats.ms.aa = now_ms() - t0;
    }
}

// Listing 22 from P-buffer src into dst. Offsets are one destination pixel apart, so the
// first pass also downsamples (bilinear taps) and the kernel's reach is in bloom pixels.
void DeferredShader::blur(int src, int dst, glm::vec2 dir, bool select) {
    post_states();
    fb_bind_render(dst);
    int dw = fb_[dst]->width(), dh = fb_[dst]->height();
    set_ortho(dw, dh);
    Program& prog = blur_prog_[select ? 1 : 0];
    prog.use();
    prog.set("source", 0);
    const int n = opts_.post.bloom_taps;
    const float sx = fb_[src]->tex_scale_x(), sy = fb_[src]->tex_scale_y();
    std::vector<GLfloat> offs(size_t(n) * 2);
    for (int i = 0; i < n; ++i) {
        float k = float(i - (n - 1) / 2);
        offs[2 * i] = k * dir.x * sx / float(dw);
        offs[2 * i + 1] = k * dir.y * sy / float(dh);
    }
    glUniform2fv(glGetUniformLocation(prog.id(), "offset"), n, offs.data());
    prog.set("uv_clamp", uv_clamp(*fb_[src]));
    fb_bind_texture(src, 0);
    draw_quad(float(dw), float(dh), sx, sy);
    fb_unbind_texture(src, 0);
    glUseProgram(0);
    fb_unbind_render(dst);
    check_gl("post stage: bloom blur");
}

// §3.5.2 / Appendix A: horizontal blur 0 -> 2, vertical 2 -> 3, then P-buffer 3 added to 0
// by fixed function (additive blend, texture modulated by the strength, no shader).
void DeferredShader::draw_bloom() {
    blur(0, 2, {1, 0}, true);
    blur(2, 3, {0, 1}, false);
    post_states();
    fb_[0]->bind_render(true);  // blends onto the lit image
    set_ortho(w_, h_);
    glUseProgram(0);
    float s = opts_.post.bloom_strength;
    glColor4f(s, s, s, 1.0f);
    glActiveTexture(GL_TEXTURE0);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glBlendFunc(GL_ONE, GL_ONE);
    glEnable(GL_BLEND);
    fb_bind_texture(3, 0);
    draw_quad(float(w_), float(h_), fb_[3]->tex_scale_x(), fb_[3]->tex_scale_y());
    fb_unbind_texture(3, 0);
    glDisable(GL_BLEND);
    glDisable(GL_TEXTURE_2D);
    glColor4f(1, 1, 1, 1);
    fb_unbind_render(0);
    check_gl("post stage: bloom add");
}

// §3.5.1 / Appendix A: anti-alias P-buffer 0 into P-buffer 1, then swap so 0 holds the
// result. factor_only writes the blur factor instead (Figure 8) and does not swap.
void DeferredShader::draw_anti_alias(bool factor_only) {
    post_states();
    fb_bind_render(1);
    set_ortho(w_, h_);
    Program& prog = aa_prog_[factor_only ? 1 : 0];
    prog.use();
    prog.set("normal_map", 0);
    prog.set("color_map", 1);
    prog.set("depth_map", 2);
    prog.set("pixel_size", glm::vec2(1.0f / float(fb_[0]->texture_width()), 1.0f / float(fb_[0]->texture_height())));
    prog.set("weight", opts_.post.aa_weight);
    prog.set("planes", planes_);
    prog.set("zrange", zrange_);
    prog.set("depth_scale", opts_.post.aa_depth_scale);
    prog.set("uv_clamp", uv_clamp(*fb_[0]));  // G-buffer and P-buffer 0 share their size
    mrt_bind_texture(G_NORMAL, 0);
    fb_bind_texture(0, 1);
    mrt_bind_texture(depth_target(), 2);
    draw_quad(float(w_), float(h_), fb_[0]->tex_scale_x(), fb_[0]->tex_scale_y());
    mrt_unbind_texture(depth_target(), 2);
    fb_unbind_texture(0, 1);
    mrt_unbind_texture(G_NORMAL, 0);
    glUseProgram(0);
    fb_unbind_render(1);
    check_gl("post stage: anti-alias");
    if (!factor_only) std::swap(fb_[0], fb_[1]);
}

}  // namespace dsr
