// Light geometry `volume` (LearnOpenGL "Light volumes"; Vasilovici §4.2): each light draws the
// back faces of a closed mesh enclosing its sphere, front faces culled, with the depth test
// GL_GREATER against the scene's depth (handed to P-buffer 0 by hand_off_depth): a pixel
// enters the light shader only where the scene surface lies in front of the volume's far side.
// Back faces rather than front ones so the camera may stand inside the volume (its front faces
// are then behind the eye, TRAPS "Stencil light volumes"). A light whose mesh reaches past the
// far plane would lose its clipped back faces: it is drawn as its scissored quad instead.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "deferred/deferred_shader.h"
#include "deferred/light_queries.h"
#include "gl/state.h"

namespace dsr {

// An icosahedron subdivided twice (320 faces), its vertices on the unit sphere, then scaled so
// that every face plane lies at least 1 from the centre: the mesh encloses the unit sphere.
void DeferredShader::build_volume_mesh() {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    std::vector<unsigned> f = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4,
                               11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8,
                               3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
    for (auto& p : v) p = glm::normalize(p);
    for (int level = 0; level < 2; ++level) {
        std::map<std::pair<unsigned, unsigned>, unsigned> mid;
        auto midpoint = [&](unsigned a, unsigned b) {
            auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            v.push_back(glm::normalize(v[a] + v[b]));
            return mid[key] = unsigned(v.size() - 1);
        };
        std::vector<unsigned> g;
        for (size_t i = 0; i < f.size(); i += 3) {
            unsigned a = f[i], b = f[i + 1], c = f[i + 2];
            unsigned ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            g.insert(g.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        f = g;
    }
    float dmin = 1;
    for (size_t i = 0; i < f.size(); i += 3) {
        const glm::vec3 n = glm::normalize(glm::cross(v[f[i + 1]] - v[f[i]], v[f[i + 2]] - v[f[i]]));
        dmin = std::min(dmin, std::abs(glm::dot(n, v[f[i]])));
    }
    const float scale = 1.0f / dmin * 1.0001f;  // a hair over, for the float rounding of the transform
    volume_mesh_.clear();
    for (auto& p : v)
        for (int k = 0; k < 3; ++k) volume_mesh_.push_back(p[k] * scale);
    volume_index_ = f;
    volume_mesh_reach_ = scale;
}

bool DeferredShader::mesh_past_far(const LightDraw& l) const {
    return l.eye.z - l.light->radius * volume_mesh_reach_ <= -zrange_.y;
}

// The mesh in eye space: the light's centre and radius as the model-view, the camera's projection.
void DeferredShader::draw_light_mesh(const LightDraw& l) {
    const glm::mat4 mv = glm::scale(glm::translate(glm::mat4(1), l.eye), glm::vec3(l.light->radius));
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(glm::value_ptr(mv));
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, volume_mesh_.data());
    glDrawElements(GL_TRIANGLES, GLsizei(volume_index_.size()), GL_UNSIGNED_INT, volume_index_.data());
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

void DeferredShader::draw_lights_volume(const std::vector<LightDraw>& lights, FrameStats& stats) {
    LightQueries q(paths_.count_fragments, caps_.pipeline_statistics);
    light_passes_drawn_ = 0;
    // The quads first: lights whose mesh the far plane would clip.
    set_light_uniforms(light_prog_);
    for (const LightDraw& l : lights)
        if (mesh_past_far(l)) {
            draw_light_quad(l, q);
            ++stats.lights_as_quads;
        }
    set_light_uniforms(light_volume_prog_);
    load_projection(proj_);
    RenderState s = light_pass_state(light_volume_prog_.id(), false);
    s.cull = true;
    s.cull_face = GL_FRONT;  // back faces only: the camera may be inside
    s.depth_test = true;
    s.depth_func = GL_GREATER;  // the volume's far side behind the scene surface
    s.depth_write = false;
    gl_state().apply(s);
    for (const LightDraw& l : lights) {
        if (mesh_past_far(l)) continue;
        light_volume_prog_.set("lightpos", glm::vec4(l.eye, l.light->radius));
        light_volume_prog_.set("lightcolor", l.light->color);
        q.begin();
        draw_light_mesh(l);
        q.end();
        ++light_passes_drawn_;
    }
    set_ortho(w_, h_);
    q.collect(stats);
    stats.light_passes = light_passes_drawn_;
}

}  // namespace dsr
