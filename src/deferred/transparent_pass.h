// Transparent surfaces (docs/forward.md): the tutorial's answer to deferred shading's "major
// limitation" (§4): "fall-back to a non deferred shading approach for transparent surfaces and
// blend them". Objects whose material has opacity < 1 are kept out of the G-buffer
// (GpuScene::ranges) and drawn here, after the opaque surfaces are in the target and its depth
// buffer holds their depth: back to front by object (transparent_order.h), each lit by the lights
// whose volume reaches its bounding sphere with lighting.glsl (the light passes' function, through
// forward.frag, ambient included), blended GL_SRC_ALPHA / GL_ONE_MINUS_SRC_ALPHA, depth tested
// against the opaque surfaces (GL_LEQUAL) and not written. Used by the deferred renderer's forward
// stage (forward_stage.h) and by the forward renderers (src/forward/), so both draw a transparent
// object the same way: it lives here, beside the scene upload and light volumes both use.
//
// What is approximate (docs/guide.md, "Transparent surfaces"): the order is per object, not per pixel;
// back faces are culled (a closed object shows its near side only), except on two-sided objects,
// whose both sides are drawn in one pass (a back face's normal flipped); transparent surfaces cast no
// shadows and get no SSAO; nothing is written to the depth buffer, so a transparent surface never
// hides another. They receive shadows: each shadowed light is a pass of its own, through
// forward.frag's SHADOW form with the light's map (glsl120/shadow.glsl, docs/shadows.md).
#pragma once
#include <string>
#include <vector>

#include "deferred/frame.h"
#include "deferred/gpu_scene.h"
#include "deferred/light_params.h"
#include "deferred/options.h"
#include "gl/program.h"
#include "scene/bounds.h"
#include "scene/scene.h"

namespace dsr {

struct TransparentStats {
    int objects = 0;             // transparent objects drawn
    int passes = 0;              // draw calls (more than one per object past max lights per pass)
    long long light_object_pairs = 0;
};

class TransparentPass {
public:
    // Compiles nothing yet: each program (normal map or not, every light type or the tutorial's
    // point lights only) is built on first use. Needs a current context with GLSL 1.20.
    TransparentPass(const std::string& shader_dir, bool listing2_literal);

    // Draws gpu's transparent objects into the bound framebuffer. Before: GL_PROJECTION holds the
    // camera's projection, gpu.set_view(camera) was called, the depth buffer holds the opaque
    // surfaces' depth. `bounds`: object_bounds(scene); `lights`: every scene light's
    // light_params (eye space) and `visible`: whether it survived frustum culling.
    // `shadows`: per scene light, its map this frame (null: none); empty for no shadowed lights.
    // `filter`: the lookup's (options.h).
    TransparentStats draw(const Scene& scene, const GpuScene& gpu, const std::vector<ObjectBounds>& bounds,
                          const std::vector<LightParams>& lights, const std::vector<char>& visible,
                          const std::vector<const ShadowLookup*>& shadows = {},
                          ShadowFilter filter = ShadowFilter::pcf2);

    int lights_per_pass() const { return batch_; }

private:
    // surface: DrawRange::surface(), the forms of shader_table.h surface_defines; metal_rough:
    // glTF's BRDF (forward.frag METAL_ROUGH_FORWARD, docs/metal_rough.md).
    Program& program(bool normal_map, bool any_light, int surface, bool metal_rough);
    // The form with one shadowed light's lookup, for maps packed or not.
    Program& shadow_program(bool normal_map, bool packed, ShadowFilter filter, int surface, bool metal_rough);

    std::string shader_dir_;
    bool listing2_literal_;
    int batch_ = 1;
    Program progs_[2][2][kSurfaceForms][2];         // [normal map][any light][surface][metal_rough]
    Program shadow_progs_[2][2][kSurfaceForms][2];  // [normal map][packed][surface][metal_rough]
    ShadowFilter shadow_filter_ = ShadowFilter::pcf2;  // what shadow_progs_ were built with
};

}  // namespace dsr
