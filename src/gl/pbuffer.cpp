#include "gl/pbuffer.h"

#include "dsr_error.h"
#include "gl/check.h"

namespace dsr {

PBuffer::PBuffer(std::string name, const PBufferDesc& desc) : name_(std::move(name)), desc_(desc) {
    glGenFramebuffersEXT(1, &fbo_);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fbo_);
    for (size_t i = 0; i < desc.color_formats.size(); ++i) {
        GLenum fmt = desc.color_formats[i];
        bool fl = fmt == GL_RGBA16F_ARB || fmt == GL_RGBA32F_ARB || fmt == GL_RGB16F_ARB || fmt == GL_RGB32F_ARB;
        colors_.emplace_back(desc.width, desc.height, fmt, GL_RGBA, fl ? GL_FLOAT : GL_UNSIGNED_BYTE, nullptr,
                             desc.filter, GL_CLAMP_TO_EDGE);
        glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GLenum(GL_COLOR_ATTACHMENT0_EXT + i), GL_TEXTURE_2D,
                                  colors_.back().id(), 0);
    }
    if (desc.depth == DepthAttachment::texture) {
        depth_tex_ = Texture(desc.width, desc.height, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT,
                             nullptr, GL_NEAREST, GL_CLAMP_TO_EDGE);
        glBindTexture(GL_TEXTURE_2D, depth_tex_.id());
        // Read raw depth, not a shadow comparison (Listing 20 samples it as a float).
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE_ARB, GL_NONE);
        glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE_ARB, GL_LUMINANCE);
        glBindTexture(GL_TEXTURE_2D, 0);
        glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_TEXTURE_2D, depth_tex_.id(), 0);
    } else if (desc.depth == DepthAttachment::renderbuffer) {
        glGenRenderbuffersEXT(1, &depth_rb_);
        glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, depth_rb_);
        glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, desc.width, desc.height);
        glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, 0);
        glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT, depth_rb_);
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

PBuffer::~PBuffer() {
    if (depth_rb_) glDeleteRenderbuffersEXT(1, &depth_rb_);
    if (fbo_) glDeleteFramebuffersEXT(1, &fbo_);
}

void PBuffer::bind_render() {
    if (textures_bound_ > 0)
        throw Error("P-buffer " + name_ + ": bind_render while it is bound as a texture (§3.2 forbids both at once)");
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fbo_);
    glViewport(0, 0, desc_.width, desc_.height);
    rendering_ = true;
    std::vector<int> all;
    for (int i = 0; i < color_targets(); ++i) all.push_back(i);
    if (!all.empty()) set_draw_targets(all);
}

void PBuffer::unbind_render() {
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    rendering_ = false;
}

void PBuffer::set_draw_targets(const std::vector<int>& targets) {
    GLenum bufs[8];
    int n = 0;
    for (int t : targets) bufs[n++] = GLenum(GL_COLOR_ATTACHMENT0_EXT + t);
    if (n == 1)
        glDrawBuffer(bufs[0]);
    else
        glDrawBuffersARB(n, bufs);
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
