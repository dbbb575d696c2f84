// Which pass writes a frame's ambient term (Listing 15: the background where the G-buffer holds no
// surface, ambient x diffuse elsewhere), decided once a frame. Pure: facts in, one writer out; no
// GL, so every combination is unit-tested (tests/test_ambient_writer.cpp). DeferredShader::
// draw_lights gathers the facts, draws what the answer says, and FrameStats records the answer.
//
// Two facts are known only after the light geometry's plan (LightGeometryPass::prepare): whether
// the full-screen light takes a pass of its own (the fold) and whether the frame hands its depth
// off. So the decision comes in two steps over the same rules: ambient_before_plan says what the
// facts before the plan already settle (the ambient pass goes first, where nothing can take its
// place and the plan does not read back, so the GPU draws it while the CPU plans), and
// decide_ambient, called after the plan, says where it is written in every case.
#pragma once
#include <optional>

namespace dsr {

enum class AmbientWriter {
    material_pass,         // the material pass's ambient target (Paths::ambient_target)
    pass_before_plan,      // Listing 15's fixed-function pass, before the light geometry's plan
    pass_after_plan,       // the same pass after the plan (a read-back, a fold or a hand-off that did not come)
    light_fold,            // a full-screen light's own pass (ambient_fold.h, SkipOptions::ambient_pass)
    geometry_first_batch,  // the light geometry's first pass (paths.h draws_own_ambient: screen)
    handoff,               // the depth hand-off's pass (Paths::ambient_in_handoff)
};

// Known before the light geometry's plan.
struct AmbientFacts {
    bool material_pass = false;      // the material pass wrote it this frame
    bool ssao = false;               // SSAO scales Listing 15's pass alone: no other writer then
    bool fold_program = false;       // the light shader's fold form was built (SkipOptions::ambient_pass)
    bool geometry_draws_own = false; // draws_own_ambient of the frame's light geometry
    bool has_lights = false;         // the frame draws a light
    bool full_screen_light = false;  // ambient_fold.h full_screen_light found one
    bool handoff_program = false;    // the depth hand-off has its ambient form (DepthHandoffPass::can_write_ambient)
    bool plan_reads_back = false;    // LightGeometryPass::prepare_reads_back
    // The frame has surfaces whose ambient term holds emission or occlusion, which the G-buffer
    // cannot hold and only the material pass or Listing 15's pass with the emission pass after it
    // write (emission_pass.h): no other writer then.
    bool emission = false;
};

// Known after it.
struct PlanFacts {
    bool own_pass = false;   // the full-screen light costs the geometry a pass of its own (LightGeometryPass::own_pass)
    bool hands_off = false;  // the frame hands the scene's depth to P-buffer 0 (hands_off_depth)
};

// The writer where the facts before the plan settle it; none where it waits for the plan.
std::optional<AmbientWriter> ambient_before_plan(const AmbientFacts& a);
// The writer, from every fact; equal to ambient_before_plan(a) wherever that has one.
AmbientWriter decide_ambient(const AmbientFacts& a, const PlanFacts& p);

// Whether Listing 15's fixed-function pass may write the frame's ambient term: the one writer that
// tells a surface by the G-buffer's diffuse alpha (the shaders that may take its place read the
// normal target's alpha, which every surface writes as 1 or 0.5), so the one reader of the diffuse
// target's clear (GbufferClears). Asked before the geometry stage, where the facts after the
// culling (has_lights, full_screen_light) and the plan are not known: false only where no value of
// them makes decide_ambient answer a pass. hands_off_certain: the frame hands off whatever the plan
// (hands_off_depth with lights_need_depth false).
bool ambient_pass_possible(const AmbientFacts& a, bool hands_off_certain);

// Whether a frame hands the scene's depth off to P-buffer 0: the paths give it a depth buffer
// (Paths::accum_depth) and a later pass tests against it (the lights, the forward stage, the
// depth-bounds test).
inline bool hands_off_depth(bool accum_depth, bool lights_need_depth, bool forward_stage, bool depth_bounds) {
    return accum_depth && (lights_need_depth || forward_stage || depth_bounds);
}

const char* ambient_writer_name(AmbientWriter w);  // "material-pass", "pass-before-plan", ...

}  // namespace dsr
