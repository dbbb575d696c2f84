// The tutorial's pDeferredShader (§3, Appendix A): the G-buffer and four P-buffers (Listing 6),
// and the frame in Appendix A's order. Each stage is a part of its own that owns its programs and
// buffers; DeferredShader chooses the paths, holds the targets and the stages, builds each
// frame's values (frame.h) and hands them down, and times the stages:
//   geometry_stage.h  §3.3  depth pre-pass (Listing 8) + material pass (Listings 9-13)
//   ssao_stage.h            ambient occlusion for the ambient pass (docs/ssao.md)
//   lighting_stage.h  §3.4  ambient pass (Listing 15) + the light geometry (light_geometry.h)
//   forward_stage.h         markers and transparent surfaces after the lights (docs/forward.md)
//   post_stage.h      §3.5  bloom (Listing 22) then anti-alias (Listing 21, Equation 7)
//   final_stage.h     §3.6  P-buffer 0 to the main frame buffer, fixed function
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "deferred/final_stage.h"
#include "deferred/frame.h"
#include "deferred/frame_stats.h"
#include "deferred/render_targets.h"
#include "deferred/shader_table.h"
#include "deferred/view_names.h"
#include "gl/frame_timer.h"
#include "scene/image.h"
#include "scene/scene.h"

namespace dsr {

class GpuScene;
class GeometryStage;
class SsaoStage;
class LightingStage;
class ForwardStage;
class PostStage;
class ShadowStage;
class EmissionPass;

class DeferredShader {
public:
    // width x height: the deferred buffers. Needs an OpenGL context current; compiles every program
    // of the shader table this configuration uses. Throws dsr::Error naming a missing capability.
    DeferredShader(const Caps& caps, int width, int height, const ShaderOptions& opts, const std::string& shader_dir);
    ~DeferredShader();
    // Counting the light passes' fragments (LightingStage::set_counting); on by default.
    void set_counting(bool on);
    // Reallocates the G-buffer and P-buffers at the new size; no shader is recompiled.
    void resize(int width, int height);
    void set_scene(const Scene& scene);
    // The whole pipeline (Appendix A) into the current main frame buffer of out_w x out_h; the
    // projection takes the output's aspect (set_output_size), whatever the buffers' size.
    FrameStats render(const Scene& scene, int out_w, int out_h);
    // The caller reads each frame back with read_output and shows it in no window (a headless
    // render, the bench): where the output is the buffers' own size and P-buffer 0 is RGBA8, the
    // final pass (§3.6) is then skipped (SkipOptions::final_pass) and read_output reads P-buffer 0.
    // Off by default: the final pass draws into the main frame buffer, which a window shows.
    void set_read_back(bool on) { read_back_ = on; }
    // The last frame's image as the main frame buffer would hold it after the final pass, out_w x
    // out_h (render()'s): read from P-buffer 0 where render() left the final pass out at that size
    // (skips_final), else read_pixels.
    Image read_output(int out_w, int out_h);
    // The same frame without the 8-bit main frame buffer: P-buffer 0 as float after the final
    // stage's exposure, unclamped (FinalStage::read_linear), for float image files.
    Image read_output_linear(int out_w, int out_h) const;
    // The main frame buffer's size the frames are projected for (§3.6): its aspect is the
    // projection's, so an image scaled to it keeps its proportions. render() sets it; before
    // any, the buffers' aspect. For the one-stage API below.
    void set_output_size(int out_w, int out_h);

    // Appendix A's stages one by one (tests, figures), each on the frame of the camera handed in
    // (the scene's): the shader keeps no frame between calls.
    void geometry_stage(const Scene& scene);
    // Listing 14: the lighting stage (with SSAO, the depth hand-off and the forward stage).
    void draw_lights(const Scene& scene, bool scissors, FrameStats& stats);
    void post_stage(const Camera& camera);
    void final_stage(int out_w, int out_h);
    // After render() of a frame seen by `camera`: replaces the main frame buffer's image with
    // `view` (draw_view.cpp).
    void draw_view(View view, const Camera& camera, int out_w, int out_h);
    // Post-processing passes, for the figures (Figure 10 shows them one by one); post_stage.h.
    void blur(int src, int dst, glm::vec2 dir, bool select);
    void draw_bloom();
    void draw_anti_alias(const Camera& camera, bool factor_only = false);

    // High dynamic range (docs/hdr.md): the exposure scale the last final pass applied (1 on the
    // fixed-function path), and P-buffer 0's luminance reduced to (mean log2, max) per block
    // (FinalStage::reduce_luminance; empty without the log_luminance program), after render().
    float exposure_scale() const { return final_.exposure_scale(); }
    std::vector<glm::vec2> reduce_luminance() { return final_.reduce_luminance(*targets_); }

