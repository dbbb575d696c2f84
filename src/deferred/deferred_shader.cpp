// pDeferredShader: set-up, the frame in Appendix A's order, and the one-stage-at-a-time API.
#include "deferred/deferred_shader.h"

#include "deferred/ambient_fold.h"
#include "deferred/ambient_writer.h"
#include "deferred/emission_pass.h"
#include "deferred/forward_stage.h"
#include "deferred/geometry_stage.h"
#include "deferred/gpu_scene.h"
#include "deferred/lighting_stage.h"
#include "deferred/post_stage.h"
#include "deferred/shadow_stage.h"
#include "deferred/ssao_stage.h"
#include "dsr_clock.h"
#include "dsr_error.h"
#include "gl/check.h"
#include "gl/readback.h"

namespace dsr {

namespace {
// f() as stage `slot` of the frame timer.
template <class F>
void timed(FrameTimer& timer, int slot, F&& f) {
    timer.begin(slot);
    f();
    timer.end();
}
}  // namespace

DeferredShader::DeferredShader(const Caps& caps, int width, int height, const ShaderOptions& opts,
                               const std::string& shader_dir)
    : config_(shader_config(caps, opts)), shader_dir_(shader_dir), final_(config_.paths.fbo) {
    targets_ = std::make_unique<RenderTargets>(config_.paths, config_.opts, width, height);
    ProgramSet programs(shader_dir, config_);  // the whole table, compiled and linked now
    if (config_.opts.shadow_lights) shadows_ = std::make_unique<ShadowStage>(config_, programs);
    geometry_ = std::make_unique<GeometryStage>(config_, programs);
    if (config_.opts.ssao.on) ssao_ = std::make_unique<SsaoStage>(config_, programs);
    lighting_ = std::make_unique<LightingStage>(config_, programs, width, height);
    forward_ = std::make_unique<ForwardStage>(shader_dir, config_.opts);
    post_ = std::make_unique<PostStage>(config_, programs);
    final_.set_up(config_, programs);
    timer_.set_source(choose_timing(caps, width, height).source);
    check_gl("creating the deferred shader");
}

DeferredShader::~DeferredShader() = default;

void DeferredShader::set_counting(bool on) {
    counting_ = on;
    lighting_->set_counting(on);
}

void DeferredShader::resize(int width, int height) {
    if (width == this->width() && height == this->height()) return;
    targets_->resize(width, height);
    lighting_->resize(width, height);
    check_gl("resizing the deferred buffers");
}

void DeferredShader::set_scene(const Scene& scene) {
    const ColourMaps maps = !config_.opts.hdr.textures_srgb ? ColourMaps::as_stored
                            : config_.caps.texture_srgb    ? ColourMaps::srgb_texture
                                                           : ColourMaps::decoded_on_upload;
    gpu_ = std::make_unique<GpuScene>(scene, !config_.caps.npot, maps);
    // A metallic-roughness material where the options did not foresee one (RenderOptions::resolved
    // does): the light programs are built again with the material model's flag (METAL_ROUGH).
    bool metal_rough = false;
    for (const Material& m : scene.materials) metal_rough = metal_rough || m.metal_rough();
    if (metal_rough && !config_.opts.metal_rough) {
        config_.opts.metal_rough = true;
        ProgramSet programs(shader_dir_, config_);
        lighting_ = std::make_unique<LightingStage>(config_, programs, width(), height());
        lighting_->set_counting(counting_);
    }
    // Transparent materials are drawn by the forward stage, which needs the scene's depth in
    // P-buffer 0: where the options did not foresee them (RenderOptions::resolved does), the paths
    // are chosen again, the buffers reallocated and the depth hand-off built; no other shader is.
    if (!gpu_->transparent_objects().empty() && !config_.opts.forward_surfaces) {
        ShaderOptions o = config_.opts;
        o.forward_surfaces = true;
        const bool had_depth = config_.paths.accum_depth;
        const bool had_target = config_.paths.ambient_target;
        config_ = shader_config(config_.caps, o);
        // The material pass was built for the ambient target or not: that stays as it was, and the
        // hand-off writes the ambient term only where the material pass does not.
        config_.paths.ambient_target = had_target;
        if (!had_depth) targets_ = std::make_unique<RenderTargets>(config_.paths, config_.opts, width(), height());
        ProgramSet handoff(shader_dir_, config_, {"depth_copy", "depth_copy_ambient"});
        lighting_->set_handoff(config_, handoff);
    }
    forward_->set_scene(scene, *gpu_);
    if (shadows_) shadows_->set_scene(scene);
    emission_ = std::make_unique<EmissionPass>(shader_dir_, scene, *gpu_);
}

FrameDef DeferredShader::frame_of(const Camera& camera, const std::vector<Light>& lights, bool scissors) const {
    return make_frame(camera, lights, frame_setup(scissors));
}

FrameSetup DeferredShader::frame_setup(bool scissors) const {
    FrameSetup s;
    s.width = width();
    s.height = height();
    s.aspect = aspect();
    s.gbuffer_extent = targets_->gbuffer_extent();
    s.scissors = scissors;
    s.skip_empty = config_.opts.skip.empty_lights;
    s.shadows = shadows_ != nullptr;
    return s;
}

void DeferredShader::set_output_size(int out_w, int out_h) {
    out_aspect_ = out_w > 0 && out_h > 0 ? float(out_w) / float(out_h) : 0.0f;
}

GbufferClears DeferredShader::gbuffer_clears(bool material_writes_ambient) const {
    GbufferClears c;
    if (!config_.opts.skip.gbuffer_clears) return c;
    AmbientFacts a;  // the facts known before the geometry stage
    a.material_pass = material_writes_ambient;
    a.ssao = ssao_ != nullptr;
    a.handoff_program = lighting_->handoff_writes_ambient();
    a.emission = emission_ && emission_->needed() && targets_->accum_attachable();  // draw_lights' fact
    const Paths& p = config_.paths;
    c.diffuse = ambient_pass_possible(a, hands_off_depth(p.accum_depth, false, p.forward_stage, p.depth_bounds));
    c.specular = false;
    return c;
}

bool DeferredShader::skips_final(int out_w, int out_h) const {
    return config_.opts.skip.final_pass && read_back_ && out_w == width() && out_h == height() &&
           !config_.opts.hdr.float_accum() && !config_.opts.hdr.final_program();
}

FrameStats DeferredShader::render(const Scene& scene, int out_w, int out_h) {
    if (!gpu_) throw Error("DeferredShader::render before set_scene");
    FrameStats st;
    st.tiles.on = draws_tiles(config_.paths.light_geometry);
    const double cpu0 = thread_cpu_ms();
    timer_.begin_frame(S_COUNT);
    set_output_size(out_w, out_h);
    // The frame's camera first. The geometry stage needs nothing else, so the lights are culled
    // and their rectangles made (Listing 17) while the GPU fills the G-buffer, unless the shadow
    // stage needs them before it.
    const FrameSetup setup = frame_setup(config_.opts.scissor);
    FrameDef f = make_frame(scene.camera, {}, setup);
    const auto cull_lights = [&] {
        const double t0 = thread_cpu_ms();
        add_visible_lights(f, scene.lights, setup);
        st.ms.cpu_make_frame += thread_cpu_ms() - t0;
    };
    st.ms.cpu_make_frame = thread_cpu_ms() - cpu0;
    // 0. the shadow maps of the frame's shadowed lights, handed to the light passes in the frame.
    if (shadows_) {
        cull_lights();
        if (f.shadowed_lights > 0) timed(timer_, S_SHADOWS, [&] { f.shadows = shadows_->draw(f, scene, *gpu_, st.shadows); });
    }
    // 1. geometry stage, which also writes the ambient pass's colours into P-buffer 0 where it can
    // (Paths::ambient_target): the lighting stage then draws no ambient pass.
    const AmbientTerm ambient{scene.background, scene.ambient};
    const bool material_writes_ambient = targets_->ambient_target();
    gbuffer_clears_ = gbuffer_clears(material_writes_ambient);
    timed(timer_, S_GEOMETRY, [&] {
        geometry_->draw(f, *gpu_, *targets_, st, material_writes_ambient ? &ambient : nullptr, gbuffer_clears_);
    });
    if (!shadows_) {
        glFlush();  // the GPU starts on the G-buffer now, not when the light stage first waits on it
        cull_lights();
    }
    const double cpu_lights0 = thread_cpu_ms();
    draw_lights(f, scene, material_writes_ambient, st);                 // 2. lighting stage
    st.ms.cpu_lights = thread_cpu_ms() - cpu_lights0;
    draw_post(f);                                                       // 3. post-processing
    // 4. final stage, unless the caller reads P-buffer 0 itself at its own size (read_output): then
    // the fixed-function copy into the main frame buffer would give it the same bytes. Not with a
    // float P-buffer 0, nor where the final pass maps or encodes (docs/hdr.md).
    st.passes.final = !skips_final(out_w, out_h);
    if (st.passes.final) timed(timer_, S_FINAL, [&] { final_.draw(*targets_, out_w, out_h); });
    std::vector<double> ms;
    st.ms.cpu = thread_cpu_ms() - cpu0;
    st.ms.frame = timer_.end_frame(ms);
    st.ms.geometry = ms[S_GEOMETRY];
    st.ms.ambient = ms[S_AMBIENT];
    st.ms.lights = ms[S_LIGHTS];
    st.ms.bloom = ms[S_BLOOM];
    st.ms.aa = ms[S_AA];
    st.ms.final = ms[S_FINAL];
    st.ms.depth_copy = ms[S_DEPTH_COPY];
    st.ms.ssao = ms[S_SSAO];
    st.ms.forward = ms[S_FORWARD];
    st.ms.shadows = ms[S_SHADOWS];
    st.timing = timer_.source();
    check_gl("frame");  // per stage too with --debug-gl (check_gl_stage)
    return st;
}

// Listing 14, with SSAO before the ambient pass it scales, the depth hand-off before the light
// passes that test against it, and the forward stage after them, all into P-buffer 0. Which pass
// writes the ambient term is decided by ambient_writer.h; this draws what it says, in its order.
void DeferredShader::draw_lights(const FrameDef& f, const Scene& scene, bool material_wrote_ambient, FrameStats& st) {
    if (ssao_) timed(timer_, S_SSAO, [&] { ssao_->draw(f, *targets_); });
    // Where the material pass did not write the ambient term, emission and occlusion are added
    // after Listing 15's pass by the emission pass, which no other writer can stand in for (asked
    // before P-buffer 0 is bound: RenderTargets asks the G-buffer's framebuffer).
    const bool emission = !material_wrote_ambient && emission_ && emission_->needed() && targets_->accum_attachable();
    fb_bind_render(P_ACCUM);
    const int units[4] = {0, 1, 2, 3};
    const int gbuffer[4] = {G_NORMAL, G_DIFFUSE, G_SPECULAR, depth_target(config_.opts.depth)};
    const auto bind_gbuffer = [&] {
        for (int i = 0; i < 4; ++i) mrt_bind_texture(gbuffer[i], units[i]);  // mrt_bind_texture(ALL)
    };
    const auto unbind_gbuffer = [&] {
        for (int i = 3; i >= 0; --i) mrt_unbind_texture(gbuffer[i], units[i]);
    };
    const auto ambient_pass = [&] {  // binds its diffuse target on unit 0: the G-buffer is bound after it
        timer_.begin(S_AMBIENT);
        lighting_->draw_ambient(f, scene, *targets_, ssao_.get());
        check_gl_stage("lighting stage: ambient pass");
        if (emission) {
            fb_unbind_render(P_ACCUM);
            emission_->draw(f, *gpu_, *targets_);
            fb_bind_render(P_ACCUM);
        }
        timer_.end();
    };
    const AmbientTerm colours{scene.background, scene.ambient};
    const std::optional<size_t> full_light = full_screen_light(f);
    AmbientFacts facts;
    facts.material_pass = material_wrote_ambient;
    facts.ssao = ssao_ != nullptr;
    facts.fold_program = lighting_->fold_built();
    facts.geometry_draws_own = lighting_->geometry_writes_ambient();
    facts.has_lights = !f.lights.empty();
    facts.full_screen_light = full_light.has_value();
    facts.handoff_program = lighting_->handoff_writes_ambient();
    facts.plan_reads_back = lighting_->prepare_reads_back(f);
    facts.emission = emission;
    // Where nothing can take the ambient pass's place and the plan does not read back, it goes
    // first: the GPU draws it while the light geometry plans.
    const std::optional<AmbientWriter> early = ambient_before_plan(facts);
    if (early == AmbientWriter::pass_before_plan) ambient_pass();
    // The light geometry's plan for the frame (the auto geometry's depth spans, timed with the
    // light passes): whether its lights need the scene's depth decides the hand-off, and whether it
    // would draw the full-screen light by a pass of its own decides the fold.
    bool lights_need_depth = false;
    bind_gbuffer();
    timed(timer_, S_LIGHTS, [&] { lights_need_depth = lighting_->prepare(f, *targets_, st); });
    PlanFacts plan;
    plan.own_pass = full_light && lighting_->own_pass(*full_light);
    plan.hands_off =
        hands_off_depth(config_.paths.accum_depth, lights_need_depth, config_.paths.forward_stage, config_.paths.depth_bounds);
    const AmbientWriter writer = decide_ambient(facts, plan);
    st.passes.ambient = writer;
    // After the plan: where the plan reads back, the read-back waits for the G-buffer alone and the
    // GPU draws the ambient pass while the CPU plans the light draws (docs/gpu_frame.md, "The
    // ambient pass after the plan"); or where a fold
    // or a hand-off could have written it and did not.
    if (writer == AmbientWriter::pass_after_plan) {
        unbind_gbuffer();
        ambient_pass();
        bind_gbuffer();
        // Placed here for the read-back: handed to the GPU now, not with the first light batch.
        if (early == AmbientWriter::pass_after_plan) glFlush();
    }
    // The fold: the full-screen light's own pass, which the geometry then leaves out of its plan,
    // or the geometry's first batch; the geometry draws the frame's lights less the folded one.
    std::optional<AmbientFold> fold;
    if (writer == AmbientWriter::light_fold) {
        lighting_->drop(*full_light);
        fold = AmbientFold{*full_light, false, colours};
    } else if (writer == AmbientWriter::geometry_first_batch) {
        fold = AmbientFold{0, true, colours};
    }
    std::optional<FrameDef> rest;
    if (writer == AmbientWriter::light_fold) rest = without_light(f, fold->light);
    const FrameDef& lights = rest ? *rest : f;
    if (plan.hands_off) {
        timed(timer_, S_DEPTH_COPY, [&] {
            lighting_->hand_off_depth(f, *targets_, writer == AmbientWriter::handoff ? &colours : nullptr);
        });
        check_gl_stage("lighting stage: depth hand-off");
    }
    timer_.begin(S_LIGHTS);
    lighting_->draw_lighting(f, lights, *targets_, st, fold ? &*fold : nullptr);  // Listing 17
    unbind_gbuffer();
    check_gl_stage("lighting stage: light passes");
    if (config_.paths.forward_stage) {
        timer_.end();
        timer_.begin(S_FORWARD);
        forward_->draw(f, scene, *gpu_, st.forward);
        check_gl_stage("forward stage");
    }
    fb_unbind_render(P_ACCUM);
    timer_.end();
}

void DeferredShader::draw_post(const FrameDef& f) {
    if (post_->bloom()) timed(timer_, S_BLOOM, [&] { post_->draw_bloom(*targets_); });
    if (post_->anti_alias()) timed(timer_, S_AA, [&] { post_->draw_anti_alias(f, *targets_); });
}

// --- one stage at a time -------------------------------------------------------------------
void DeferredShader::geometry_stage(const Scene& scene) {
    if (!gpu_) throw Error("DeferredShader::geometry_stage before set_scene");
    FrameStats st;
    geometry_->draw(frame_of(scene.camera), *gpu_, *targets_, st);
}

void DeferredShader::draw_lights(const Scene& scene, bool scissors, FrameStats& stats) {
    FrameDef f = frame_of(scene.camera, scene.lights, scissors);
    if (shadows_ && f.shadowed_lights > 0) f.shadows = shadows_->draw(f, scene, *gpu_, stats.shadows);
    draw_lights(f, scene, false, stats);  // geometry_stage() leaves P-buffer 0 alone: the ambient pass runs
}

void DeferredShader::post_stage(const Camera& camera) { draw_post(frame_of(camera)); }
void DeferredShader::final_stage(int out_w, int out_h) { final_.draw(*targets_, out_w, out_h); }
void DeferredShader::blur(int src, int dst, glm::vec2 dir, bool select) { post_->blur(*targets_, src, dst, dir, select); }
void DeferredShader::draw_bloom() { post_->draw_bloom(*targets_); }
void DeferredShader::draw_anti_alias(const Camera& camera, bool factor_only) {
    post_->draw_anti_alias(frame_of(camera), *targets_, factor_only);
}

// --- read-back -----------------------------------------------------------------------------
Image DeferredShader::read_gbuffer(int target) {
    const PBuffer& g = targets_->gbuffer();
    return read_texture(g.texture(target), width(), height(), g.texture_width(), g.texture_height(),
                        target == PBuffer::DEPTH);
}

std::vector<uint32_t> DeferredShader::read_gbuffer_depth_codes() {
    if (config_.opts.depth != DepthPath::texture)
        throw Error(std::string("read_gbuffer_depth_codes: the ") + depth_path_name(config_.opts.depth) +
                    " path has no depth texture");
    const PBuffer& g = targets_->gbuffer();
    return read_depth_codes(g.texture(PBuffer::DEPTH), width(), height(), g.texture_width(), g.texture_height());
}

Image DeferredShader::reconstructed_positions(const Camera& camera) {
    return lighting_->reconstructed_positions(frame_of(camera), *targets_);
}

Image DeferredShader::read_output(int out_w, int out_h) {
    if (!skips_final(out_w, out_h)) return read_pixels(out_w, out_h);
    const PBuffer& b = targets_->pbuffer(P_ACCUM);
    return read_texture_rgba8(b.texture(0), b.width(), b.height(), b.texture_width(), b.texture_height());
}

Image DeferredShader::read_output_linear(int out_w, int out_h) const { return final_.read_linear(*targets_, out_w, out_h); }

Image DeferredShader::read_pbuffer(int fb) {
    const PBuffer& b = targets_->pbuffer(fb);
    return read_texture(b.texture(0), b.width(), b.height(), b.texture_width(), b.texture_height(), false);
}

}  // namespace dsr
