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
            ++stats.lights.passes;
            ++stats.lights.as_quads;
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
    ++stats.lights.passes;
}

namespace {

// A volume's light pass with `program`: its back faces only (the camera may be inside), where the
// volume's far side lies behind the scene surface.
RenderState volume_pass_state(GLuint program) {
    RenderState s = light_pass_state(program, false);
    s.cull = true;
    s.cull_face = GL_FRONT;
    s.depth_test = true;
    s.depth_func = GL_GREATER;
    s.depth_write = false;
    return s;
}

}  // namespace

void LightMeshes::shade_volumes(const FrameDef& f, const std::vector<const LightDraw*>& lights,
                                LightVolumeBatch& batch, LightPrograms& progs, LightQueries& q,
                                FrameStats& stats) const {
    std::vector<const LightDraw*> batched, one_by_one;
    for (const LightDraw* l : lights) (LightVolumeBatch::takes(*l) ? batched : one_by_one).push_back(l);
    batch.draw(f, batched, q, stats);
    if (one_by_one.empty()) return;
    progs.begin(f);
    begin(f);
    RenderState s = volume_pass_state(0);
    for (const LightDraw* l : one_by_one) {
        Program& prog = progs.form(*l);
        s.program = prog.id();
        gl_state().apply(s);
        bind_shadow(prog, f, *l);
        shade(*l, prog, q, stats);
        unbind_shadow(*l);
    }
}

LightVolumeBatch::LightVolumeBatch(ProgramSet& programs, int batch, const LightMeshes& meshes)
    : progs_(programs, "light_volume_batch"), batch_(batch), mesh_(&meshes.unit_sphere()) {}

// The batch's copies of the mesh, built on the first draw: a renderer whose frames draw no
// volume (auto on most scenes) holds no buffers (about 310 KB at a batch of 128).
void LightVolumeBatch::upload() {
    const VolumeMesh& m = *mesh_;
    std::vector<float> verts;
    std::vector<uint32_t> idx;
    verts.reserve(size_t(batch_) * m.vertices.size() * 4);
    idx.reserve(size_t(batch_) * m.indices.size());
    for (int k = 0; k < batch_; ++k) {
        const uint32_t base = uint32_t(size_t(k) * m.vertices.size());
        for (const glm::vec3& v : m.vertices) verts.insert(verts.end(), {v.x, v.y, v.z, float(k)});
        for (uint32_t i : m.indices) idx.push_back(base + i);
    }
    glGenBuffers(1, &vbo_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(verts.size() * sizeof(float)), verts.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glGenBuffers(1, &ibo_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(idx.size() * sizeof(uint32_t)), idx.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

LightVolumeBatch::~LightVolumeBatch() {
    if (vbo_) glDeleteBuffers(1, &vbo_);
    if (ibo_) glDeleteBuffers(1, &ibo_);
}

bool LightVolumeBatch::takes(const LightDraw& l) {
    return l.eye.kind == LightVolume::Kind::sphere && l.light->type == Light::Type::point && l.shadow < 0;
}

void LightVolumeBatch::draw(const FrameDef& f, const std::vector<const LightDraw*>& lights, LightQueries& q,
                            FrameStats& stats) {
    if (lights.empty()) return;
    if (!vbo_) upload();
    gl_state().set_camera(f.proj);
    progs_.begin(f);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 4 * sizeof(float), nullptr);
    glClientActiveTexture(GL_TEXTURE2);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(1, GL_FLOAT, 4 * sizeof(float), reinterpret_cast<const void*>(3 * sizeof(float)));
    for_each_light_batch(lights, batch_, [&](LightShader form, const LightDraw* const* run, size_t n) {
        Program& prog = progs_[form];
        arrays_.clear();
        for (size_t k = 0; k < n; ++k) arrays_.add(run[k]->params);
        gl_state().apply(volume_pass_state(prog.id()));
        arrays_.set(prog, LightArrays::kBatch);
        q.begin();
        glDrawElements(GL_TRIANGLES, GLsizei(n * mesh_->indices.size()), GL_UNSIGNED_INT, nullptr);
        q.end();
        ++stats.lights.passes;
    });
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glClientActiveTexture(GL_TEXTURE0);
    glDisableClientState(GL_VERTEX_ARRAY);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

}  // namespace dsr
