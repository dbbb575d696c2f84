// The tutorial's pPBuffer (§3.2, Listing 6): an offscreen buffer used either as a render
// target or as a texture, never both at once. Built on EXT_framebuffer_object with texture
// attachments, so a pass renders straight into the textures the next pass samples.
#pragma once
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/texture.h"

namespace dsr {

enum class DepthAttachment { none, texture, renderbuffer };

struct PBufferDesc {
    int width = 0, height = 0;
    std::vector<GLenum> color_formats;   // one texture per colour target (GL_RGBA8 …)
    DepthAttachment depth = DepthAttachment::none;
    GLenum filter = GL_NEAREST;          // G-buffer reads are 1:1 (§3): nearest
};

class PBuffer {
public:
    static constexpr int DEPTH = -1;  // target index of the depth texture

    PBuffer(std::string name, const PBufferDesc& desc);
    ~PBuffer();
    PBuffer(const PBuffer&) = delete;
    PBuffer& operator=(const PBuffer&) = delete;

    // Render target: binds the framebuffer, sets the viewport, enables all colour targets
    // (ARB_draw_buffers). Fails loudly if any of its textures is bound for reading.
    void bind_render();
    void unbind_render();
    // Writes only these colour targets (one target: a single-target pass; all: MRT).
    void set_draw_targets(const std::vector<int>& targets);
    // Texture: binds target (colour index or DEPTH) on `unit`. Fails loudly while rendering.
    void bind_texture(int target, int unit);
    void unbind_texture(int target, int unit);

    GLuint texture(int target) const;
    int width() const { return desc_.width; }
    int height() const { return desc_.height; }
    int color_targets() const { return static_cast<int>(colors_.size()); }
    bool is_rendering() const { return rendering_; }
    const std::string& name() const { return name_; }

private:
    std::string name_;
    PBufferDesc desc_;
    GLuint fbo_ = 0, depth_rb_ = 0;
    std::vector<Texture> colors_;
    Texture depth_tex_;
    bool rendering_ = false;
    int textures_bound_ = 0;
};

}  // namespace dsr
