#include "gl/pbuffer.h"

#include <algorithm>

#include "gl/surfaces.h"

#include "dsr_error.h"
#include "gl/check.h"
#include "gl/state.h"

namespace dsr {

int next_pow2(int v) {
    int p = 1;
    while (p < v) p <<= 1;
    return p;
}

PBuffer::PBuffer(std::string name, const PBufferDesc& desc) : name_(std::move(name)), desc_(desc) {
    tex_w_ = desc.pow2 ? next_pow2(desc.width) : desc.width;
    tex_h_ = desc.pow2 ? next_pow2(desc.height) : desc.height;
    for (GLenum fmt : desc.color_formats) {
        bool fl = fmt == GL_RGBA16F_ARB || fmt == GL_RGBA32F_ARB || fmt == GL_RGB16F_ARB || fmt == GL_RGB32F_ARB;
        colors_.emplace_back(tex_w_, tex_h_, fmt, GL_RGBA, fl ? GL_FLOAT : GL_UNSIGNED_BYTE, nullptr, desc.filter,
                             GL_CLAMP_TO_EDGE);
    }
    if (desc.depth == DepthAttachment::texture) {
        depth_tex_ = Texture(tex_w_, tex_h_, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr,
                             GL_NEAREST, GL_CLAMP_TO_EDGE);
        // Read raw depth, not a shadow comparison (Listing 20 samples it as a float). OpenGL ES
        // 2.0 has neither setting: its depth textures read raw depth into every channel.
        if (!current_gl_is_es()) {
            glBindTexture(GL_TEXTURE_2D, depth_tex_.id());
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE_ARB, GL_NONE);
            glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE_ARB, GL_LUMINANCE);
            glBindTexture(GL_TEXTURE_2D, 0);
        }
    }
    check_gl(("creating the textures of " + name_).c_str());
    if (!desc.use_fbo && desc.use_pbuffer) {
        // pbuffer mode: a surface of its own, at the content's size (no padding needed there).
        OffscreenSurfaces* s = offscreen_surfaces();
        if (!s) throw Error("P-buffer " + name_ + ": this context has no pbuffer surfaces (--render-target pbuffer needs --context egl)");
        surface_ = s->create_surface(desc.width, desc.height);
        return;
    }
    if (!desc.use_fbo) {
        // Copy mode: the main frame buffer is the render target; its depth buffer serves as
        // the depth attachment (a depth texture is filled by copying from it).
        return;
    }
    glGenFramebuffersEXT(1, &fbo_);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fbo_);
    // OpenGL ES 2.0 without draw buffers has one colour attachment: the target drawn is attached
    // there when it is drawn (set_draw_targets).
    const bool one_attachment = gl_state().es() && !gl_entry.DrawBuffersARB;
    for (size_t i = 0; i < (one_attachment ? std::min<size_t>(1, colors_.size()) : colors_.size()); ++i)
        glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GLenum(GL_COLOR_ATTACHMENT0_EXT + i), GL_TEXTURE_2D,
                                  colors_[i].id(), 0);
    if (desc.depth == DepthAttachment::texture) {
        glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_TEXTURE_2D, depth_tex_.id(), 0);
    } else if (desc.depth == DepthAttachment::renderbuffer || desc.depth == DepthAttachment::depth_stencil) {
        const bool ds = desc.depth == DepthAttachment::depth_stencil;
        glGenRenderbuffersEXT(1, &depth_rb_);
        glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, depth_rb_);
        glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, ds ? GL_DEPTH24_STENCIL8_EXT : GL_DEPTH_COMPONENT24, tex_w_,
                                 tex_h_);
        glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, 0);
        glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT, depth_rb_);
        if (ds)
            glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_STENCIL_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT, depth_rb_);
    }
    if (colors_.empty()) {
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
    }
    GLenum status = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE_EXT)
        throw Error("P-buffer " + name_ + " (" + std::to_string(desc.width) + "x" + std::to_string(desc.height) +
                    "): framebuffer " + framebuffer_status_name(status));
    check_gl(("creating P-buffer " + name_).c_str());
}

