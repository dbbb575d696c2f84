// The forward stage after the lights (docs/forward.md): P-buffer 0 holds the lit opaque image and,
// through the depth hand-off (depth_handoff.h), the scene's depth, so geometry drawn now is hidden
// by opaque surfaces exactly as in a forward render. Two things are drawn, before post-processing
// so bloom and anti-aliasing see them:
//  * light markers (`--show-lights`): a small emissive sphere (or the scene's `markers box`) in
//    each point and spot light's colour, fixed function, depth tested and written, so bloom makes them glow as the tutorial's
//    Figure 11 highlights do;
//  * transparent surfaces (materials with opacity < 1): the tutorial's §4 "fall-back to a non
//    deferred shading approach for transparent surfaces", LearnOpenGL's "Combining deferred
//    rendering with forward rendering": transparent_pass.h.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "deferred/frame.h"
#include "deferred/frame_stats.h"
#include "deferred/gpu_scene.h"
#include "deferred/options.h"
#include "deferred/transparent_pass.h"
#include "scene/bounds.h"
#include "scene/scene.h"

namespace dsr {

class ForwardStage {
public:
    // Builds nothing yet: the marker mesh and the transparent pass's programs on first use.
    ForwardStage(const std::string& shader_dir, const ShaderOptions& opts);
    // The scene's bounds, and its transparent pass where it has transparent objects.
    void set_scene(const Scene& scene, const GpuScene& gpu);
    // Into the bound P-buffer 0, its depth handed off.
    void draw(const FrameDef& f, const Scene& scene, GpuScene& gpu, ForwardCounts& stats);

private:
    void draw_light_markers(const FrameDef& f, const Scene& scene, ForwardCounts& stats);
    std::string shader_dir_;
    bool listing2_literal_, show_lights_;
    ShadowFilter shadow_filter_;  // the transparent surfaces' shadow lookups (ShadowOptions::filter)
    std::vector<ObjectBounds> bounds_;              // object_bounds(scene)
    std::unique_ptr<TransparentPass> transparent_;  // scenes with transparent materials
    Mesh marker_mesh_;                              // the unit sphere
    Mesh marker_box_;                               // the cube of +-1 (`markers box`)
};

}  // namespace dsr
