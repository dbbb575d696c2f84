// Geometry stage (§3.3, Listings 7-13): the only stage that sees 3D geometry. A depth-only
// pre-pass fills the G-buffer's depth, then the material pass writes normal, diffuse,
// specular (and packed depth or position) for exactly the visible fragments (early Z, §3.3.1).
#pragma once
#include <map>
#include <tuple>

#include "deferred/frame.h"
#include "deferred/gpu_scene.h"
#include "deferred/render_targets.h"
#include "deferred/shader_table.h"
#include "gl/program.h"
#include "gl/state.h"

namespace dsr {

// One material program of the shader table (Listing 9's variants).
struct MaterialKey {
    bool normal_map = false;   // tangent-space normal map read (NORMAL_MAP)
    bool no_specular = false;  // specular target written as zero, no map read (NO_SPECULAR)
    int target = -1;           // -1: every target in one pass (MRT); t: only G-buffer target t
    bool operator<(const MaterialKey& o) const {
        return std::tie(normal_map, no_specular, target) < std::tie(o.normal_map, o.no_specular, o.target);
    }
};

class GeometryStage {
public:
    GeometryStage(const ShaderConfig& c, ProgramSet& programs);
    // Listing 7: the G-buffer filled with `gpu`'s opaque surfaces as the frame's camera sees them.
    void draw(const FrameDef& f, GpuScene& gpu, RenderTargets& targets);

private:
    static RenderState depth_pass_state();
    static RenderState material_pass_state();
    void draw_depth(const GpuScene& gpu);                                // Listing 8
    void draw_material(const FrameDef& f, const GpuScene& gpu, int target);  // Listings 9-13
    Program& material_program(const GpuMaterial& m, int target);

    std::map<MaterialKey, Program> programs_;
    bool mrt_, variants_;
    DepthPath depth_;
    DepthEncoding encoding_;
};

}  // namespace dsr
