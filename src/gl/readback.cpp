#include "gl/readback.h"

#include <vector>

#include "dsr_error.h"
#include "gl/check.h"
#include "gl/gl.h"
#include "gl/state.h"

namespace dsr {

namespace {

// w x h RGBA8 pixels, rows `stride` pixels apart, as an Image of k / 255 values: what both the
// frame buffer's and an RGBA8 texture's read-backs hold.
Image image_of_rgba8(const std::vector<unsigned char>& px, int w, int h, int stride) {
    Image img;
    img.width = w;
    img.height = h;
    img.rgba.resize(size_t(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (size_t i = 0; i < size_t(w) * 4; ++i) img.rgba[size_t(y) * w * 4 + i] = px[size_t(y) * stride * 4 + i] / 255.0f;
    return img;
}

// OpenGL ES 2.0 has no glGetTexImage: an RGBA8 texture is read through a framebuffer object of
// its own with glReadPixels (docs/gles2.md).
std::vector<unsigned char> es_read_rgba8(GLuint tex, int tw, int th) {
    std::vector<unsigned char> all(size_t(tw) * th * 4);
    GLint bound = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING_EXT, &bound);
    GLuint fbo = 0;
    glGenFramebuffersEXT(1, &fbo);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fbo);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, tex, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, tw, th, GL_RGBA, GL_UNSIGNED_BYTE, all.data());
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, GLuint(bound));
    glDeleteFramebuffersEXT(1, &fbo);
    return all;
}

}  // namespace

Image read_pixels(int width, int height) {
    std::vector<unsigned char> px(size_t(width) * height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
    check_gl("reading the main frame buffer");
    return image_of_rgba8(px, width, height, width);
}

Image read_texture(GLuint tex, int w, int h, int tw, int th, bool depth) {
    if (gl_state().es()) {
        if (depth) throw Error("reading a depth texture back: OpenGL ES 2.0 reads no depth texture (no glGetTexImage)");
        return read_texture_rgba8(tex, w, h, tw, th);
    }
    Image img;
    img.width = w;
    img.height = h;
    img.rgba.assign(size_t(w) * h * 4, 1.0f);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    std::vector<float> all(size_t(tw) * th * (depth ? 1 : 4));
    glGetTexImage(GL_TEXTURE_2D, 0, depth ? GL_DEPTH_COMPONENT : GL_RGBA, GL_FLOAT, all.data());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* q = img.at(x, y);
            if (depth) {
                q[0] = q[1] = q[2] = all[size_t(y) * tw + x];
            } else {
                const float* p = &all[(size_t(y) * tw + x) * 4];
                for (int c = 0; c < 4; ++c) q[c] = p[c];
            }
        }
    glBindTexture(GL_TEXTURE_2D, 0);
    check_gl("reading a buffer back");
    return img;
}

Image read_texture_rgba8(GLuint tex, int w, int h, int tw, int th) {
    if (gl_state().es()) {
        const std::vector<unsigned char> px = es_read_rgba8(tex, tw, th);
        check_gl("reading a buffer back");
        return image_of_rgba8(px, w, h, tw);
    }
    std::vector<unsigned char> all(size_t(tw) * th * 4);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, all.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    check_gl("reading a buffer back");
    return image_of_rgba8(all, w, h, tw);
}

std::vector<uint32_t> read_depth_codes(GLuint tex, int w, int h, int tw, int th) {
    std::vector<GLuint> all(size_t(tw) * th);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, all.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    check_gl("reading a depth texture back");
    std::vector<uint32_t> out(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) out[size_t(y) * w + x] = all[size_t(y) * tw + x];
    return out;
}

}  // namespace dsr
