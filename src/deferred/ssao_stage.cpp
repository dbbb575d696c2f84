// SSAO stage (issue 13; Vasilovici §5): ambient occlusion from the G-buffer's depth and normals
// in a pass of its own, then a depth-aware blur, both into the SSAO buffers (render_targets.h)
// at 1/ssao.scale of the frame. Unlike Vasilovici, who writes it into the final target's alpha
// after the light pass, it scales the ambient pass only (Listing 15, Eq. 6): lights stay as the
// tutorial adds them. With --ssao off none of this runs and the ambient pass is the tutorial's.
#include <string>
#include <vector>

#include "deferred/deferred_shader.h"
#include "deferred/reconstruct.h"
#include "deferred/screen_quad.h"
#include "deferred/ssao_kernel.h"
#include "dsr_error.h"
#include "gl/check.h"
#include "gl/state.h"

namespace dsr {

namespace {
// Eye-depth differences below this fraction of the radius do not occlude: no acne on flat
// surfaces from the depth's rounding (packed: 24 bits) or the normal's (8 bits per component).
constexpr float kBiasOfRadius = 0.04f;
// The blur: a tap whose eye depth differs from the centre's by this fraction of it weighs 0.
constexpr float kBlurDepthTolerance = 0.05f;

// The SSAO passes write every pixel of their buffer: one quad, every test off, no blending.
RenderState ssao_pass_state(GLuint program) {
    RenderState s = fixed_function_2d();
    s.program = program;
    return s;
}

// P-buffer 0 (the ambient pass's image) times the AO buffer: the texture replaces the fragment
// colour and the blend multiplies it into the destination (GL_DST_COLOR, GL_ZERO). Where ao is 1
// (255) the destination stays exactly as it was.
RenderState ssao_modulate_state() {
    RenderState s = textured_2d(GL_REPLACE);
    s.blend = true;
    s.blend_src = GL_DST_COLOR;
    s.blend_dst = GL_ZERO;
    return s;
}
}  // namespace

void DeferredShader::build_ssao_programs() {
    const SsaoOptions& o = opts_.ssao;
    if (o.scale != 1 && o.scale != 2) throw Error("ssao scale must be 1 or 2, got " + std::to_string(o.scale));
    if (o.samples < 4 || o.samples > 64) throw Error("ssao samples must be 4..64, got " + std::to_string(o.samples));
    if (!(o.radius > 0)) throw Error("ssao radius must be positive, got " + std::to_string(o.radius));
    if (!(o.strength >= 0)) throw Error("ssao strength must be 0 or more, got " + std::to_string(o.strength));
    std::vector<std::string> defs = depth_defines();
    defs.push_back("SAMPLES " + std::to_string(o.samples));
    ssao_prog_ = Program(shader_dir_, "light.vert", "ssao.frag", defs);
    defs.pop_back();
    ssao_blur_prog_ = Program(shader_dir_, "post.vert", "ssao_blur.frag", defs);
}

// The frame's ortho camera (set_ortho), moved by half a frame pixel at half scale: an AO pixel's
// centre (frame x = 2i + 1) then takes the texture coordinates and view ray of G-buffer pixel
// 2i's centre, the texel its nearest fetch reads; unshifted it would pair that texel's depth with
// the ray of a pixel corner, and at grazing angles the floor would occlude itself.
void DeferredShader::set_ssao_ortho() {
    set_ortho(w_, h_);
    if (opts_.ssao.scale == 2) glTranslatef(0.5f, 0.5f, 0.0f);
}

// Both SSAO passes: `target` bound, the camera above, `prog` with its state, and the uniforms of
// ssao_position.glsl (the G-buffer's depth on unit 1).
void DeferredShader::begin_ssao_pass(PBuffer& target, Program& prog) {
    target.bind_render();
    set_ssao_ortho();
    gl_state().apply(ssao_pass_state(prog.id()));
    prog.set("depth_map", 1);
    prog.set("planes", planes_);
    prog.set("zrange", zrange_);
}

void DeferredShader::draw_ssao() {
    // The view rays the light passes' quads carry (Listing 19), for this frame's camera.
    const auto rays = corner_rays(proj_[0][0], proj_[1][1]);
    for (int i = 0; i < 4; ++i) corner_rays_[i] = rays[i];
    const SsaoOptions& o = opts_.ssao;
    const glm::vec2 gscale(gbuf().tex_scale_x(), gbuf().tex_scale_y());

    // Occlusion: the quad is laid out in frame pixels; the viewport is the AO buffer's.
    PBuffer& raw = targets_->ssao(SSAO_RAW);
    begin_ssao_pass(raw, ssao_prog_);
    ssao_prog_.set("normal_map", 0);
    ssao_prog_.set("proj", glm::vec2(proj_[0][0], proj_[1][1]));
    ssao_prog_.set("gtex_scale", gscale);
    ssao_prog_.set("gsize", glm::vec2(float(w_), float(h_)));
    ssao_prog_.set("radius", o.radius);
    ssao_prog_.set("strength", o.strength);
    ssao_prog_.set("bias", kBiasOfRadius * o.radius);
    const std::vector<glm::vec3> kernel = ssao_kernel(o.samples);
    const std::vector<glm::vec3> rot = ssao_rotations();
    glUniform3fv(glGetUniformLocation(ssao_prog_.id(), "kernel"), GLsizei(kernel.size()), &kernel[0].x);
    glUniform3fv(glGetUniformLocation(ssao_prog_.id(), "rotations"), GLsizei(rot.size()), &rot[0].x);
    mrt_bind_texture(G_NORMAL, 0);
    mrt_bind_texture(depth_target(), 1);
    draw_rect(0, 0, float(w_), float(h_), true);
    raw.unbind_render();
    check_gl_stage("ssao: occlusion");

    // Depth-aware blur, raw -> blurred, the G-buffer's depth still on unit 1.
    PBuffer& blurred = targets_->ssao(SSAO_BLURRED);
    begin_ssao_pass(blurred, ssao_blur_prog_);
    ssao_blur_prog_.set("ao_map", 0);
    ssao_blur_prog_.set("texel", glm::vec2(1.0f / float(raw.texture_width()), 1.0f / float(raw.texture_height())));
    ssao_blur_prog_.set("uv_clamp", uv_clamp(raw));
    ssao_blur_prog_.set("to_ao", glm::vec2(raw.tex_scale_x(), raw.tex_scale_y()) / gscale);
    ssao_blur_prog_.set("depth_tolerance", kBlurDepthTolerance);
    mrt_unbind_texture(G_NORMAL, 0);
    raw.bind_texture(0, 0);
    draw_rect(0, 0, float(w_), float(h_), false);
    raw.unbind_texture(0, 0);
    mrt_unbind_texture(depth_target(), 1);
    blurred.unbind_render();
    check_gl_stage("ssao: blur");
}

// Inside the ambient pass, P-buffer 0 bound: Eq. 6's ambient term times ao, before any light adds.
void DeferredShader::modulate_ambient_by_ssao() {
    gl_state().apply(ssao_modulate_state());
    PBuffer& ao = targets_->ssao(SSAO_BLURRED);
    ao.bind_texture(0, 0);
    draw_quad_clamped(float(w_), float(h_), ao);  // bilinear: the half-size buffer scaled up
    ao.unbind_texture(0, 0);
}

}  // namespace dsr
