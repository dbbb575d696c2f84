// The SSAO stage (ssao_stage.h).
#include "deferred/ssao_stage.h"

#include <glm/gtc/matrix_transform.hpp>

#include "deferred/screen_quad.h"
#include "deferred/ssao_kernel.h"
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

SsaoStage::SsaoStage(const ShaderConfig& c, ProgramSet& programs)
    : o_(c.opts.ssao),
      depth_target_(depth_target(c.opts.depth)),
      occlusion_(programs.take("ssao")),
      blur_(programs.take("ssao_blur")) {}

// Both SSAO passes: `target` bound, the uniforms of ssao_position.glsl (the G-buffer's depth on
// unit 1), and the frame's pixel camera moved by half a frame pixel at half scale: an AO pixel's
// centre (frame x = 2i + 1) then takes the texture coordinates and view ray of G-buffer pixel
// 2i's centre, the texel its nearest fetch reads; unshifted it would pair that texel's depth with
// the ray of a pixel corner, and at grazing angles the floor would occlude itself.
void SsaoStage::begin_pass(const FrameDef& f, PBuffer& target, Program& prog) const {
    target.bind_render();
    const glm::mat4 shift = o_.scale == 2 ? glm::translate(glm::mat4(1), glm::vec3(0.5f, 0.5f, 0.0f)) : glm::mat4(1);
    gl_state().set_camera(f.pixels(), shift);
    gl_state().apply(ssao_pass_state(prog.id()));
    prog.set("depth_map", 1);
    prog.set("planes", f.planes);
    prog.set("zrange", f.zrange);
}

void SsaoStage::draw(const FrameDef& f, RenderTargets& t) {
    // Occlusion: the quad is laid out in frame pixels; the viewport is the AO buffer's.
    PBuffer& raw = t.ssao(SSAO_RAW);
    begin_pass(f, raw, occlusion_);
    occlusion_.set("normal_map", 0);
    occlusion_.set("proj", glm::vec2(f.proj[0][0], f.proj[1][1]));
    occlusion_.set("gtex_scale", f.gbuffer_extent);
    occlusion_.set("gsize", glm::vec2(float(f.width), float(f.height)));
    occlusion_.set("radius", o_.radius);
    occlusion_.set("strength", o_.strength);
    occlusion_.set("bias", kBiasOfRadius * o_.radius);
    const std::vector<glm::vec3> kernel = ssao_kernel(o_.samples);
    const std::vector<glm::vec3> rot = ssao_rotations();
    occlusion_.set_array("kernel", kernel.data(), int(kernel.size()));
    occlusion_.set_array("rotations", rot.data(), int(rot.size()));
    t.mrt_bind_texture(G_NORMAL, 0);
    t.mrt_bind_texture(depth_target_, 1);
    draw_rect(f, 0, 0, float(f.width), float(f.height), true);
    raw.unbind_render();
    check_gl_stage("ssao: occlusion");

    // Depth-aware blur, raw -> blurred, the G-buffer's depth still on unit 1.
    PBuffer& blurred = t.ssao(SSAO_BLURRED);
    begin_pass(f, blurred, blur_);
    blur_.set("ao_map", 0);
    blur_.set("texel", glm::vec2(1.0f / float(raw.texture_width()), 1.0f / float(raw.texture_height())));
    blur_.set("uv_clamp", uv_clamp(raw));
    blur_.set("to_ao", glm::vec2(raw.tex_scale_x(), raw.tex_scale_y()) / f.gbuffer_extent);
    blur_.set("depth_tolerance", kBlurDepthTolerance);
    t.mrt_unbind_texture(G_NORMAL, 0);
    raw.bind_texture(0, 0);
    draw_rect(f, 0, 0, float(f.width), float(f.height), false);
    raw.unbind_texture(0, 0);
    t.mrt_unbind_texture(depth_target_, 1);
    blurred.unbind_render();
    check_gl_stage("ssao: blur");
}

void SsaoStage::modulate_ambient(const FrameDef& f, RenderTargets& t) const {
    gl_state().set_camera(f.pixels());
    gl_state().apply(ssao_modulate_state());
    PBuffer& ao = t.ssao(SSAO_BLURRED);
    ao.bind_texture(0, 0);
    draw_quad_clamped(float(f.width), float(f.height), ao);  // bilinear: the half-size buffer scaled up
    ao.unbind_texture(0, 0);
}

}  // namespace dsr
