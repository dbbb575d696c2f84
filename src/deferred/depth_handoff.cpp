// The depth hand-off (depth_handoff.h).
#include "deferred/depth_handoff.h"

#include "deferred/screen_quad.h"
#include "dsr_error.h"
#include "gl/state.h"

namespace dsr {

DepthHandoffPass::DepthHandoffPass(const ShaderConfig& c, ProgramSet& programs)
    : blit_(c.paths.depth_handoff == DepthHandoff::blit), stencil_(c.paths.accum_stencil) {
    if (!blit_) copy_ = programs.take("depth_copy");
    if (programs.has("depth_copy_ambient")) copy_ambient_ = programs.take("depth_copy_ambient");
}

void DepthHandoffPass::draw(const FrameDef& f, RenderTargets& t, const AmbientTerm* ambient) {
    if (ambient && !can_write_ambient()) throw Error("depth hand-off: no program writes the ambient term here");
    if (blit_ && !ambient) {
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
    Program& prog = ambient ? copy_ambient_ : copy_;
    RenderState s;  // blending off: with the ambient term, every pixel written as the clear and the pass leave it
    s.color_write = ambient != nullptr;
    s.depth_test = true;  // GL writes depth only with the test on
    s.depth_func = GL_ALWAYS;
    s.depth_write = true;
    s.program = prog.id();
    gl_state().apply(s);  // stencil write mask all ones (the default) for the clear
    if (stencil_) {
        glClearStencil(0);
        glClear(GL_STENCIL_BUFFER_BIT);
    }
    gl_state().set_camera(f.pixels());
    prog.set("depth_map", 3);  // the G-buffer's depth on unit 3, as the light passes read it
    prog.set("planes", f.planes);
    prog.set("zrange", f.zrange);
    prog.set("uv_scale", f.uv_scale);
    if (ambient) {
        prog.set("normal_map", 0);  // the G-buffer as the light passes have it bound
        prog.set("diffuse_map", 1);
        prog.set("ambient", ambient->ambient);
        prog.set("background", ambient->background);
    }
    draw_rect(f, 0, 0, float(f.width), float(f.height), false);
}

}  // namespace dsr
