#include "gl/texture.h"

#include <utility>

namespace dsr {

Texture::Texture(int width, int height, GLenum internal_format, GLenum format, GLenum type, const void* data,
                 GLenum filter, GLenum wrap, bool mipmaps)
    : w_(width), h_(height) {
    glGenTextures(1, &id_);
    glBindTexture(GL_TEXTURE_2D, id_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // GL_GENERATE_MIPMAP (core 1.4) rather than glGenerateMipmapEXT, which belongs to
    // EXT_framebuffer_object and is absent on the no-FBO path.
    if (mipmaps) glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, internal_format, width, height, 0, format, type, data);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                    mipmaps ? GL_LINEAR_MIPMAP_LINEAR : static_cast<GLint>(filter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
    glBindTexture(GL_TEXTURE_2D, 0);
}

Texture::~Texture() {
    if (id_) glDeleteTextures(1, &id_);
}

Texture& Texture::operator=(Texture&& o) noexcept {
    if (this != &o) {
        if (id_) glDeleteTextures(1, &id_);
        id_ = std::exchange(o.id_, 0);
        w_ = o.w_;
        h_ = o.h_;
    }
    return *this;
}

}  // namespace dsr
