// The light meshes of the volume and stencil geometries (light_mesh.h).
#include "deferred/light_mesh.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/gl.h"
#include "gl/state.h"

namespace dsr {

// Segments around the sphere's equator: fewer, larger triangles than volume_mesh's default (24),
// since a software rasteriser pays per triangle and per partly covered block; the mesh encloses the
// sphere either way (it is only a little larger).
constexpr int kLightMeshSegments = 12;

// The unit sphere's enclosing mesh (light_volume.h: every face plane on or outside the sphere),
// drawn for every point light scaled by its radius.
LightMeshes::LightMeshes() {
    LightVolume unit;
    unit.kind = LightVolume::Kind::sphere;
    unit.radius = 1;
    unit_sphere_ = volume_mesh(unit, kLightMeshSegments);
    reach_ = 0;
    for (const glm::vec3& v : unit_sphere_.vertices) reach_ = std::max(reach_, glm::length(v));
}

bool LightMeshes::past_far(const FrameDef& f, const LightDraw& l) const {
    const float far_plane = f.zrange.y;
    switch (l.eye.kind) {
        case LightVolume::Kind::full_screen: return true;
        case LightVolume::Kind::sphere: return l.eye.pos.z - l.eye.radius * reach_ <= -far_plane;
        case LightVolume::Kind::cone: {
            const VolumeMesh m = volume_mesh(l.eye);
            for (const glm::vec3& v : m.vertices)
                if (v.z <= -far_plane) return true;
            return false;
        }
    }
    return true;
}

void LightMeshes::draw_quads_past_far(const FrameDef& f, LightQuads& quads, LightQueries& q, FrameStats& stats) const {
    quads.begin(f);
    for (const LightDraw& l : f.lights)
        if (past_far(f, l)) {
            quads.draw(f, l, q);
            ++stats.light_passes;
            ++stats.lights_as_quads;
        }
}

void LightMeshes::begin(const FrameDef& f) const { gl_state().set_camera(f.proj); }

void LightMeshes::draw(const LightDraw& l) const {
    VolumeMesh cone;
    const VolumeMesh* m = &unit_sphere_;
    if (l.eye.kind == LightVolume::Kind::sphere) {
        gl_state().set_modelview(glm::scale(glm::translate(glm::mat4(1), l.eye.pos), glm::vec3(l.eye.radius)));
    } else {
        cone = volume_mesh(l.eye);
        m = &cone;
        gl_state().set_modelview(glm::mat4(1));
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, &m->vertices[0].x);
    glDrawElements(GL_TRIANGLES, GLsizei(m->indices.size()), GL_UNSIGNED_INT, m->indices.data());
    glDisableClientState(GL_VERTEX_ARRAY);
}

void LightMeshes::shade(const LightDraw& l, Program& prog, LightQueries& q, FrameStats& stats) const {
    set_light_params(prog, l.params);
    q.begin();
    draw(l);
    q.end();
    ++stats.light_passes;
}

void LightMeshes::shade_volumes(const FrameDef& f, const std::vector<const LightDraw*>& lights, LightPrograms& progs,
                                LightQueries& q, FrameStats& stats) const {
    begin(f);
    RenderState s = light_pass_state(0, false);
    s.cull = true;
    s.cull_face = GL_FRONT;  // back faces only: the camera may be inside
    s.depth_test = true;
    s.depth_func = GL_GREATER;  // the volume's far side behind the scene surface
    s.depth_write = false;
    for (const LightDraw* l : lights) {
        Program& prog = progs.form(*l);
        s.program = prog.id();
        gl_state().apply(s);
        bind_shadow(prog, f, *l);
        shade(*l, prog, q, stats);
        unbind_shadow(*l);
    }
}

}  // namespace dsr
