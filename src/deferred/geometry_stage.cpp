// Geometry stage (§3.3, Listings 7-13): the only stage that sees 3D geometry. A depth-only
// pre-pass fills the G-buffer's depth, then the material pass writes normal, diffuse,
// specular (and packed depth) for exactly the visible fragments (early Z, §3.3.1).
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "deferred/deferred_shader.h"
#include "deferred/depth_codec.h"
#include "deferred/gpu_scene.h"
#include "deferred/reconstruct.h"
#include "gl/check.h"

namespace dsr {

void DeferredShader::geometry_stage(const Scene& scene) {
    const Camera& cam = scene.camera;
    view_ = cam.view();
    proj_ = cam.projection(float(w_) / float(h_));
    planes_ = planes_uniform(cam.near_plane, cam.far_plane);
    zrange_ = glm::vec3(cam.near_plane, cam.far_plane, std::log2(cam.far_plane / cam.near_plane));

    mrt_bind_render();  // Listing 7 line 3
    // set_perspective_camera() (line 5)
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(glm::value_ptr(proj_));
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(glm::value_ptr(view_));
    // Render states, Listing 7 lines 7-17.
    glCullFace(GL_BACK);
    glEnable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_ALPHA_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_TEXTURE_2D);
    glColor4f(1, 1, 1, 1);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    // Listing 7 clears every target to the background colour with one glClear; here each
    // target gets its own "no surface" value (docs/errata.md): a zero normal (0.5 grey,
    // which Listing 20's len > 0.1 test leaves unlit), zero diffuse with alpha 0 (the
    // ambient pass skips it), zero specular, and the packed depth of the far plane.
    const glm::vec4 clear[4] = {{0.5f, 0.5f, 0.5f, 0.0f}, {0, 0, 0, 0}, {0, 0, 0, 0},
                                glm::vec4(encode_eye_z(opts_.encoding, -cam.far_plane, cam.near_plane,
                                                       cam.far_plane), 0)};
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    check_gl("geometry stage: set-up");
    draw_depth();  // line 20
    check_gl("geometry stage: depth pass");
    // Each target is cleared to its own value; without MRT (§3.2, "rendering one pass per
    // buffer") each is also drawn right away, the depth pre-pass keeping every pass to the
    // visible fragments like the single MRT pass.
    std::vector<int> all;
    for (int t = 0; t < mrt_->color_targets(); ++t) {
        mrt_->set_draw_targets({t});
        glClearColor(clear[t].r, clear[t].g, clear[t].b, clear[t].a);
        glClear(GL_COLOR_BUFFER_BIT);
        if (!mrt_path_) draw_material(t);
        all.push_back(t);
    }
    if (mrt_path_) {
        mrt_->set_draw_targets(all);
        draw_material(-1);  // line 22: all targets in one pass (ARB_draw_buffers)
    }
    check_gl("geometry stage: material pass");

    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    mrt_unbind_render();  // line 24
}

// Listing 8: raw positions, no shader, colour writes off.
void DeferredShader::draw_depth() {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_TRUE);
    glUseProgram(0);
    gpu_->bind_positions();
    gpu_->draw_all();
    gpu_->unbind();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_FALSE);
}

// Listing 9 (target -1: all targets at once; t: only G-buffer target t), with its test un-inverted (docs/errata.md): materials with a normal map use
// the tangent-space shader, the others a variant that skips the normal map.
void DeferredShader::draw_material(int target) {
    gpu_->bind_all();
    int bound = -1;
    for (const DrawRange& r : gpu_->ranges()) {
        const GpuMaterial& m = gpu_->material(r.material);
        const bool variants = opts_.skip.material_variants;
        Program& prog = material_prog_[m.normal_map || !variants ? 1 : 0][variants && !m.has_specular ? 1 : 0][target + 1];
        if (bound != int(prog.id())) {
            prog.use();
            prog.set("normaltex", 0);
            prog.set("colortex", 1);
            prog.set("speculartex", 2);
            prog.set("planes", planes_);
            prog.set("zrange", zrange_);
            bound = int(prog.id());
        }
        // set_material_shader_params (Listing 9 line 13)
        prog.set("diffuse", m.diffuse);
        prog.set("specular", m.specular);
        prog.set("shininess_code", m.shininess_code);
        prog.set("tile", m.tile);
        const GLuint tex[3] = {m.normal_map || variants ? m.normal_tex : gpu_->flat_normal(), m.diffuse_tex,
                               m.specular_tex};
        for (int u = 0; u < 3; ++u) {
            glActiveTexture(GL_TEXTURE0 + u);
            glBindTexture(GL_TEXTURE_2D, tex[u]);
        }
        gpu_->draw(r);
    }
    for (int u = 2; u >= 0; --u) {
        glActiveTexture(GL_TEXTURE0 + u);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    glUseProgram(0);
    gpu_->unbind();
}

}  // namespace dsr
