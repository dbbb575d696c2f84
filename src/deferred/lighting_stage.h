// Lighting stage (§3.4, Listings 14-20): image space, into P-buffer 0. A fixed-function ambient
// pass (Listing 15, Eq. 6, scaled by SSAO when it is on), the depth hand-off where a later pass
// tests against the scene's depth, then every visible light of the frame added by the light
// geometry the options ask for (light_geometry.h). Where a light covers the whole screen, the
// ambient pass may be folded into that light's pass (ambient_fold.h, SkipOptions::ambient_pass). Also the light pass's arithmetic written out as
// positions, for the accuracy measurements (reconstructed_positions).
#pragma once
#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "deferred/ambient_fold.h"
#include "deferred/depth_handoff.h"
#include "deferred/frame.h"
#include "deferred/frame_stats.h"
#include "deferred/light_geometry.h"
#include "deferred/render_targets.h"
#include "deferred/shader_table.h"
#include "gl/pbuffer.h"
#include "gl/program.h"
#include "scene/image.h"
#include "scene/scene.h"

namespace dsr {

class LightPrograms;
class SsaoStage;

// The ambient pass folded into the pass of f.lights[light], a full-screen light: the colours the
// clear and Listing 15 would have used.
struct AmbientFold {
    size_t light = 0;        // the full-screen light whose pass takes the ambient pass's place
    bool by_geometry = false;  // instead, the light geometry's first pass (paths.h draws_own_ambient)
    AmbientTerm colours;
};

class LightingStage {
public:
    LightingStage(const ShaderConfig& c, ProgramSet& programs, int width, int height);
    ~LightingStage();
    void resize(int width, int height);
    // The depth hand-off again, for paths chosen again (DeferredShader::set_scene).
    void set_handoff(const ShaderConfig& c, ProgramSet& programs);
    // Counting (LightCounts fragments, invocations): two queries around every light
    // draw. On by default; the bench turns it off for its timed frames (on a GPU at 1024 lights the
    // queries were most of the CPU's frame) and counts in one more frame after them.
    void set_counting(bool on) { counting_ = on; }

    // Listing 15, with the background kept: P-buffer 0 (bound) starts as the background colour and
    // the alpha test keeps it where the G-buffer holds no surface (diffuse alpha 0). `ssao`: the
    // AO buffer it is multiplied by, or null.
    void draw_ambient(const FrameDef& f, const Scene& scene, RenderTargets& targets, const SsaoStage* ssao);
    // Before the depth hand-off (the ambient pass before or after it: ambient_writer.h), with the
    // G-buffer bound as textures and P-buffer 0 for rendering: the light geometry's plan for the
    // frame's lights (LightGeometryPass::prepare); whether its lights need the scene's depth in
    // P-buffer 0.
    bool prepare(const FrameDef& f, RenderTargets& targets, FrameStats& stats) {
        return geometry_->prepare(f, targets, stats);
    }
    // Whether prepare() may read back from the GL (LightGeometryPass::prepare_reads_back).
    bool prepare_reads_back(const FrameDef& f) const { return geometry_->prepare_reads_back(f); }
    // The facts the ambient decision (ambient_writer.h) takes from this stage: the light shader's
    // fold form built (the ambient skip on, SSAO off), the geometry's first pass writing the
    // ambient itself (paths.h draws_own_ambient: screen, as LearnOpenGL's lighting pass does), the
    // hand-off's ambient form built.
    bool fold_built() const { return fold_ != nullptr; }
    bool geometry_writes_ambient() const { return draws_own_ambient_; }
    bool handoff_writes_ambient() const { return handoff_ && handoff_->can_write_ambient(); }
    // After prepare(f): whether f.lights[i], drawn over the whole screen, costs the geometry a pass
    // of its own (LightGeometryPass::own_pass), and, where the fold draws it, leaving it out of the
    // geometry's plan (LightGeometryPass::drop).
    bool own_pass(size_t i) const { return geometry_->own_pass(i); }
    void drop(size_t i) { geometry_->drop(i); }
    // hand_off_depth (depth_handoff.h), with the G-buffer bound as textures; with `ambient`, the
    // hand-off's pass also writes the ambient term (only where handoff_writes_ambient()).
    void hand_off_depth(const FrameDef& f, RenderTargets& targets, const AmbientTerm* ambient = nullptr);
    // Listing 17: the frame's visible lights added into P-buffer 0, with the G-buffer bound as
    // textures (units 0-3); counted when counting is on and the GL can. With `fold`, that light
    // first, writing every pixel with the ambient pass folded in; then `lights` (f, or f without
    // the folded light) by the light geometry.
    void draw_lighting(const FrameDef& f, const FrameDef& lights, RenderTargets& targets, FrameStats& stats,
                       const AmbientFold* fold = nullptr);
    // After the geometry stage: the eye-space position each pixel's depth reconstructs to, exactly
    // as the light pass computes it (same decoder, planes and view rays), in float: rgb = (x, y, z),
    // alpha 1 where the G-buffer has a surface, 0 elsewhere. Throws without float targets.
    Image reconstructed_positions(const FrameDef& f, RenderTargets& targets);

private:
    bool count_samples_, count_invocations_;
    bool counting_ = true;
    int depth_target_;
    bool pow2_;
    bool draws_own_ambient_;  // paths.h draws_own_ambient of the frame's geometry
    std::unique_ptr<LightGeometryPass> geometry_;
    std::unique_ptr<DepthHandoffPass> handoff_;  // where Paths::accum_depth
    void draw_fold(const FrameDef& f, const AmbientFold& fold, LightQueries& q);
    std::unique_ptr<LightPrograms> fold_;        // light_fold's three forms: the ambient skip on, SSAO off
    float fold_round_ = 0.5f;                    // ShaderConfig::tile_round: quantize.glsl's fallback
    Program position_prog_;                      // where the table built it
    std::unique_ptr<PBuffer> position_buf_;      // on first use
};

}  // namespace dsr
