// The forward stage after the lights (issue 13; DESIGN "forward after lights"): P-buffer 0 holds
// the lit opaque image and, through the depth hand-off (depth_handoff.cpp), the scene's depth, so
// geometry drawn now is hidden by opaque surfaces exactly as in a forward render. Two things are
// drawn, before post-processing so bloom and anti-aliasing see them:
//  * light markers (`--show-lights`): a small emissive sphere in each point and spot light's
//    colour, fixed function, depth tested and written, so bloom makes them glow as the tutorial's
//    Figure 11 highlights do;
//  * transparent surfaces (materials with opacity < 1): the tutorial's §4 "fall-back to a non
//    deferred shading approach for transparent surfaces", LearnOpenGL's "Combining deferred
//    rendering with forward rendering": forward/transparent_pass.h.
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "deferred/deferred_shader.h"
#include "deferred/gpu_scene.h"
#include "deferred/light_marker.h"
#include "forward/transparent_pass.h"
#include "gl/check.h"
#include "gl/state.h"

namespace dsr {

void DeferredShader::forward_stage(const Scene& scene, FrameStats& stats) {
    glMatrixMode(GL_PROJECTION);  // the lighting stage left its orthographic camera
    glLoadMatrixf(glm::value_ptr(proj_));
    glMatrixMode(GL_MODELVIEW);
    if (opts_.show_lights) draw_light_markers(scene, stats);
    if (transparent_ && !gpu_->transparent_objects().empty()) {
        // The lights the light passes drew (visible_lights: frustum-culled, in eye space), by scene
        // index; the others reach no visible pixel, or add nothing.
        std::vector<LightParams> params(scene.lights.size());
        std::vector<char> visible(scene.lights.size(), 0);
        for (const LightDraw& l : frame_lights_) {
            const size_t i = size_t(l.light - scene.lights.data());
            params[i] = l.params;
            visible[i] = 1;
        }
        const TransparentStats ts = transparent_->draw(scene, *gpu_, bounds_, params, visible);
        stats.transparent_objects = ts.objects;
        stats.transparent_passes = ts.passes;
    }
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

// One sphere mesh, scaled and moved per light by the modelview; client-side arrays (a few
// hundred vertices), fixed function: the colour is the light's, unlit.
void DeferredShader::draw_light_markers(const Scene& scene, FrameStats& stats) {
    if (marker_mesh_.indices.empty()) marker_mesh_ = make_sphere(1.0f, 0, 16, 8);
    RenderState s = opaque_geometry();  // back faces culled, GL_LEQUAL, depth written, no program
    gl_state().apply(s);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, sizeof(Vertex), &marker_mesh_.vertices[0].pos);
    for (const Light& l : scene.lights) {
        if (l.type == Light::Type::directional) continue;  // no position to mark
        const glm::vec3 eye = scene.camera.to_eye(l.pos);  // in double, rounded once
        const float r = marker_radius(glm::length(eye), proj_[1][1]);
        if (!(r > 0)) continue;
        const glm::mat4 mv = glm::scale(glm::translate(glm::mat4(1), eye), glm::vec3(r));
        glLoadMatrixf(glm::value_ptr(mv));
        glColor4f(l.color.r, l.color.g, l.color.b, 1.0f);
        glDrawElements(GL_TRIANGLES, GLsizei(marker_mesh_.indices.size()), GL_UNSIGNED_INT, marker_mesh_.indices.data());
        ++stats.light_markers;
    }
    glDisableClientState(GL_VERTEX_ARRAY);
    glColor4f(1, 1, 1, 1);
    check_gl_stage("forward stage: light markers");
}

}  // namespace dsr
