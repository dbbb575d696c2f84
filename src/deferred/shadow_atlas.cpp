// A batch's shadow maps in one texture (shadow_atlas.h).
#include "deferred/shadow_atlas.h"

#include <string>

#include "dsr_error.h"

namespace dsr {

ShadowAtlas::ShadowAtlas(bool packed) : packed_(packed) {}

ShadowAtlas::~ShadowAtlas() {
    if (read_fbo_) glDeleteFramebuffersEXT(1, &read_fbo_);
    if (texture_) glDeleteTextures(1, &texture_);
}

void ShadowAtlas::allocate(int width, int height) {
    if (!texture_) glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    // The lookup reads single texels at their centres and weighs them itself (shadow.glsl).
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    if (packed_) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, width, height, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
    } else {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE_ARB, GL_COMPARE_R_TO_TEXTURE_ARB);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC_ARB, GL_LEQUAL);
        glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE_ARB, GL_LUMINANCE);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, width, height, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT,
                     nullptr);
    }
}

long long ShadowAtlas::update(const AtlasLayout& layout, const std::vector<const ShadowLookup*>& maps, int unit) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    if (!texture_ || layout.width != layout_.width || layout.height != layout_.height) {
        allocate(layout.width, layout.height);
        held_.clear();
    }
    glBindTexture(GL_TEXTURE_2D, texture_);
    // A region moved or resized holds nothing of use.
    if (!(layout == layout_)) {
        held_.resize(layout.regions.size());
        for (size_t k = 0; k < held_.size(); ++k)
            if (k >= layout_.regions.size() || !(layout_.regions[k] == layout.regions[k])) held_[k] = Held{};
        layout_ = layout;
    }
    long long texels = 0;
    GLint previous = 0;  // the light pass's framebuffer, bound again after the copies
    for (size_t k = 0; k < maps.size(); ++k) {
        const ShadowLookup& m = *maps[k];
        if (held_[k].texture == m.texture && held_[k].generation == m.generation && m.generation != 0) continue;
        if (texels == 0) glGetIntegerv(GL_FRAMEBUFFER_BINDING_EXT, &previous);
        if (!read_fbo_) glGenFramebuffersEXT(1, &read_fbo_);
        glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, read_fbo_);
        if (packed_) {
            glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, m.texture, 0);
            glReadBuffer(GL_COLOR_ATTACHMENT0_EXT);
        } else {
            glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_TEXTURE_2D, m.texture, 0);
            glReadBuffer(GL_NONE);
        }
        glDrawBuffer(GL_NONE);
        const GLenum status = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
        if (status != GL_FRAMEBUFFER_COMPLETE_EXT)
            throw Error("shadow atlas: a map of " + std::to_string(m.width) + "x" + std::to_string(m.height) +
                        " cannot be read through a framebuffer object");
        const AtlasRegion& r = layout.regions[k];
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, r.x, r.y, 0, 0, r.width, r.height);
        held_[k] = Held{m.texture, m.generation};
        texels += (long long)r.width * r.height;
    }
    if (texels > 0) {
        // Detach, so no map stays attached to a framebuffer object while the shadow stage draws it.
        glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, packed_ ? GL_COLOR_ATTACHMENT0_EXT : GL_DEPTH_ATTACHMENT_EXT,
                                  GL_TEXTURE_2D, 0, 0);
        glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, GLuint(previous));
    }
    glActiveTexture(GL_TEXTURE0);
    return texels;
}

}  // namespace dsr
