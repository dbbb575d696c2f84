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
#include "dsr_error.h"
#include "gl/check.h"
#include "gl/state.h"

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
    // Each draw loads its object's modelview, view * model composed in double (camera-relative).
    gpu_->set_view(cam.view_d());
    glColor4f(1, 1, 1, 1);
    // Listing 7 clears every target to the background colour with one glClear; here each
    // target gets its own "no surface" value (docs/errata.md): a zero normal (0.5 grey,
    // which Listing 20's len > 0.1 test leaves unlit), zero diffuse with alpha 0 (the
    // ambient pass skips it), zero specular, and the packed depth (or position) of the far plane.
    // The position paths' target holds the far plane's eye z there (x = y = 0, alpha 0), so the
    // light pass's depth test and the depth hand-off see the background where the depth paths do.
    const glm::vec4 far_code = is_position_path(opts_.depth)
                                   ? glm::vec4(0, 0, -cam.far_plane, 0)
                                   : glm::vec4(encode_eye_z(opts_.encoding, -cam.far_plane, cam.near_plane, cam.far_plane), 0);
    const glm::vec4 clear[4] = {{0.5f, 0.5f, 0.5f, 0.0f}, {0, 0, 0, 0}, {0, 0, 0, 0}, far_code};
    gl_state().apply(depth_pass_state());  // the clear writes depth: depth writes on, no scissor
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    check_gl_stage("geometry stage: set-up");
    draw_depth();  // line 20
    check_gl_stage("geometry stage: depth pass");
    // Each target is cleared to its own value; without MRT (§3.2, "rendering one pass per
    // buffer") each is also drawn right away, the depth pre-pass keeping every pass to the
    // visible fragments like the single MRT pass.
    gl_state().apply(material_pass_state());  // the clears write colour
    std::vector<int> all;
    for (int t = 0; t < gbuf().color_targets(); ++t) {
        gbuf().set_draw_targets({t});
        glClearColor(clear[t].r, clear[t].g, clear[t].b, clear[t].a);
        glClear(GL_COLOR_BUFFER_BIT);
        if (!paths_.mrt) draw_material(t);
        all.push_back(t);
    }
    if (paths_.mrt) {
        gbuf().set_draw_targets(all);
        draw_material(-1);  // line 22: all targets in one pass (ARB_draw_buffers)
    }
    check_gl_stage("geometry stage: material pass");
    mrt_unbind_render();  // line 24
}

// Render states of Listing 7 lines 7-17: back faces culled, GL_LEQUAL, no blending, no
// scissor, no alpha test, no fixed-function texturing.
RenderState DeferredShader::depth_pass_state() {
    RenderState s = opaque_geometry();
    s.color_write = false;  // Listing 8: depth only
    return s;
}

// The material pass: the same, colour on and depth writes off (the pre-pass laid it down,
// so only the visible fragment passes GL_LEQUAL: early Z, §3.3.1).
RenderState DeferredShader::material_pass_state() {
    RenderState s = depth_pass_state();
    s.color_write = true;
    s.depth_write = false;
    return s;
}

// Listing 8: raw positions, no shader, colour writes off.
void DeferredShader::draw_depth() {
    gl_state().apply(depth_pass_state());
    gpu_->bind_positions();
    gpu_->draw_all();
    gpu_->unbind();
}

Program& DeferredShader::material_program(const GpuMaterial& m, int target) {
    // Without the variants skip, every material takes the full shader (normal map and
    // specular map read), as a single-shader renderer would.
    const bool variants = opts_.skip.material_variants;
    const MaterialKey key{m.normal_map || !variants, variants && !m.has_specular, target};
    auto it = material_progs_.find(key);
    if (it == material_progs_.end()) throw Error("no material program for this material and target");
    return it->second;
}

// Listing 9 (target -1: all targets at once; t: only G-buffer target t), with its test un-inverted (docs/errata.md): materials with a normal map use
// the tangent-space shader, the others a variant that skips the normal map.
void DeferredShader::draw_material(int target) {
    gl_state().apply(material_pass_state());
    gpu_->bind_all();
    int bound = -1;
    const bool variants = opts_.skip.material_variants;
    for (const DrawRange& r : gpu_->ranges()) {
        const GpuMaterial& m = gpu_->material(r.material);
        Program& prog = material_program(m, target);
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
    gpu_->unbind();
}

}  // namespace dsr
