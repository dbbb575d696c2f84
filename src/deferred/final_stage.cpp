// The final stage (final_stage.h).
#include "deferred/final_stage.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "deferred/screen_quad.h"
#include "gl/blit.h"
#include "gl/check.h"
#include "gl/readback.h"
#include "gl/state.h"

namespace dsr {

float auto_exposure_scale(const std::vector<float>& means, float key) {
    if (means.empty()) return 1.0f;
    double sum = 0;
    for (float m : means) sum += m;
    return float(double(key) / std::exp2(sum / double(means.size())));
}

Image resample_bilinear(const Image& img, int w, int h) {
    if (w == img.width && h == img.height) return img;
    Image out;
    out.width = w, out.height = h;
    out.rgba.resize(size_t(w) * size_t(h) * 4);
    // Output pixel centre x + 0.5 lands at source texel coordinate (x + 0.5) * W / w - 0.5.
    auto taps = [](int i, int n_out, int n_in, int& a, int& b, float& t) {
        const double c = std::clamp((i + 0.5) * double(n_in) / double(n_out) - 0.5, 0.0, double(n_in - 1));
        a = int(std::floor(c));
        b = std::min(a + 1, n_in - 1);
        t = float(c - a);
    };
    for (int y = 0; y < h; ++y) {
        int y0, y1;
        float ty;
        taps(y, h, img.height, y0, y1, ty);
        for (int x = 0; x < w; ++x) {
            int x0, x1;
            float tx;
            taps(x, w, img.width, x0, x1, tx);
            float* d = out.at(x, y);
            for (int c = 0; c < 4; ++c) {
                const float top = img.at(x0, y1)[c] + (img.at(x1, y1)[c] - img.at(x0, y1)[c]) * tx;
                const float bottom = img.at(x0, y0)[c] + (img.at(x1, y0)[c] - img.at(x0, y0)[c]) * tx;
                d[c] = bottom + (top - bottom) * ty;
            }
        }
    }
    return out;
}

FinalStage::FinalStage(bool fbo) : fbo_(fbo) {}
FinalStage::~FinalStage() = default;

void FinalStage::set_up(const ShaderConfig& c, ProgramSet& programs) {
    hdr_ = c.opts.hdr;
    if (programs.has("tonemap")) tonemap_ = programs.take("tonemap");
    if (programs.has("log_luminance")) log_luminance_ = programs.take("log_luminance");
}

std::vector<glm::vec2> FinalStage::reduce_luminance(const RenderTargets& t) {
    if (!log_luminance_.id()) return {};
    const PBuffer& accum = t.pbuffer(P_ACCUM);
    // At most 64 blocks a side, each TAPS x TAPS samples of its block: a few thousand texels read
    // back, whatever the frame's size.
    const int rw = std::min(64, accum.width()), rh = std::min(64, accum.height());
    if (!reduced_ || reduced_->width() != rw || reduced_->height() != rh) {
        PBufferDesc d;
        d.width = rw;
        d.height = rh;
        d.color_formats = {GL_RGBA32F_ARB};
        reduced_ = std::make_unique<PBuffer>("log-luminance buffer", d);
    }
    reduced_->bind_render();
    gl_state().set_camera(glm::ortho(0.0f, float(rw), 0.0f, float(rh), -1.0f, 1.0f));
    RenderState s = fixed_function_2d();
    s.program = log_luminance_.id();
    gl_state().apply(s);
    log_luminance_.set("source", 0);
    const float sx = accum.tex_scale_x(), sy = accum.tex_scale_y();
    log_luminance_.set("block", glm::vec2(sx / float(rw), sy / float(rh)));
    log_luminance_.set("uv_clamp", uv_clamp(accum));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, accum.texture(0));
    draw_quad(float(rw), float(rh), sx, sy);
    glBindTexture(GL_TEXTURE_2D, 0);
    std::vector<float> px(size_t(rw) * size_t(rh) * 4);
    glReadPixels(0, 0, rw, rh, GL_RGBA, GL_FLOAT, px.data());
    reduced_->unbind_render();
    check_gl_stage("final stage: log luminance");
    std::vector<glm::vec2> out(size_t(rw) * size_t(rh));
    for (size_t i = 0; i < out.size(); ++i) out[i] = {px[4 * i], px[4 * i + 1]};
    return out;
}

void FinalStage::draw(const RenderTargets& t, int out_w, int out_h) {
    const PBuffer& accum = t.pbuffer(P_ACCUM);
    const glm::vec2 extent{accum.tex_scale_x(), accum.tex_scale_y()};
    if (!tonemap_.id()) {  // the tutorial's fixed-function copy (§3.6)
        scale_ = 1;
        draw_texture(accum.texture(0), out_w, out_h, extent);
        return;
    }
    scale_ = std::exp2(hdr_.exposure);
    if (hdr_.exposure_auto) {
        std::vector<float> means;
        for (const glm::vec2& b : reduce_luminance(t)) means.push_back(b.x);
        scale_ = auto_exposure_scale(means);
    }
    if (fbo_) glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    glDrawBuffer(GL_BACK);
    glViewport(0, 0, out_w, out_h);
    gl_state().set_camera(glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f));  // the unit square
    RenderState s = fixed_function_2d();
    s.program = tonemap_.id();
    gl_state().apply(s);
    tonemap_.set("source", 0);
    tonemap_.set("exposure_scale", scale_);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, accum.texture(0));
    // P-buffer 0 samples bilinearly (render_targets.cpp); at the buffers' own size every fragment
    // samples a texel centre, so that is the texel itself, as the fixed-function copy's nearest.
    draw_quad(1.0f, 1.0f, extent.x, extent.y);
    glBindTexture(GL_TEXTURE_2D, 0);
    check_gl_stage("final stage: tone mapping");
}

Image FinalStage::read_linear(const RenderTargets& t, int out_w, int out_h) const {
    const PBuffer& accum = t.pbuffer(P_ACCUM);
    Image img = read_texture(accum.texture(0), accum.width(), accum.height(), accum.texture_width(),
                             accum.texture_height(), false);
    for (size_t i = 0; i < img.rgba.size(); ++i)
        if (i % 4 != 3) img.rgba[i] = (img.rgba[i] < 0.0f ? 0.0f : img.rgba[i]) * scale_;
    return resample_bilinear(img, out_w, out_h);
}

void FinalStage::draw_texture(GLuint texture, int out_w, int out_h, glm::vec2 extent) const {
    draw_texture_to_framebuffer0(texture, out_w, out_h, extent, fbo_);
}

}  // namespace dsr