    // Read-back (views and tests): a G-buffer target or its depth texture (PBuffer::DEPTH, grey).
    Image read_gbuffer(int target);
    // The depth texture's raw GL_UNSIGNED_INT codes (24-bit depth in the high bits), w x h, row 0
    // at the bottom. After geometry_stage, on the depth-texture path only (throws otherwise).
    std::vector<uint32_t> read_gbuffer_depth_codes();
    // After geometry_stage of a frame seen by `camera`: LightingStage::reconstructed_positions.
    Image reconstructed_positions(const Camera& camera);
    Image read_pbuffer(int fb);
    int pbuffer_width(int fb) const { return targets_->pbuffer(fb).width(); }
    int pbuffer_height(int fb) const { return targets_->pbuffer(fb).height(); }
    int width() const { return targets_->width(); }
    int height() const { return targets_->height(); }
    // The options as run: depth `automatic` resolved by choose_paths.
    const ShaderOptions& options() const { return config_.opts; }
    const Paths& paths() const { return config_.paths; }
    // The projection a frame seen by `camera` takes (its view matrix: camera.view()).
    glm::mat4 proj_matrix(const Camera& camera) const { return camera.projection(aspect()); }
    // The projection's aspect: the output's (set_output_size), else the buffers'.
    float aspect() const { return out_aspect_ > 0 ? out_aspect_ : float(width()) / float(height()); }

    // Listing 6: G-buffer and P-buffer management.
    void mrt_bind_render() { targets_->mrt_bind_render(); }
    void mrt_unbind_render() { targets_->mrt_unbind_render(); }
    void mrt_bind_texture(int target, int unit) { targets_->mrt_bind_texture(target, unit); }
    void mrt_unbind_texture(int target, int unit) { targets_->mrt_unbind_texture(target, unit); }
    void fb_bind_render(int b) { targets_->fb_bind_render(b); }
    void fb_unbind_render(int b) { targets_->fb_unbind_render(b); }
    void fb_bind_texture(int b, int unit) { targets_->fb_bind_texture(b, unit); }
    void fb_unbind_texture(int b, int unit) { targets_->fb_unbind_texture(b, unit); }

private:
    // Stage slots of the frame timer, in StageTimes order.
    enum Slot { S_GEOMETRY, S_AMBIENT, S_LIGHTS, S_BLOOM, S_AA, S_FINAL, S_DEPTH_COPY, S_SSAO, S_FORWARD, S_SHADOWS, S_COUNT };
    FrameSetup frame_setup(bool scissors) const;
    FrameDef frame_of(const Camera& camera, const std::vector<Light>& lights, bool scissors) const;
    FrameDef frame_of(const Camera& camera) const { return frame_of(camera, {}, true); }  // no lights
    // Whether render() at out_w x out_h leaves the final pass out (set_read_back).
    bool skips_final(int out_w, int out_h) const;
    // The G-buffer's colour clears this frame needs (SkipOptions::gbuffer_clears).
    GbufferClears gbuffer_clears(bool material_writes_ambient) const;
    // `material_wrote_ambient`: the geometry stage's material pass wrote the ambient term.
    void draw_lights(const FrameDef& f, const Scene& scene, bool material_wrote_ambient, FrameStats& stats);
    void draw_post(const FrameDef& f);

    ShaderConfig config_;  // capabilities, options as run, paths chosen
    std::string shader_dir_;
    std::unique_ptr<RenderTargets> targets_;  // G-buffer and P-buffers 0-3
    std::unique_ptr<GpuScene> gpu_;
    std::unique_ptr<ShadowStage> shadows_;  // scenes with shadowed lights (ShaderOptions::shadow_lights)
    std::unique_ptr<GeometryStage> geometry_;
    std::unique_ptr<SsaoStage> ssao_;  // with --ssao
    std::unique_ptr<LightingStage> lighting_;
    std::unique_ptr<EmissionPass> emission_;  // the scene's emission and occlusion (emission_pass.h)
    bool counting_ = true;  // set_counting's, kept for a lighting stage built again by set_scene
    std::unique_ptr<ForwardStage> forward_;
    std::unique_ptr<PostStage> post_;
    FinalStage final_;
    FrameTimer timer_;
    float out_aspect_ = 0;  // set_output_size's width / height; 0: the buffers'
    bool read_back_ = false;  // set_read_back
    GbufferClears gbuffer_clears_;  // the last geometry stage's: the G-buffer views need every one
};

}  // namespace dsr
