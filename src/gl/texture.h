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

// Textures tex[0..n) bound to units 0..n-1, in that order (unit n-1 left active); and units
// n-1..0 given texture 0 again (unit 0 left active): a material's maps around its draws.
void bind_texture_units(const GLuint* tex, int n);
void unbind_texture_units(int n);

}  // namespace dsr
