// The depth hand-off (depth_handoff.h).
#include "deferred/depth_handoff.h"

#include "deferred/screen_quad.h"
#include "gl/state.h"

namespace dsr {

DepthHandoffPass::DepthHandoffPass(const ShaderConfig& c, ProgramSet& programs)
    : blit_(c.paths.depth_handoff == DepthHandoff::blit), stencil_(c.paths.accum_stencil) {
    if (!blit_) copy_ = programs.take("depth_copy");
}

void DepthHandoffPass::draw(const FrameDef& f, RenderTargets& t) {
    if (blit_) {
        RenderState s;  // no scissor (it clips a blit); depth writes on for the stencil clear below
        s.color_write = false;
        gl_state().apply(s);
        t.gbuffer().blit_depth_to(t.pbuffer(P_ACCUM));
        if (stencil_) {
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
    s.program = copy_.id();
    gl_state().apply(s);  // stencil write mask all ones (the default) for the clear
    if (stencil_) {
        glClearStencil(0);
        glClear(GL_STENCIL_BUFFER_BIT);
    }
    gl_state().set_camera(f.pixels());
    copy_.set("depth_map", 3);  // the G-buffer's depth on unit 3, as the light passes read it
    copy_.set("planes", f.planes);
    copy_.set("zrange", f.zrange);
    draw_rect(f, 0, 0, float(f.width), float(f.height), false);
}

}  // namespace dsr