void PBuffer::blit_depth_to(const PBuffer& dst) const {
    if (!desc_.use_fbo || !dst.desc_.use_fbo || dst.desc_.width != desc_.width || dst.desc_.height != desc_.height)
        throw Error("P-buffer " + name_ + ": a depth blit needs two framebuffer objects of one size (to " + dst.name_ + ")");
    glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, fbo_);
    glBindFramebufferEXT(GL_DRAW_FRAMEBUFFER_EXT, dst.fbo_);
    glBlitFramebufferEXT(0, 0, desc_.width, desc_.height, 0, 0, desc_.width, desc_.height, GL_DEPTH_BUFFER_BIT,
                         GL_NEAREST);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, dst.fbo_);
}

PBuffer::~PBuffer() {
    if (depth_rb_) glDeleteRenderbuffersEXT(1, &depth_rb_);
    if (fbo_) glDeleteFramebuffersEXT(1, &fbo_);
    if (surface_ && offscreen_surfaces()) {  // a context gone first took its surfaces with it
        if (rendering_) offscreen_surfaces()->make_surface_current(nullptr);
        offscreen_surfaces()->destroy_surface(surface_);
    }
}

void PBuffer::bind_render(bool keep_contents) {
    if (textures_bound_ > 0)
        throw Error("P-buffer " + name_ + ": bind_render while it is bound as a texture (§3.2 forbids both at once)");
    if (desc_.use_fbo) glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fbo_);
    if (surface_) offscreen_surfaces()->make_surface_current(surface_);
    glViewport(0, 0, desc_.width, desc_.height);
    rendering_ = true;
    if (!desc_.use_fbo) {
        copy_target_ = colors_.empty() ? -1 : 0;
        // A pbuffer surface still holds target 0's image when target 0 was the last one drawn.
        const bool still_there = surface_ && drawn_ && last_target_ == 0;
        if (keep_contents && copy_target_ >= 0 && !still_there) {
            // The main buffer holds another buffer's image: draw ours back (fixed function,
            // 1:1 texels) before the pass blends onto it.
            const RenderState pass = gl_state().current();  // the pass's, put back after
            gl_state().apply(textured_2d(GL_REPLACE));
            glMatrixMode(GL_PROJECTION);
            glPushMatrix();
            glLoadIdentity();
            glOrtho(0, 1, 0, 1, -1, 1);
            glMatrixMode(GL_MODELVIEW);
            glPushMatrix();
            glLoadIdentity();
            glBindTexture(GL_TEXTURE_2D, colors_[0].id());
            float sx = tex_scale_x(), sy = tex_scale_y();
            glBegin(GL_QUADS);
            glTexCoord2f(0, 0); glVertex2f(0, 0);
            glTexCoord2f(sx, 0); glVertex2f(1, 0);
            glTexCoord2f(sx, sy); glVertex2f(1, 1);
            glTexCoord2f(0, sy); glVertex2f(0, 1);
            glEnd();
            glBindTexture(GL_TEXTURE_2D, 0);
            glMatrixMode(GL_PROJECTION);
            glPopMatrix();
            glMatrixMode(GL_MODELVIEW);
            glPopMatrix();
            gl_state().apply(pass);
        }
        return;
    }
    std::vector<int> all;
    for (int i = 0; i < color_targets(); ++i) all.push_back(i);
    if (!all.empty()) set_draw_targets(all);
}

void PBuffer::copy_to_textures(bool depth) {
    // Read from the buffer the pass drew into.
    GLint draw = GL_BACK;
    glGetIntegerv(GL_DRAW_BUFFER, &draw);
    glReadBuffer(GLenum(draw));
    if (copy_target_ >= 0) {
        glBindTexture(GL_TEXTURE_2D, colors_[copy_target_].id());
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, desc_.width, desc_.height);
    }
    if (depth && depth_tex_) {
        glBindTexture(GL_TEXTURE_2D, depth_tex_.id());
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, desc_.width, desc_.height);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    check_gl_stage(("copying into P-buffer " + name_).c_str());
}

