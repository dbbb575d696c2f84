// The lighting stage (lighting_stage.h).
#include "deferred/lighting_stage.h"

#include "deferred/ambient_fold.h"
#include "deferred/light_pass.h"
#include "deferred/screen_quad.h"
#include "deferred/ssao_stage.h"
#include "dsr_error.h"
#include "gl/check.h"
#include "gl/readback.h"
#include "gl/state.h"

namespace dsr {

namespace {

// Listing 15's fixed-function modulate: unit 0 textured by the G-buffer's diffuse target,
// scaled by the ambient colour; the alpha test keeps the background where there is no surface.
// Listing 7 disabled GL_TEXTURE_2D; the modulate needs it back (docs/errata.md).
RenderState ambient_pass_state() {
    RenderState s = textured_2d(GL_MODULATE);
    s.alpha_test = true;
    s.alpha_func = GL_GREATER;
    s.alpha_ref = 0.5f;
    return s;
}

}  // namespace

LightingStage::LightingStage(const ShaderConfig& c, ProgramSet& programs, int width, int height)
    : count_samples_(c.paths.count_fragments),
      count_invocations_(c.caps.pipeline_statistics),
      depth_target_(depth_target(c.opts.depth)),
      pow2_(!c.caps.npot),
      draws_own_ambient_(draws_own_ambient(c.paths.light_geometry)),
      geometry_(make_light_geometry(c, programs, width, height)) {
    set_handoff(c, programs);
    fold_round_ = c.tile_round;
    if (programs.has("light_fold")) fold_ = std::make_unique<LightPrograms>(programs, "light_fold");
    if (programs.has("position")) position_prog_ = programs.take("position");
}

LightingStage::~LightingStage() = default;

void LightingStage::resize(int width, int height) {
    geometry_->resize(width, height);
    position_buf_.reset();  // made again at the new size on next use
}

void LightingStage::set_handoff(const ShaderConfig& c, ProgramSet& programs) {
    handoff_.reset();
    if (c.paths.accum_depth) handoff_ = std::make_unique<DepthHandoffPass>(c, programs);
}

void LightingStage::draw_ambient(const FrameDef& f, const Scene& scene, RenderTargets& t, const SsaoStage* ssao) {
    gl_state().set_camera(f.pixels());
    gl_state().apply(ambient_pass_state());  // before the clear: colour writes on, no scissor
    glClearColor(scene.background.r, scene.background.g, scene.background.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(scene.ambient.r, scene.ambient.g, scene.ambient.b, 1.0f);
    t.mrt_bind_texture(G_DIFFUSE, 0);
    draw_rect(f, 0, 0, float(f.width), float(f.height), false);
    t.mrt_unbind_texture(G_DIFFUSE, 0);
    glColor4f(1, 1, 1, 1);
    if (ssao) ssao->modulate_ambient(f, t);
}

void LightingStage::hand_off_depth(const FrameDef& f, RenderTargets& t, const AmbientTerm* ambient) {
    if (!handoff_) throw Error("the depth hand-off runs only where the paths give P-buffer 0 a depth buffer");
    handoff_->draw(f, t, ambient);
}

void LightingStage::draw_lighting(const FrameDef& f, const FrameDef& lights, RenderTargets& t, FrameStats& stats,
                                  const AmbientFold* fold) {
    stats.lights.total = f.lights_total;
    stats.lights.culled = f.lights_culled;
    stats.lights.drawn = int(f.lights.size());
    stats.lights.scissor_pixels = f.scissor_pixels;
    // Whether this frame is counted: decided here for every geometry.
    LightQueries q(counting_ && count_samples_, counting_ && count_invocations_);
    if (fold && fold->by_geometry) {
        geometry_->draw_with_ambient(lights, t, q, stats, fold->colours);
    } else {
        if (fold) {
            draw_fold(f, *fold, q);
            ++stats.lights.passes;
        }
        geometry_->draw(lights, t, q, stats);
    }
    q.collect(stats.lights);
    // unbind_light(): nothing to restore, the next pass states what it needs.
}

// The full-screen light's quad through its fold variant: it replaces the clear and Listing 15, so
// it writes every pixel (no blending, no scissor) and rejects none (light.frag's AMBIENT_FOLD).
void LightingStage::draw_fold(const FrameDef& f, const AmbientFold& fold, LightQueries& q) {
    const LightDraw& l = f.lights[fold.light];
    Program& prog = (*fold_)[l.shader()];  // full_screen_light: never a shadowed light
    gl_state().set_camera(f.pixels());
    RenderState s = fixed_function_2d();
    s.program = prog.id();
    gl_state().apply(s);
    set_light_uniforms(prog, f);
    prog.set("ambient", fold.colours.ambient);
    prog.set("background", fold.colours.background);
    prog.set("quantize_round", fold_round_);  // quantize.glsl's fallback (unused where a model fits)
    set_light_params(prog, l.params);
    q.begin();
    draw_rect(f, 0, 0, float(f.width), float(f.height), true);
    q.end();
}

Image LightingStage::reconstructed_positions(const FrameDef& f, RenderTargets& t) {
    if (!position_prog_.id()) throw Error("position read-back needs EXT_framebuffer_object and ARB_texture_float");
    const int w = f.width, h = f.height;
    if (!position_buf_) {
        PBufferDesc d;
        d.width = w;
        d.height = h;
        d.color_formats = {GL_RGBA32F_ARB};
        d.pow2 = pow2_;
        position_buf_ = std::make_unique<PBuffer>("position read-back", d);
    }
    position_buf_->bind_render();
    gl_state().set_camera(f.pixels());
    RenderState s = fixed_function_2d();  // the light shader's arithmetic, written, not blended
    s.program = position_prog_.id();
    gl_state().apply(s);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    set_light_uniforms(position_prog_, f);  // light.frag's: samplers, planes, uv_scale and ray_map
    t.mrt_bind_texture(G_NORMAL, 0);
    t.mrt_bind_texture(depth_target_, 3);
    draw_rect(f, 0, 0, float(w), float(h), true);
    t.mrt_unbind_texture(depth_target_, 3);
    t.mrt_unbind_texture(G_NORMAL, 0);
    position_buf_->unbind_render();
    check_gl("position read-back");
    const PBuffer& pb = *position_buf_;
    return read_texture(pb.texture(0), w, h, pb.texture_width(), pb.texture_height(), false);
}

}  // namespace dsr
