// The depth hand-off: the G-buffer's depth onto P-buffer 0's own depth buffer, so passes drawn
// into P-buffer 0 (the volume and stencil light geometries, the depth-bounds test, a forward pass
// after the lights) can test against the scene. Sampling the G-buffer's depth texture while it is
// attached to the framebuffer being drawn would be a feedback loop even with depth writes off
// (TRAPS "Feedback loop"), so dsr tests against a copy: one full-screen pass writing gl_FragDepth
// from the depth texture (texture path, the value itself) or from the packed target (packed path,
// decoded, Listing 18), colour writes off. The same pass serves both paths and the copy path
// without framebuffer objects; EXT_framebuffer_blit could copy the texture path's depth but not
// decode the packed one.
// Issue 13: where EXT_framebuffer_blit exists (and both are framebuffer objects) the hand-off is a
// blit of the G-buffer's depth buffer instead (`--depth-handoff auto|blit|pass`, Paths::
// depth_handoff): the G-buffer always has a 24-bit depth buffer for its pre-pass (a texture on the
// texture path, a renderbuffer on the others), so the blit serves every depth path and needs no
// decoding; P-buffer 0's depth has the same 24 depth bits. `--stats` ms.depth_copy is its cost,
// either way.
#include "deferred/deferred_shader.h"
#include "gl/state.h"

namespace dsr {

void DeferredShader::hand_off_depth() {
    if (paths_.depth_handoff == DepthHandoff::blit) {
        RenderState s;  // no scissor (it clips a blit); depth writes on for the stencil clear below
        s.color_write = false;
        gl_state().apply(s);
        gbuf().blit_depth_to(pbuf(P_ACCUM));
        if (paths_.accum_stencil) {
            glClearStencil(0);
            glClear(GL_STENCIL_BUFFER_BIT);
        }
        return;
    }
    RenderState s;
    s.color_write = false;
    s.depth_test = true;  // GL writes depth only with the test on
    s.depth_func = GL_ALWAYS;
    s.depth_write = true;
    s.program = depth_copy_prog_.id();
    gl_state().apply(s);  // stencil write mask all ones (the default) for the clear
    if (paths_.accum_stencil) {
        glClearStencil(0);
        glClear(GL_STENCIL_BUFFER_BIT);
    }
    depth_copy_prog_.set("depth_map", 3);  // the G-buffer's depth on unit 3, as the light passes read it
    depth_copy_prog_.set("planes", planes_);
    depth_copy_prog_.set("zrange", zrange_);
    draw_rect(0, 0, float(w_), float(h_), false);
}

}  // namespace dsr
