// The depth hand-off: the G-buffer's depth onto P-buffer 0's own depth buffer, so passes drawn
// into P-buffer 0 (the volume and stencil light geometries, the depth-bounds test, a forward pass
// after the lights) can test against the scene. Sampling the G-buffer's depth texture while it is
// attached to the framebuffer being drawn would be a feedback loop even with depth writes off
// (TRAPS "Feedback loop"), so dsr tests against a copy: one full-screen pass writing gl_FragDepth
// from the depth texture (texture path, the value itself) or from the packed target (packed path,
// decoded, Listing 18), colour writes off. The same pass serves both paths and the copy path
// without framebuffer objects; EXT_framebuffer_blit could copy the texture path's depth but not
// decode the packed one. `--stats` ms.depth_copy is its cost.
#include "deferred/deferred_shader.h"
#include "gl/state.h"

namespace dsr {

void DeferredShader::hand_off_depth() {
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
