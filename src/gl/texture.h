// RAII GL texture name (2D only: everything the tutorial samples is 2D).
#pragma once
#include <utility>

#include "gl/gl.h"

namespace dsr {

class Texture {
public:
    Texture() = default;
    // Allocates width x height with `internal_format`; `data` may be null.
    Texture(int width, int height, GLenum internal_format, GLenum format, GLenum type, const void* data,
            GLenum filter = GL_NEAREST, GLenum wrap = GL_CLAMP_TO_EDGE, bool mipmaps = false);
    ~Texture();
    Texture(Texture&& o) noexcept { *this = std::move(o); }
    Texture& operator=(Texture&& o) noexcept;
    Texture(const Texture&) = delete;
    Texture& operator=(const Texture&) = delete;

    GLuint id() const { return id_; }
    int width() const { return w_; }
    int height() const { return h_; }
    explicit operator bool() const { return id_ != 0; }

private:
    GLuint id_ = 0;
    int w_ = 0, h_ = 0;
};

}  // namespace dsr
