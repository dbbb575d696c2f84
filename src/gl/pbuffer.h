// The tutorial's pPBuffer (§3.2, Listing 6): an offscreen buffer used either as a render
// target or as a texture, never both at once. Two implementations behind one interface:
//  * fbo:  EXT_framebuffer_object with texture attachments; a pass renders straight into the
//          textures the next pass samples (render-to-texture, no copy).
//  * copy: no framebuffer objects (the pbuffer era without WGL_ARB_render_texture): the pass
//          renders into the lower-left region of the main frame buffer, and the region is
//          copied into the textures with glCopyTexSubImage2D when the target changes or the
//          buffer is unbound. The buffer must fit in the main frame buffer.
//  * pbuffer: the copy implementation on a surface of its own (gl/surfaces.h: an EGL pbuffer made
//          current with the one context), the 2005 pbuffer without render-to-texture. Its colour,
//          depth and stencil persist between binds, so a pass that blends onto the buffer needs no
//          draw-back; a multi-target buffer (the G-buffer) draws its targets one pass at a time into
//          its one surface (one depth buffer, which the depth pre-pass filled, serves every target).
// Without non-power-of-two textures the textures are padded to powers of two; the content is
// the lower-left width x height, and tex_scale() gives its extent in texture coordinates.
#pragma once
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/texture.h"

namespace dsr {

// renderbuffer: 24-bit depth; depth_stencil: one EXT_packed_depth_stencil renderbuffer on both
// the depth and the stencil attachment (the light geometries' P-buffer 0).
enum class DepthAttachment { none, texture, renderbuffer, depth_stencil };

struct PBufferDesc {
    int width = 0, height = 0;
    std::vector<GLenum> color_formats;   // one texture per colour target (GL_RGBA8 …)
    DepthAttachment depth = DepthAttachment::none;
    GLenum filter = GL_NEAREST;          // G-buffer reads are 1:1 (§3): nearest
    bool use_fbo = true;                 // false: the copy implementation
    bool use_pbuffer = false;            // with use_fbo false: copy from a surface of its own
    bool pow2 = false;                   // pad textures to powers of two
};

int next_pow2(int v);

class PBuffer {
public:
    static constexpr int DEPTH = -1;  // target index of the depth texture

    PBuffer(std::string name, const PBufferDesc& desc);
    ~PBuffer();
    PBuffer(const PBuffer&) = delete;
    PBuffer& operator=(const PBuffer&) = delete;

    // Render target: binds the framebuffer, sets the viewport, enables all colour targets
    // (ARB_draw_buffers). Fails loudly if any of its textures is bound for reading.
    // keep_contents: start from the buffer's current image (a pass that blends onto it). The
    // fbo implementation always keeps it; the copy one draws the texture back first.
    void bind_render(bool keep_contents = false);
    void unbind_render();
    // Writes only these colour targets (one target: a single-target pass; all: MRT).
    void set_draw_targets(const std::vector<int>& targets);
    // fbo implementation: attaches another buffer's texture of this buffer's size as colour target
    // color_targets() (set_draw_targets may then name it), or detaches it with 0; with `check`,
    // whether the framebuffer is complete with it (a status query: done once, not every frame).
    // Keeps this buffer bound where it is the render target.
    bool attach_extra(GLuint texture, bool check = false);
    // Texture: binds target (colour index or DEPTH) on `unit`. Fails loudly while rendering.
    void bind_texture(int target, int unit);
    void unbind_texture(int target, int unit);

    // Copies this buffer's depth into `dst`'s depth buffer with EXT_framebuffer_blit (both fbo
    // implementation, same size, both with a depth attachment of the same depth bits), then
    // binds `dst` for drawing again: what the depth hand-off does while dst is the render target.
    // The caller checks Caps::framebuffer_blit; the scissor test must be off (it clips blits).
    void blit_depth_to(const PBuffer& dst) const;

    GLuint texture(int target) const;
    int width() const { return desc_.width; }
    int height() const { return desc_.height; }
    int color_targets() const { return static_cast<int>(colors_.size()); }
    int texture_width() const { return tex_w_; }
    int texture_height() const { return tex_h_; }
    // Content extent in texture coordinates: (1,1) unless padded to powers of two.
    float tex_scale_x() const { return float(desc_.width) / float(tex_w_); }
    float tex_scale_y() const { return float(desc_.height) / float(tex_h_); }
    bool uses_fbo() const { return desc_.use_fbo; }
    bool is_rendering() const { return rendering_; }
    const std::string& name() const { return name_; }

private:
    void copy_to_textures(bool depth);
    void set_es_draw_targets(const std::vector<int>& targets);  // OpenGL ES 2.0's draw buffers
    std::string name_;
    PBufferDesc desc_;
    int tex_w_ = 0, tex_h_ = 0;
    int copy_target_ = -1;  // copy mode: the colour target the main buffer currently holds
    GLuint fbo_ = 0, depth_rb_ = 0;
    void* surface_ = nullptr;  // pbuffer implementation: its offscreen surface
    bool drawn_ = false;       // pbuffer: the surface holds an image of ours (keep_contents needs no draw-back)
    int last_target_ = -1;     // pbuffer: the target the surface held when last unbound
    std::vector<Texture> colors_;
    Texture depth_tex_;
    bool rendering_ = false;
    int textures_bound_ = 0;
};

}  // namespace dsr