void PBuffer::unbind_render() {
    if (desc_.use_fbo) {
        glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    } else if (rendering_) {
        copy_to_textures(true);
        drawn_ = true;
        last_target_ = copy_target_;
        if (surface_) offscreen_surfaces()->make_surface_current(nullptr);
    }
    rendering_ = false;
    copy_target_ = -1;
}

void PBuffer::set_draw_targets(const std::vector<int>& targets) {
    if (!desc_.use_fbo) {
        // One colour buffer: one target at a time. What was drawn for the previous target
        // is saved to its texture before the next one starts.
        if (targets.size() != 1)
            throw Error("P-buffer " + name_ + ": without framebuffer objects only one target can be drawn at a time");
        if (rendering_ && copy_target_ >= 0 && copy_target_ != targets[0]) copy_to_textures(false);
        copy_target_ = targets[0];
        return;
    }
    if (gl_state().es()) return set_es_draw_targets(targets);
    GLenum bufs[8];
    int n = 0;
    for (int t : targets) bufs[n++] = GLenum(GL_COLOR_ATTACHMENT0_EXT + t);
    if (n == 1)
        glDrawBuffer(bufs[0]);
    else
        glDrawBuffersARB(n, bufs);
}

// EXT_draw_buffers and NV_draw_buffers take target i only in place i (GL_NONE elsewhere); without
// either, the one attachment is re-pointed at the target drawn, which the shader writes as
// gl_FragData[0] (the per-target path, §3.2).
void PBuffer::set_es_draw_targets(const std::vector<int>& targets) {
    if (!gl_entry.DrawBuffersARB) {
        if (targets.size() != 1 || targets[0] >= int(colors_.size()))
            throw Error("P-buffer " + name_ + ": OpenGL ES 2.0 without EXT_draw_buffers draws one of its own targets at a time");
        glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D,
                                  colors_[size_t(targets[0])].id(), 0);
        return;
    }
    GLenum bufs[8];
    int n = 0;
    for (int t : targets) n = std::max(n, t + 1);
    for (int i = 0; i < n; ++i) bufs[i] = GL_NONE;
    for (int t : targets) bufs[t] = GLenum(GL_COLOR_ATTACHMENT0_EXT + t);
    gl_entry.DrawBuffersARB(n, bufs);
}

bool PBuffer::attach_extra(GLuint texture, bool check) {
    if (!desc_.use_fbo) throw Error("P-buffer " + name_ + ": another buffer's target needs a framebuffer object");
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fbo_);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GLenum(GL_COLOR_ATTACHMENT0_EXT + colors_.size()), GL_TEXTURE_2D,
                              texture, 0);
    const bool complete = !check || glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT) == GL_FRAMEBUFFER_COMPLETE_EXT;
    if (!rendering_) glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    return complete;
}

GLuint PBuffer::texture(int target) const {
    if (target == DEPTH) {
        if (!depth_tex_) throw Error("P-buffer " + name_ + " has no depth texture");
        return depth_tex_.id();
    }
    if (target < 0 || target >= color_targets())
        throw Error("P-buffer " + name_ + " has no colour target " + std::to_string(target));
    return colors_[target].id();
}

void PBuffer::bind_texture(int target, int unit) {
    if (rendering_)
        throw Error("P-buffer " + name_ +
                    ": bind_texture while it is the render target (§3.2: never read and written at once)");
    GLuint id = texture(target);
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, id);
    glActiveTexture(GL_TEXTURE0);
    ++textures_bound_;
}

void PBuffer::unbind_texture(int target, int unit) {
    (void)target;
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    if (textures_bound_ > 0) --textures_bound_;
}

}  // namespace dsr
