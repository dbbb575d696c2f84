// Light geometry `volume` (LearnOpenGL "Light volumes"; Vasilovici §4.2): each light draws the
// back faces of a closed mesh enclosing its sphere, front faces culled, with the depth test
// GL_GREATER against the scene's depth (handed to P-buffer 0 by hand_off_depth): a pixel
// enters the light shader only where the scene surface lies in front of the volume's far side.
// Back faces rather than front ones so the camera may stand inside the volume (its front faces
// are then behind the eye, TRAPS "Stencil light volumes"). A light whose mesh reaches past the
// far plane would lose its clipped back faces: it is drawn as its scissored quad instead.
#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "deferred/deferred_shader.h"
#include "deferred/light_queries.h"
#include "gl/state.h"

namespace dsr {

// Segments around the sphere's equator: fewer, larger triangles than volume_mesh's default (24),
// since a software rasteriser pays per triangle and per partly covered block; the mesh encloses the
// sphere either way (it is only a little larger).
constexpr int kLightMeshSegments = 12;

// The unit sphere's enclosing mesh (light_volume.h: every face plane on or outside the sphere),
// drawn for every point light scaled by its radius.
void DeferredShader::build_volume_mesh() {
    LightVolume unit;
    unit.kind = LightVolume::Kind::sphere;
    unit.radius = 1;
    unit_sphere_mesh_ = volume_mesh(unit, kLightMeshSegments);
    volume_mesh_reach_ = 0;
    for (const glm::vec3& v : unit_sphere_mesh_.vertices) volume_mesh_reach_ = std::max(volume_mesh_reach_, glm::length(v));
}

bool DeferredShader::mesh_past_far(const LightDraw& l) const {
    switch (l.eye.kind) {
        case LightVolume::Kind::full_screen: return true;
        case LightVolume::Kind::sphere: return l.eye.pos.z - l.eye.radius * volume_mesh_reach_ <= -zrange_.y;
        case LightVolume::Kind::cone: {
            const VolumeMesh m = volume_mesh(l.eye);
            for (const glm::vec3& v : m.vertices)
                if (v.z <= -zrange_.y) return true;
            return false;
        }
    }
    return true;
}

void DeferredShader::draw_light_mesh(const LightDraw& l) {
    glMatrixMode(GL_MODELVIEW);
    VolumeMesh cone;
    const VolumeMesh* m = &unit_sphere_mesh_;
    if (l.eye.kind == LightVolume::Kind::sphere) {
        const glm::mat4 mv = glm::scale(glm::translate(glm::mat4(1), l.eye.pos), glm::vec3(l.eye.radius));
        glLoadMatrixf(glm::value_ptr(mv));
    } else {
        cone = volume_mesh(l.eye);  // already in eye space
        m = &cone;
        glLoadIdentity();
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, &m->vertices[0].x);
    glDrawElements(GL_TRIANGLES, GLsizei(m->indices.size()), GL_UNSIGNED_INT, m->indices.data());
    glDisableClientState(GL_VERTEX_ARRAY);
}

// Projection for the meshes (the camera's) and back for the quads (pixels, §3.1).
namespace {
void load_projection(const glm::mat4& p) {
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(glm::value_ptr(p));
    glMatrixMode(GL_MODELVIEW);
}
}  // namespace

// What volume and stencil share: the quads first (lights whose mesh the far plane would clip),
// then the volume program's uniforms and the perspective projection for the meshes.
void DeferredShader::begin_light_meshes(const std::vector<LightDraw>& lights, LightQueries& q, FrameStats& stats) {
    light_passes_drawn_ = 0;
    set_light_uniforms(light_any_prog_);
    set_light_uniforms(light_prog_);
    for (const LightDraw& l : lights)
        if (mesh_past_far(l)) {
            draw_light_quad(l, q);
            ++stats.lights_as_quads;
        }
    set_light_uniforms(light_volume_prog_);
    if (light_stencil_prog_.id()) set_light_uniforms(light_stencil_prog_);
    load_projection(proj_);
}

void DeferredShader::draw_lights_volume(const std::vector<LightDraw>& lights, FrameStats& stats) {
    LightQueries q(counting_ && paths_.count_fragments, counting_ && caps_.pipeline_statistics);
    begin_light_meshes(lights, q, stats);
    RenderState s = light_pass_state(light_volume_prog_.id(), false);
    s.cull = true;
    s.cull_face = GL_FRONT;  // back faces only: the camera may be inside
    s.depth_test = true;
    s.depth_func = GL_GREATER;  // the volume's far side behind the scene surface
    s.depth_write = false;
    gl_state().apply(s);
    for (const LightDraw& l : lights) {
        if (mesh_past_far(l)) continue;
        draw_light_mesh_pass(l, q, light_volume_prog_);
    }
    end_light_meshes(q, stats);
}

// One light's shaded pass over its mesh, counted; volume and stencil share it.
void DeferredShader::draw_light_mesh_pass(const LightDraw& l, LightQueries& q, Program& prog) {
    set_light_params(prog, l.params);
    q.begin();
    draw_light_mesh(l);
    q.end();
    ++light_passes_drawn_;
}

// After the meshes: back to the image-space camera, and the counts into the stats.
void DeferredShader::end_light_meshes(LightQueries& q, FrameStats& stats) {
    set_ortho(w_, h_);
    q.collect(stats);
    stats.light_passes = light_passes_drawn_;
}

}  // namespace dsr
