// What the volume and stencil geometries share: each light drawn as a closed mesh enclosing its
// volume (light_volume.h volume_mesh), in eye space, and the lights that mesh cannot serve.
#pragma once
#include "deferred/frame.h"
#include "deferred/frame_stats.h"
#include "deferred/light_pass.h"
#include "deferred/light_volume.h"
#include "gl/gl.h"

namespace dsr {

class LightVolumeBatch;

class LightMeshes {
public:
    LightMeshes();
    // Lights a mesh geometry draws as its quad instead (LightQuads): directional lights (full
    // screen, no mesh) and volumes whose mesh reaches past the far plane, where its back faces
    // would be clipped away.
    bool past_far(const FrameDef& f, const LightDraw& l) const;
    // Those lights, first: each its counted quad (stats.lights.as_quads).
    void draw_quads_past_far(const FrameDef& f, LightQuads& quads, LightQueries& q, FrameStats& stats) const;
    // The frame's perspective camera for the meshes; before the first draw.
    void begin(const FrameDef& f) const;
    // The light's mesh: spheres as the unit sphere's mesh scaled and moved by the modelview,
    // cones as their own mesh (already in eye space).
    void draw(const LightDraw& l) const;
    // The light's shading pass over its mesh with `prog` (bound, its state applied): parameters,
    // the mesh inside the light's queries, one light pass counted.
    void shade(const LightDraw& l, Program& prog, LightQueries& q, FrameStats& stats) const;
    // The volume geometry's light passes (light_geometry_volume.cpp, auto's volumes) for `lights`
    // (none past far): back faces, depth test GL_GREATER against the scene's depth in P-buffer 0.
    // The point lights `batch` takes (LightVolumeBatch::takes) go in its batches; each of the
    // others (spots, shadowed lights) is a draw of its own with its form of `progs`.
    void shade_volumes(const FrameDef& f, const std::vector<const LightDraw*>& lights, LightVolumeBatch& batch,
                       LightPrograms& progs, LightQueries& q, FrameStats& stats) const;

    const VolumeMesh& unit_sphere() const { return unit_sphere_; }

private:
    VolumeMesh unit_sphere_;  // volume_mesh of the unit sphere at the origin
    float reach_ = 1;         // its farthest vertex from the centre
};

// The volume geometry's passes for many point lights in a few draws (pseudo-instancing, as
// LightQuadBatch draws quads): buffer objects hold `batch` copies of the unit sphere's mesh, each
// vertex with its copy's slot, and light.vert's VOLUME_BATCH places copy k at light k of the
// batch's uniform arrays. The same back faces, depth test and light program form as
// shade_volumes, so the same pixels; the CPU sends only the arrays.
class LightVolumeBatch {
public:
    LightVolumeBatch(ProgramSet& programs, int batch, const LightMeshes& meshes);
    ~LightVolumeBatch();
    LightVolumeBatch(const LightVolumeBatch&) = delete;
    LightVolumeBatch& operator=(const LightVolumeBatch&) = delete;
    // Which lights it draws: point lights (their volume the unit sphere's mesh scaled) without a
    // shadow map (a batch binds none).
    static bool takes(const LightDraw& l);
    // `lights` (each takes() and none past far), one light pass counted per draw.
    void draw(const FrameDef& f, const std::vector<const LightDraw*>& lights, LightQueries& q, FrameStats& stats);

    // Whether its buffers exist (built on the first draw).
    bool uploaded() const { return vbo_ != 0; }

private:
    void upload();
    LightPrograms progs_;
    int batch_;
    const VolumeMesh* mesh_;  // LightMeshes::unit_sphere() of the geometry that owns both: one copy
    GLuint vbo_ = 0, ibo_ = 0;
    LightArrays arrays_;
};

}  // namespace dsr
