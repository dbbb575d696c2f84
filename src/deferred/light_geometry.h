// How each visible light reaches its pixels (`--light-geometry`, docs/light_geometry.md): one
// class per geometry, each in its own file, behind this interface.
//   quad     light_geometry_quad.cpp     the tutorial's scissored screen-aligned quad (§3.4.2)
//   volume   light_geometry_volume.cpp   the back faces of the light's volume mesh
//   stencil  light_geometry_stencil.cpp  the volume masked by a stencil pass
//   tiles    light_geometry_tiles.cpp    screen tiles, several lights a pass (§3.4.3's closing remark)
//   screen   light_geometry_screen.cpp   every light at every pixel (LearnOpenGL's demo, for comparison)
//   auto     light_geometry_auto.cpp     each light by the cheapest of quad, volume and tiles
// A geometry draws; whether the frame is counted, and how long it took, is decided outside it
// (LightingStage::draw_lighting, DeferredShader's timer). A fifth geometry is a new file, a line
// in make_light_geometry and its name in the options (options.h, option_table.cpp), with the rows
// of any program of its own in shader_table.cpp (docs/architecture.md has the recipe).
#pragma once
#include <cstddef>
#include <memory>

#include "deferred/ambient_fold.h"
#include "deferred/frame.h"
#include "deferred/frame_stats.h"
#include "deferred/light_queries.h"
#include "deferred/render_targets.h"
#include "deferred/shader_table.h"

namespace dsr {

class LightGeometryPass {
public:
    virtual ~LightGeometryPass() = default;
    // Adds every light of f.lights into P-buffer 0, which is bound for rendering, with the
    // G-buffer's normal, diffuse, specular and depth targets on units 0-3 and, where the paths
    // need it (Paths::accum_depth), the scene's depth handed to its depth buffer. Each draw of the
    // light shader sits between q.begin() and q.end(); the passes go into stats (lights.passes,
    // lights.as_quads, the tiles' plan). States every piece of GL state it needs, camera included.
    virtual void draw(const FrameDef& f, RenderTargets& targets, LightQueries& q, FrameStats& stats) = 0;
    // Once a frame before the depth hand-off, with the G-buffer bound as textures (units 0-3) and
    // P-buffer 0 for rendering: whether this frame's lights need the scene's depth in P-buffer 0
    // (where Paths::accum_depth gives it one). The auto geometry makes its plan for f here.
    virtual bool prepare(const FrameDef& f, RenderTargets& targets, FrameStats& stats) { return true; }
    // Whether prepare(f) may read back from the GL (the tiles' depth spans): a read-back waits for
    // every command before it, so the frame's ambient pass is then drawn after prepare(), where
    // the GPU draws it while the CPU plans the light draws, instead of before it, where the
    // read-back would wait for it too (DeferredShader::draw_lights).
    virtual bool prepare_reads_back(const FrameDef& f) const { return false; }
    // After prepare(f): whether f.lights[i], a light over the whole screen, costs this geometry a
    // pass of its own, so that folding the ambient pass into that pass saves the ambient pass
    // (quad, volume, stencil). Where the light would be one more in a batch (tiles, screen), the
    // fold's pass is a pass added, dearer than the ambient pass it saves: false (docs/guide.md has
    // the figures).
    virtual bool own_pass(size_t i) const { return true; }
    // The fold draws f.lights[i] (own_pass(i) was true): draw() is then handed f without it, and the
    // plan prepare() made must follow.
    virtual void drop(size_t i) {}
    // draw(), the first pass writing the background where the G-buffer has no surface and
    // ambient x diffuse under its lights elsewhere. Called only where draws_own_ambient (paths.h)
    // holds for the geometry and f has lights.
    virtual void draw_with_ambient(const FrameDef& f, RenderTargets& targets, LightQueries& q, FrameStats& stats,
                                   const AmbientTerm& ambient) {
        draw(f, targets, q, stats);
    }
    // The deferred buffers' new size, for what a geometry keeps at that size (the tiles' spans).
    virtual void resize(int width, int height) {}
};

// The geometry the paths chose (Paths::light_geometry), its programs taken from `programs`.
std::unique_ptr<LightGeometryPass> make_light_geometry(const ShaderConfig& config, ProgramSet& programs, int width,
                                                       int height);

}  // namespace dsr
