#include "deferred/render_targets.h"

#include <algorithm>
#include <string>

#include "dsr_error.h"

namespace dsr {

GLenum gl_format(TargetFormat f) {
    return f == TargetFormat::rgba8 ? GLenum(GL_RGBA8) : f == TargetFormat::rgba16f ? GLenum(GL_RGBA16F_ARB)
                                                                                     : GLenum(GL_RGBA32F_ARB);
}

GLenum accum_gl_format(AccumFormat a) {
    return a == AccumFormat::rgba8 ? GLenum(GL_RGBA8) : a == AccumFormat::half ? GLenum(GL_RGBA16F_ARB) : GLenum(GL_RGBA32F_ARB);
}

RenderTargets::RenderTargets(const Paths& paths, const ShaderOptions& opts, int width, int height)
    : paths_(paths), opts_(opts), w_(width), h_(height) {
    allocate();
}

void RenderTargets::resize(int width, int height) {
    if (width == w_ && height == h_) return;
    w_ = width;
    h_ = height;
    allocate();
}

void RenderTargets::allocate() {
    if (w_ <= 0 || h_ <= 0)
        throw Error("render targets: bad size " + std::to_string(w_) + "x" + std::to_string(h_));
    // The old buffers go first, so peak memory is one set.
    gbuffer_written_ = false;
    g_.reset();
    for (auto& p : p_) p.reset();
    for (auto& a : ao_) a.reset();
    // Figure 3: normal, diffuse, specular+shininess, and packed depth only when that path runs.
    PBufferDesc g;
    g.width = w_;
    g.height = h_;
    g.use_fbo = paths_.fbo;
    g.use_pbuffer = paths_.pbuffer;
    g.pow2 = paths_.pow2;
    // The formats choose_paths picked (Paths::gbuffer_formats): RGBA8, or half with the half-float
    // option (the packed depth keeps its byte codes, exact in half), and the position paths'
    // float target; all one format where only EXT_framebuffer_object is present.
    for (TargetFormat f : paths_.gbuffer_formats) g.color_formats.push_back(gl_format(f));
    // The position paths keep a depth buffer for the pre-pass's depth test only: a renderbuffer.
    g.depth = paths_.gbuffer_depth_texture ? DepthAttachment::texture : DepthAttachment::renderbuffer;
    g_ = std::make_unique<PBuffer>("G-buffer", g);
    // P-buffers 0-3 (§3.2). Bilinear, so the final pass can scale (§3.6).
    const int bs = opts_.post.bloom_scale;
    for (int i = 0; i < 4; ++i) {
        const bool bloom = i == P_BLOOM_H || i == P_BLOOM_V;  // reduced (§3.5.2)
        PBufferDesc p;
        p.width = bloom ? std::max(1, w_ / bs) : w_;
        p.height = bloom ? std::max(1, h_ / bs) : h_;
        // --accum (docs/hdr.md): every P-buffer in its format, so the post passes that read P-buffer 0
        // (anti-alias into 1, bloom's blurs into 2 and 3) keep what lies above 1; the stress runs
        // take float so NaN and Inf survive to be counted.
        p.color_formats = {accum_gl_format(opts_.hdr.accum)};
        p.filter = GL_LINEAR;
        p.use_fbo = paths_.fbo;
        p.use_pbuffer = paths_.pbuffer;
        p.pow2 = paths_.pow2;
        // The G-buffer's depth is handed to P-buffer 0 (hand_off_depth); 1 too, as the
        // anti-alias pass swaps the two. Without framebuffer objects the main buffer's serves.
        if (!bloom && paths_.accum_depth)
            p.depth = paths_.accum_stencil ? DepthAttachment::depth_stencil : DepthAttachment::renderbuffer;
        p_[i] = std::make_unique<PBuffer>("P-buffer " + std::to_string(i), p);
    }
    ambient_target_ = paths_.ambient_target && g_->attach_extra(p_[P_ACCUM]->texture(0), true) &&
                      g_->attach_extra(p_[P_AA]->texture(0), true);
    if (paths_.ambient_target) g_->attach_extra(0);
    // SSAO: occlusion, then its blur, at 1/scale; bilinear, so the ambient pass can scale the
    // half-size one up. The same render-target path as the P-buffers (fbo or copy).
    if (opts_.ssao.on) {
        const int s = opts_.ssao.scale;
        for (int i = 0; i < 2; ++i) {
            PBufferDesc a;
            a.width = std::max(1, w_ / s);
            a.height = std::max(1, h_ / s);
            a.color_formats = {GL_RGBA8};
            a.filter = GL_LINEAR;
            a.use_fbo = paths_.fbo;
            a.pow2 = paths_.pow2;
            ao_[i] = std::make_unique<PBuffer>(i == SSAO_RAW ? "SSAO buffer" : "SSAO blurred buffer", a);
        }
    }
}

bool RenderTargets::accum_attachable() {
    if (accum_attachable_ < 0) {
        GLint attachments = 0;
        if (paths_.fbo) glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS_EXT, &attachments);
        const bool room = paths_.fbo && attachments > g_->color_targets();
        accum_attachable_ = room && g_->attach_extra(p_[P_ACCUM]->texture(0), true) &&
                            g_->attach_extra(p_[P_AA]->texture(0), true);
        if (room) g_->attach_extra(0);
    }
    return accum_attachable_ == 1;
}

PBuffer& RenderTargets::ssao(int which) {
    if (!ao_[which]) throw Error("the SSAO buffers exist only with --ssao on");
    return *ao_[which];
}

}  // namespace dsr
