// The shadow stage: before the light passes, a map for every visible shadowed light of the frame
// (LightDraw::shadow), drawn from the light with only the objects inside each of its views
// (shadow_math.h: the layouts, the culling). Its result is the frame's ShadowLookup list, which
// DeferredShader puts into the FrameDef the light stage reads: nothing of this stage is read by
// another. Maps are kept per light between frames and drawn again only when the light's layout or
// what lies in its views changed (the viewer's still frames reuse them).
//   depth-texture path  a depth texture (ARB_depth_texture) compared by ARB_shadow in the lookup
//   packed path         depth packed into RGB8 by the G-buffer's codec (depth_codec.glsl
//                       pack_depth), a depth renderbuffer for the test; compared in the shader
// Without EXT_framebuffer_object each map is drawn into the main frame buffer, in pieces where it
// is larger than the frame, and copied into its texture (main_buffer_map.h); the packed path
// there where the main frame buffer's depth has fewer than 24 bits (map_pieces.h maps_packed).
// Point lights (and spots wider than kSpotCubeAngle) draw six faces into one 2D texture, 3 x 2:
// GL 2.x cannot attach a cube map face of depth, and one layout serves both paths.
#pragma once
#include <map>
#include <vector>

#include <glm/glm.hpp>

#include "deferred/frame.h"
#include "deferred/frame_stats.h"
#include "deferred/shader_table.h"
#include "deferred/shadow_math.h"
#include "gl/program.h"
#include "scene/image.h"

namespace dsr {

class GpuScene;

class ShadowStage {
public:
    // Framebuffer objects where the GL has them (c.caps.fbo), else the main frame buffer.
    ShadowStage(const ShaderConfig& c, ProgramSet& programs);
    ~ShadowStage();
    ShadowStage(const ShadowStage&) = delete;
    ShadowStage& operator=(const ShadowStage&) = delete;
    // The scene's object bounds for the culling; forgets every map.
    void set_scene(const Scene& scene);
    // The maps of f's shadowed lights (f.shadowed_lights of them, in LightDraw::shadow order),
    // drawn or reused; counts maps and triangles into stats.
    std::vector<ShadowLookup> draw(const FrameDef& f, const Scene& scene, GpuScene& gpu, ShadowCounts& stats);
    // A map as grey, white far: the texture's texels (row 0 at the bottom), for --view shadow-map.
    Image read_map(const ShadowLookup& m) const;
    bool packed() const { return packed_; }
    // The first map of the last draw (--view shadow-map); null when it had none.
    const ShadowLookup* last_first() const { return last_.empty() ? nullptr : &last_[0]; }

private:
    struct Map {
        GLuint texture = 0, fbo = 0, depth_rb = 0;  // fbo, depth_rb: 0 in the main frame buffer
        int width = 0, height = 0;
        // What it was drawn with: each view's clip matrix and the objects drawn into it.
        std::vector<glm::dmat4> clips;
        std::vector<std::vector<size_t>> objects;
        std::vector<glm::dmat4> models;  // of those objects, in their order
        unsigned generation = 0;         // ShadowLookup::generation of its last drawing
    };
    void allocate(Map& m, int width, int height);
    void release(Map& m);

    // The caster for a cut-out surface (CUT_OUT, VERTEX_COLOR with its colours), built from the
    // table's row the first time one is drawn, bound with its material's diffuse map on unit 0.
    Program& cut_out_caster(bool colors);

    Program caster_;
    ProgramSources sources_;       // the caster's row, for the cut-out forms
    Program cut_out_casters_[2];   // [vertex colours]
    bool packed_ = false;
    bool main_buffer_ = false;  // no framebuffer objects: drawn in the main frame buffer and copied
    bool hard_ = false;
    bool reuse_ = true;  // ShadowOptions::reuse
    int max_texture_ = 0;
    std::vector<ObjectBounds> bounds_;
    std::map<size_t, Map> maps_;  // by the light's index in Scene::lights
    std::vector<ShadowLookup> last_;  // the last draw's, for the view
};

}  // namespace dsr
