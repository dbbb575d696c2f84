// The forward stage (forward_stage.h).
#include "deferred/forward_stage.h"

#include <glm/gtc/matrix_transform.hpp>

#include "deferred/light_marker.h"
#include "gl/check.h"
#include "gl/state.h"

namespace dsr {

ForwardStage::ForwardStage(const std::string& shader_dir, const ShaderOptions& opts)
    : shader_dir_(shader_dir),
      listing2_literal_(opts.listing2_literal),
      show_lights_(opts.show_lights),
      shadow_filter_(opts.shadows.filter) {}

void ForwardStage::set_scene(const Scene& scene, const GpuScene& gpu) {
    bounds_ = object_bounds(scene);
    if (!gpu.transparent_objects().empty() && !transparent_)
        transparent_ = std::make_unique<TransparentPass>(shader_dir_, listing2_literal_);
}

void ForwardStage::draw(const FrameDef& f, const Scene& scene, GpuScene& gpu, ForwardCounts& stats) {
    gl_state().set_camera(f.proj);  // each draw loads its own modelview
    if (show_lights_) draw_light_markers(f, scene, stats);
    if (transparent_ && !gpu.transparent_objects().empty()) {
        // The lights the light passes drew (FrameDef::lights: frustum-culled, in eye space), by scene
        // index; the others reach no visible pixel, or add nothing.
        std::vector<LightParams> params(scene.lights.size());
        std::vector<char> visible(scene.lights.size(), 0);
        for (const LightDraw& l : f.lights) {
            params[l.index] = l.params;
            visible[l.index] = 1;
        }
        gpu.set_view(f.camera.view_d());  // the objects' modelviews, for this frame's camera
        // Shadowed lights' maps by scene index: the transparent surfaces receive their shadows.
        std::vector<const ShadowLookup*> maps;
        if (!f.shadows.empty()) {
            maps.assign(scene.lights.size(), nullptr);
            for (const LightDraw& l : f.lights)
                if (l.shadow >= 0) maps[l.index] = &f.shadows[size_t(l.shadow)];
        }
        const TransparentStats ts = transparent_->draw(scene, gpu, bounds_, params, visible, maps, shadow_filter_);
        stats.transparent_objects = ts.objects;
        stats.transparent_passes = ts.passes;
    }
}

// One sphere mesh, scaled and moved per light by the modelview, or the scene's `markers box`: a
// cube of a fixed world size, as LearnOpenGL's demo draws its light boxes. Client-side arrays (a
// few hundred vertices), fixed function: the colour is the light's, unlit.
void ForwardStage::draw_light_markers(const FrameDef& f, const Scene& scene, ForwardCounts& stats) {
    const bool boxes = scene.marker_shape == Scene::MarkerShape::box;
    Mesh& mesh = boxes ? marker_box_ : marker_mesh_;
    if (mesh.indices.empty()) mesh = boxes ? make_box(glm::vec3(2.0f), 0) : make_sphere(1.0f, 0, 16, 8);
    RenderState s = opaque_geometry();  // back faces culled, GL_LEQUAL, depth written, no program
    gl_state().apply(s);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, sizeof(Vertex), &mesh.vertices[0].pos);
    for (const Light& l : scene.lights) {
        if (l.type == Light::Type::directional) continue;  // no position to mark
        const glm::vec3 eye = f.camera.to_eye(l.pos);  // in double, rounded once
        if (boxes) {
            if (!(eye.z < 0)) continue;  // at or behind the eye
            // World-aligned, so it turns with the scene: view * model in double, rounded once.
            const glm::dmat4 model = glm::scale(glm::translate(glm::dmat4(1), glm::dvec3(l.pos)),
                                                glm::dvec3(scene.marker_size));
            gl_state().set_modelview(camera_relative(f.camera.view_d(), model));
        } else {
            const float r = marker_radius(glm::length(eye), f.proj[1][1]);
            if (!(r > 0)) continue;
            gl_state().set_modelview(glm::scale(glm::translate(glm::mat4(1), eye), glm::vec3(r)));
        }
        glColor4f(l.color.r, l.color.g, l.color.b, 1.0f);
        glDrawElements(GL_TRIANGLES, GLsizei(mesh.indices.size()), GL_UNSIGNED_INT, mesh.indices.data());
        ++stats.light_markers;
    }
    glDisableClientState(GL_VERTEX_ARRAY);
    glColor4f(1, 1, 1, 1);
    check_gl_stage("forward stage: light markers");
}

}  // namespace dsr
