// The depth hand-off: the G-buffer's depth onto P-buffer 0's own depth buffer, so passes drawn
// into P-buffer 0 (the volume and stencil light geometries, the depth-bounds test, the forward
// stage after the lights) can test against the scene. Sampling the G-buffer's depth texture while
// it is attached to the framebuffer being drawn would be a feedback loop, undefined in GL even
// with depth writes off, so dsr tests against a copy (docs/light_geometry.md "The depth hand-off"):
//  pass  one full-screen pass writing gl_FragDepth from the depth texture (texture path, the value
//        itself) or from the packed target (packed path, decoded, Listing 18), colour writes off;
//        the only way without framebuffer objects
//  blit  EXT_framebuffer_blit of the G-buffer's depth buffer (both framebuffer objects): the
//        G-buffer always has a 24-bit depth buffer for its pre-pass (a texture on the texture
//        path, a renderbuffer on the others), so it serves every depth path and needs no decoding
// `--depth-handoff auto|blit|pass` (Paths::depth_handoff); `--stats` ms.depth_copy is its cost.
// Where the frame's ambient term is still to be written (Paths::ambient_in_handoff), the hand-off
// is a pass (the paths allow it only where the hand-off is one) writing it too (depth_copy.frag AMBIENT).
#pragma once
#include "deferred/ambient_fold.h"
#include "deferred/frame.h"
#include "deferred/render_targets.h"
#include "deferred/shader_table.h"
#include "gl/program.h"

namespace dsr {

class DepthHandoffPass {
public:
    // Takes the table's "depth_copy" where the paths hand off by a pass.
    DepthHandoffPass(const ShaderConfig& c, ProgramSet& programs);
    // hand_off_depth: into the bound P-buffer 0, its stencil cleared too; the G-buffer's depth
    // target bound on unit 3 and its diffuse target on unit 1 (as the light passes read them).
    // ambient: also write what the clear and Listing 15's ambient pass would have left (only where
    // can_write_ambient()).
    void draw(const FrameDef& f, RenderTargets& targets, const AmbientTerm* ambient = nullptr);
    bool can_write_ambient() const { return copy_ambient_.id() != 0; }

private:
    Program copy_, copy_ambient_;
    bool blit_, stencil_;
};

}  // namespace dsr
