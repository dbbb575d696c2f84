// SSAO stage (Vasilovici §5; docs/ssao.md): ambient occlusion from the G-buffer's depth and
// normals in a pass of its own, then a depth-aware blur, both into the SSAO buffers
// (render_targets.h) at 1/ssao.scale of the frame. Unlike Vasilovici, who writes it into the final
// target's alpha after the light pass, it scales the ambient pass only (Listing 15, Eq. 6): lights
// stay as the tutorial adds them. With --ssao off the stage does not exist and the ambient pass is
// the tutorial's.
#pragma once
#include "deferred/frame.h"
#include "deferred/render_targets.h"
#include "deferred/shader_table.h"
#include "gl/program.h"

namespace dsr {

class SsaoStage {
public:
    SsaoStage(const ShaderConfig& c, ProgramSet& programs);
    // Occlusion from the G-buffer into the AO buffer, then the blur into the blurred AO buffer.
    // After the geometry stage.
    void draw(const FrameDef& f, RenderTargets& targets);
    // Inside the ambient pass, P-buffer 0 bound: Eq. 6's ambient term times ao, fixed function,
    // before any light adds.
    void modulate_ambient(const FrameDef& f, RenderTargets& targets) const;

private:
    void begin_pass(const FrameDef& f, PBuffer& target, Program& prog) const;
    SsaoOptions o_;
    int depth_target_;
    Program occlusion_, blur_;
};

}  // namespace dsr
