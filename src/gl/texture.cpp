#include "gl/texture.h"

#include <utility>
#include <vector>

namespace dsr {

namespace {

// OpenGL ES 2.0 takes unsized formats only, its internal format equal to the format, and converts
// nothing on upload (docs/gles2.md): a sized 8-bit format becomes its unsized one, a depth
// texture GL_DEPTH_COMPONENT (OES_depth_texture), float texels for an 8-bit texture bytes.
struct EsUpload {
    GLenum internal, format, type;
    std::vector<unsigned char> bytes;  // converted texels, where the data was float
};
EsUpload es_upload(GLenum internal, GLenum format, GLenum type, const void* data, int w, int h) {
    EsUpload u{format, format, type, {}};
    if (internal == GL_DEPTH_COMPONENT24 || internal == GL_DEPTH_COMPONENT) {
        u.internal = u.format = GL_DEPTH_COMPONENT;
        u.type = GL_UNSIGNED_INT;
        return u;
    }
    const bool eight_bit = internal == GL_RGBA8 || internal == GL_RGB8 || internal == GL_RGBA || internal == GL_RGB ||
                           internal == GL_LUMINANCE8 || internal == GL_ALPHA8;
    if (eight_bit && type == GL_FLOAT) {
        u.type = GL_UNSIGNED_BYTE;
        if (data) {
            const int comps = format == GL_RGBA ? 4 : format == GL_RGB ? 3 : 1;
            const float* f = static_cast<const float*>(data);
            u.bytes.resize(size_t(w) * h * comps);
            for (size_t i = 0; i < u.bytes.size(); ++i) {
                const float c = f[i] < 0 ? 0 : f[i] > 1 ? 1 : f[i];
                u.bytes[i] = static_cast<unsigned char>(c * 255.0f + 0.5f);
            }
        }
    }
    return u;
}

}  // namespace

Texture::Texture(int width, int height, GLenum internal_format, GLenum format, GLenum type, const void* data,
                 GLenum filter, GLenum wrap, bool mipmaps)
    : w_(width), h_(height) {
    glGenTextures(1, &id_);
    glBindTexture(GL_TEXTURE_2D, id_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (current_gl_is_es()) {
        const EsUpload u = es_upload(internal_format, format, type, data, width, height);
        glTexImage2D(GL_TEXTURE_2D, 0, GLint(u.internal), width, height, 0, u.format, u.type,
                     u.bytes.empty() ? (u.type == type ? data : nullptr) : u.bytes.data());
        if (mipmaps) glGenerateMipmap(GL_TEXTURE_2D);  // ES 2.0 core; no GL_GENERATE_MIPMAP
    } else {
        // GL_GENERATE_MIPMAP (core 1.4) rather than glGenerateMipmapEXT, which belongs to
        // EXT_framebuffer_object and is absent on the no-FBO path.
        if (mipmaps) glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
        glTexImage2D(GL_TEXTURE_2D, 0, internal_format, width, height, 0, format, type, data);
    }
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

void bind_texture_units(const GLuint* tex, int n) {
    for (int u = 0; u < n; ++u) {
        glActiveTexture(GLenum(GL_TEXTURE0 + u));
        glBindTexture(GL_TEXTURE_2D, tex[u]);
    }
}

void unbind_texture_units(int n) {
    for (int u = n - 1; u >= 0; --u) {
        glActiveTexture(GLenum(GL_TEXTURE0 + u));
        glBindTexture(GL_TEXTURE_2D, 0);
    }
}

}  // namespace dsr
