// Geometry stage (§3.3, Listings 7-13): the only stage that sees 3D geometry. A depth-only
// pre-pass fills the G-buffer's depth, then the material pass writes normal, diffuse,
// specular (and packed depth or position) for exactly the visible fragments (early Z, §3.3.1).
// Where the frame's depth complexity makes the pre-pass pure cost (SkipOptions::depth_prepass,
// depth_prepass.h) it is left out and the material pass writes depth itself.
#pragma once
#include <map>
#include <tuple>

#include "deferred/ambient_fold.h"
#include "deferred/depth_prepass.h"
#include "deferred/frame.h"
#include "deferred/frame_stats.h"
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
    int surface = 0;           // DrawRange::surface(): the shader table's surface_defines
    bool operator<(const MaterialKey& o) const {
        return std::tie(normal_map, no_specular, target, surface) <
               std::tie(o.normal_map, o.no_specular, o.target, o.surface);
    }
};

class GeometryStage {
public:
    GeometryStage(const ShaderConfig& c, ProgramSet& programs);
    ~GeometryStage();
    GeometryStage(const GeometryStage&) = delete;
    GeometryStage& operator=(const GeometryStage&) = delete;
    // Listing 7: the G-buffer filled with `gpu`'s opaque surfaces as the frame's camera sees them;
    // whether the pre-pass ran, and the depth complexity that chose it, into `stats`. With `ambient`
    // (where RenderTargets::ambient_target) the material pass also leaves in P-buffer 0 what the
    // clear and the ambient pass would have, and the lighting stage draws no ambient pass.
    // `clears`: the colour targets cleared besides the normal target and the packed depth.
    void draw(const FrameDef& f, GpuScene& gpu, RenderTargets& targets, FrameStats& stats,
              const AmbientTerm* ambient = nullptr, GbufferClears clears = {});

private:
    static RenderState depth_pass_state();
    // write_depth: the material pass lays depth down itself (no pre-pass before it).
    static RenderState material_pass_state(bool write_depth);
    // The last frame's two counts into the choice (read a frame late: no wait on the GPU).
    void collect_counts();
    void draw_depth(const GpuScene& gpu);                                // Listing 8
    void draw_material(const FrameDef& f, const GpuScene& gpu, int target, bool write_depth,
                       glm::vec3 ambient);  // Listings 9-13
    // The program of a draw; a surface form's is built from its row the first time it is drawn.
    Program& material_program(const GpuMaterial& m, int target, int surface);

    std::map<MaterialKey, Program> programs_;
    ProgramSources sources_;  // the material rows, for the surface forms
    bool mrt_, variants_;
    float quantize_round_;  // quantize.glsl's fallback offset (the ambient target's diffuse rounding)
    DepthPath depth_;
    DepthEncoding encoding_;
    // The pre-pass skip: on where asked and the GL has occlusion queries to measure with.
    bool skip_prepass_;
    DepthPrepassChoice choice_;
    GLuint queries_[2] = {0, 0};  // samples passed: the pre-pass, the (first) material pass
    int pending_ = 0;             // 0: none; 1: the material pass's count; 2: both
};

}  // namespace dsr
