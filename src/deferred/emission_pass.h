// The emission pass: where Listing 15's pass writes the ambient term of a frame with
// metallic-roughness surfaces that emit light or carry an occlusion map, it adds what the G-buffer
// cannot hold (docs/metal_rough.md, "Where the ambient, occlusion and emission go"). The opaque
// surfaces of those materials are drawn once more through the G-buffer's depth, with P-buffer 0 as
// the G-buffer framebuffer's render target (RenderTargets::mrt_attach_accum), as the passes without
// MRT draw each target after the first (§3.2): only the visible fragments pass GL_LEQUAL. Each
// writes (emission, occlusion), blended as emission + P-buffer 0 x occlusion, so P-buffer 0 holds
// ambient x base x occlusion (x SSAO's factor) + emission, what the material pass's ambient target
// writes. ambient_writer.h keeps every other writer of the term out of such frames (AmbientFacts::emission).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "deferred/frame.h"
#include "deferred/gpu_scene.h"
#include "deferred/render_targets.h"
#include "deferred/shader_table.h"
#include "scene/scene.h"

namespace dsr {

// Whether a material's ambient term holds more than ambient x base colour: a metallic-roughness
// material with an emissive colour or an occlusion map that counts (strength above 0).
bool adds_to_ambient(const Material& m);

class EmissionPass {
public:
    // The draws of `gpu` (scene's materials) the pass redraws; none where no material adds to
    // the ambient term.
    EmissionPass(const std::string& shader_dir, const Scene& scene, const GpuScene& gpu);
    // The frame has surfaces whose ambient term only this pass (or the material pass) carries.
    bool needed() const { return !ranges_.empty(); }
    // Into P-buffer 0 through the G-buffer's depth; after Listing 15's pass (and SSAO's scaling of
    // it), before the lights. Needs RenderTargets::accum_attachable. Leaves no framebuffer bound.
    void draw(const FrameDef& f, GpuScene& gpu, RenderTargets& t);

private:
    Program& program(int surface);
    ProgramSources sources_;
    std::vector<DrawRange> ranges_;
    std::map<int, Program> programs_;  // by surface bits (gpu_scene.h), built on first use
};

}  // namespace dsr
