// GL state through one door (Doom 3's GL_State, sokol_gfx's state cache).
// Every pass states the fixed-function state it needs as a RenderState and hands it to
// GlState::apply, which touches only what differs from what it last set. No pass relies on
// what the previous one left, and no pass restores anything on its way out.
//
// Each field's default is GL's own initial value, so a RenderState{} describes a fresh
// context; a pass changes only the fields it cares about. The fixed-function matrices go through
// the same door (GlState::set_camera): each pass states its camera, none inherits one.
#pragma once
#include <glm/glm.hpp>

#include "gl/gl.h"

namespace dsr {

struct StencilFace {
    GLenum func = GL_ALWAYS;   // glStencilFuncSeparate
    GLint ref = 0;
    GLuint mask = 0xff;        // all ones of the 8-bit stencil buffer every backend asks for
    GLenum fail = GL_KEEP;     // glStencilOpSeparate: stencil fails
    GLenum zfail = GL_KEEP;    //                      stencil passes, depth fails
    GLenum zpass = GL_KEEP;    //                      both pass
    GLuint write_mask = 0xff;  // glStencilMaskSeparate
    bool operator==(const StencilFace& o) const {
        return func == o.func && ref == o.ref && mask == o.mask && fail == o.fail && zfail == o.zfail &&
               zpass == o.zpass && write_mask == o.write_mask;
    }
    bool operator!=(const StencilFace& o) const { return !(*this == o); }
};

struct RenderState {
    bool blend = false;                 // GL_BLEND off
    GLenum blend_src = GL_ONE;          // glBlendFunc(GL_ONE, GL_ZERO)
    GLenum blend_dst = GL_ZERO;
    bool depth_test = false;            // GL_DEPTH_TEST off
    GLenum depth_func = GL_LESS;        // glDepthFunc(GL_LESS); the tutorial's passes use GL_LEQUAL
    bool depth_write = true;            // glDepthMask(GL_TRUE)
    bool stencil_test = false;          // GL_STENCIL_TEST off
    StencilFace stencil_front;          // GL_ALWAYS 0 0xff, GL_KEEP x3, write mask 0xff
    StencilFace stencil_back;
    // EXT_stencil_two_side's way to the two faces (GL_STENCIL_TEST_TWO_SIDE_EXT off): the faces
    // are set through glActiveStencilFaceEXT instead of GL 2.0's glStencil*Separate.
    bool stencil_two_side_ext = false;
    bool depth_bounds_test = false;     // GL_DEPTH_BOUNDS_TEST_EXT off (the bounds are per draw: glDepthBoundsEXT)
    bool cull = false;                  // GL_CULL_FACE off
    GLenum cull_face = GL_BACK;         // glCullFace(GL_BACK)
    bool scissor = false;               // GL_SCISSOR_TEST off (the rectangle is per draw: glScissor)
    bool color_write = true;            // glColorMask(GL_TRUE x4)
    bool alpha_test = false;            // GL_ALPHA_TEST off
    GLenum alpha_func = GL_ALWAYS;      // glAlphaFunc(GL_ALWAYS, 0)
    GLfloat alpha_ref = 0;
    bool texture_2d = false;            // GL_TEXTURE_2D on unit 0 off (fixed-function texturing)
    GLenum tex_env = GL_MODULATE;       // unit 0's GL_TEXTURE_ENV_MODE
    GLuint program = 0;                 // glUseProgram(0): fixed function
    // GL_DITHER, which GL turns on by default, off: a dithering GL rounds a colour to 8 bits
    // differently at each pixel, and over many additive passes (one a light, Listing 14) the
    // per-pixel bias adds up, so the geometries that sum lights in a shader would no longer match.
    bool dither = false;
    // glPointSize(1): the tiles geometry draws its tiles as points of the tile's size (Paths::tile_points).
    GLfloat point_size = 1;

    bool operator==(const RenderState& o) const;
    bool operator!=(const RenderState& o) const { return !(*this == o); }
};

// Named starting points the passes refine.
RenderState fixed_function_2d();    // image-space pass: everything off, colour writes on
RenderState opaque_geometry();      // 3D surfaces: back faces culled, GL_LEQUAL, depth written
RenderState textured_2d(GLenum env);  // the same with unit 0 textured (GL_MODULATE / GL_REPLACE)

class GlState {
public:
    // Changes only what differs from the last applied state (everything, with the cache off
    // or after reset()). Two-sided stencil state needs GL 2.0's glStencil*Separate; on an
    // older GL only the front face is set (both faces then share it).
    void apply(const RenderState& s);
    // Binds a program inside a pass (the material pass changes program per material).
    void use_program(GLuint program);
    // The camera a pass draws with: GL_PROJECTION and GL_MODELVIEW loaded, GL_MODELVIEW left the
    // current matrix mode. Each pass states its own at its start (an image-space pass its pixel
    // ortho, a pass of 3D geometry the frame's projection), so no pass repairs what the last left.
    // Always loaded, not cached: code outside the door (the bench's floor passes, the probes)
    // loads matrices of its own, and it is two loads a pass.
    void set_camera(const glm::mat4& projection, const glm::mat4& modelview = glm::mat4(1));
    // One draw's modelview inside a pass that set its camera (an object, a light's mesh, a marker).
    void set_modelview(const glm::mat4& modelview);
    // Forgets the cache: the next apply sets every field. Call after foreign GL code (a viewer
    // overlay) and whenever a context is created or made current.
    void reset() { valid_ = es_known_ = false; }
    // What the cache believes GL holds (the last applied state).
    const RenderState& current() const { return cur_; }
    // Off: every apply sets every field, so a cache bug can be told from a pass bug. Set from
    // `--gl-state-cache off` (its default from $DSR_GL_STATE_CACHE, app/environment.h).
    void set_cache(bool on) { cache_ = on; }
    bool cache() const { return cache_; }
    // Whether the current context is OpenGL ES (docs/gles2.md), read once a context: it has no
    // fixed-function state and no matrix stack, so apply leaves the fixed-function fields alone,
    // and the camera goes to the bound program as the uniforms the GLSL ES prelude gives its
    // vertex shader (gl/glsl_dialect.h).
    bool es();
    // How many GL state calls apply made (tests: the cache must skip what is unchanged).
    long long calls() const { return calls_; }

private:
    RenderState cur_;
    bool valid_ = false;
    bool cache_ = true;
    long long calls_ = 0;
    // An extension's enable is touched only once a pass has asked for it (a GL without the
    // extension would raise GL_INVALID_ENUM on every forced apply).
    bool has_two_side_ext_ = false, has_depth_bounds_ = false;
    void upload_matrices();
    bool es_ = false, es_known_ = false;
    glm::mat4 projection_{1.0f}, modelview_{1.0f};
};

// The one GL state cache of this thread's current context.
GlState& gl_state();

// Reads every RenderState field back from GL with glGet* (tests compare it with the cache).
RenderState read_gl_state();

}  // namespace dsr
