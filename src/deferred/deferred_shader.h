// The tutorial's pDeferredShader (§3, Appendix A): one G-buffer, four P-buffers, and the
// stages that fill and consume them. One .cpp per stage:
//   geometry_stage.cpp  §3.3  depth pre-pass (L8) + material pass (L9-13)
//   lighting_stage.cpp  §3.4  ambient pass (L15) + one scissored quad per light (L16-20)
//   ssao_stage.cpp      issue 13 / Vasilovici §5: ambient occlusion for the ambient pass
//   post_stage.cpp      §3.5  bloom (L22) then anti-alias (L21, Eq. 7) on the P-buffers
//   final_stage.cpp     §3.6  P-buffer 0 to the main frame buffer, fixed function
#pragma once
#include <memory>
#include <optional>
#include <tuple>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <map>

#include "deferred/depth_codec.h"
#include "deferred/options.h"
#include "deferred/paths.h"
#include "deferred/render_targets.h"
#include "deferred/light_params.h"
#include "deferred/light_volume.h"
#include "deferred/scissor.h"
#include "deferred/tile_plan.h"
#include "deferred/view.h"
#include "gl/caps.h"
#include "gl/frame_timer.h"
#include "gl/pbuffer.h"
#include "gl/program.h"
#include "gl/state.h"
#include "gl/stream_buffer.h"
#include "scene/bounds.h"
#include "scene/image.h"
#include "scene/scene.h"

namespace dsr {

class GpuScene;
struct GpuMaterial;
class TransparentPass;

// Per-stage time of one frame, in milliseconds, from the FrameTimer (gl/frame_timer.h):
// GPU timer queries or glFinish + wall clock, as `timing` says. `frame` is always the wall
// time of render() until the GPU finished.
struct StageTimes {
    double geometry = 0, ambient = 0, lights = 0, bloom = 0, aa = 0, final = 0, frame = 0;
    double ssao = 0;        // the SSAO pass and its blur (0 with --ssao off)
    double depth_copy = 0;  // hand_off_depth: the G-buffer's depth onto P-buffer 0 (0 where not needed)
    double forward = 0;     // forward_stage: light markers and transparent surfaces (0 where not run)
    // CPU time of the rendering thread from the start of render() to its end-of-frame wait: the
    // submission cost (draw calls, state, uniforms). With glFinish-timed stages (llvmpipe) the
    // waits in between are in it as far as they spin; with timer queries (a GPU) they are not there.
    double cpu = 0;
};

struct FrameStats {
    int lights_total = 0, lights_culled = 0, lights_drawn = 0;
    long long light_fragments = 0;  // samples that passed the light passes (occlusion queries): what
                                    // survived the in-shader light tests; 0 and not counted when
                                    // fragments_counted is false (no occlusion queries)
    bool fragments_counted = false;
    // Fragments that entered the light shader, summed over the light passes (ARB_pipeline_
    // statistics_query, GL_FRAGMENT_SHADER_INVOCATIONS_ARB): what the passes pay, discards
    // included. Null where the GL lacks the extension, never 0 for "not counted".
    std::optional<long long> light_invocations;
    // light_fragments as an optional: null where it was not counted.
    std::optional<long long> counted_light_fragments() const {
        return fragments_counted ? std::optional<long long>(light_fragments) : std::nullopt;
    }
    long long scissor_pixels = 0;   // sum of the rectangles the light quads were limited to
    // Light geometry (issue 12): the passes drawn (one per light; tiles: one per tile and group
    // of lights), the lights the volume and stencil geometries drew as quads because their mesh
    // reaches past the far plane, where its back faces would be clipped away.
    int light_passes = 0;
    int lights_as_quads = 0;
    long long tile_light_pairs = 0;  // tiles: (tile, light) pairs its plan shaded (tile_plan.h)
    bool tile_depth = false;         // tiles: the plan culled by the tiles' depth spans (tile_depth.cpp)
    // tiles, wall clock inside the light stage: the depth spans' two passes and read-back (which
    // waits for the G-buffer: on a GPU, a pipeline drain), and the plan with its vertices' upload.
    double tile_depth_ms = 0, tile_plan_ms = 0;
    // The forward stage (issue 13): markers drawn, transparent objects blended and their draws.
    int light_markers = 0;
    int transparent_objects = 0;
    int transparent_passes = 0;
    StageTimes ms;
    TimingSource timing = TimingSource::wall;
};

// One material program of the shader table (Listing 9's variants).
struct MaterialKey {
    bool normal_map = false;   // tangent-space normal map read (NORMAL_MAP)
    bool no_specular = false;  // specular target written as zero, no map read (NO_SPECULAR)
    int target = -1;           // -1: every target in one pass (MRT); t: only G-buffer target t
    bool operator<(const MaterialKey& o) const {
        return std::tie(normal_map, no_specular, target) < std::tie(o.normal_map, o.no_specular, o.target);
    }
};

class DeferredShader {
public:
    // width x height: the deferred buffers (G-buffer and P-buffers). Needs an OpenGL
    // context current. Throws dsr::Error naming a missing capability (choose_paths' refusal).
    DeferredShader(const Caps& caps, int width, int height, const ShaderOptions& opts,
                   const std::string& shader_dir);
    ~DeferredShader();
    // Counting (light_fragments, light_invocations): two queries around every light draw. On by
    // default; the bench turns it off for its timed frames (on a GPU at 1024 lights the queries
    // were most of the CPU's frame) and counts in one more frame after them.
    void set_counting(bool on) { counting_ = on; }
    // Reallocates the G-buffer and P-buffers at the new size; no shader is recompiled.
    void resize(int width, int height);

    void set_scene(const Scene& scene);
    // The whole pipeline (Appendix A) into the current main frame buffer of out_w x out_h.
    FrameStats render(const Scene& scene, int out_w, int out_h);

    // Appendix A stages, public so tests and figures can run them one by one.
    void geometry_stage(const Scene& scene);
    void draw_lights(const Scene& scene, bool scissors, FrameStats& stats);
    // Issue 13, forward_stage.cpp: after the light passes, into P-buffer 0 (bound, its depth handed
    // off): light markers (--show-lights), then transparent surfaces back to front.
    void forward_stage(const Scene& scene, FrameStats& stats);
    void post_stage(FrameStats& stats);
    void final_stage(int out_w, int out_h);
    // Any texture drawn into the main frame buffer the way the final stage draws P-buffer 0
    // (fixed function, bilinear when scaled): how `--view` shows the other buffers.
    void draw_texture_to_main(GLuint texture, int out_w, int out_h, glm::vec2 tex_scale = {1, 1});
    // After render(): replaces the main frame buffer's image with `view` (views.cpp).
    // Depth is shown encoded as colour (Figure 4d) on every depth path (the position paths' eye z
    // mapped to window depth first).
    void draw_view(View view, int out_w, int out_h);

    // Post-processing passes, public for the figures (Figure 10 shows them one by one).
    // blur: Listing 22 from P-buffer `src` into `dst` along `dir` (1,0) or (0,1); `select`
    // applies the bright-pass weighting of the first bloom pass.
    void blur(int src, int dst, glm::vec2 dir, bool select);  // P-buffer roles (PRole)
    void draw_bloom();
    void draw_anti_alias(bool factor_only = false);
    // The depth hand-off (depth_handoff.cpp): writes the G-buffer's depth into the depth buffer of
    // the bound P-buffer 0 (texture path: copied; packed: decoded from the packed target) and
    // clears its stencil, so passes drawn into P-buffer 0 can depth-test against the scene without
    // sampling a texture attached to the framebuffer they draw into. After geometry_stage, with
    // P-buffer 0 bound for rendering; needs paths().accum_depth (or the copy path's main buffer).
    // The light geometries use it; so can a forward pass after the lights.
    void hand_off_depth();
    // SSAO (ssao_stage.cpp, issue 13): occlusion from the G-buffer into the AO buffer, then the
    // depth-aware blur into the blurred AO buffer (render_targets.h). After geometry_stage.
    void draw_ssao();

    // Read a buffer back (views and tests): a G-buffer target, its depth texture
    // (PBuffer::DEPTH, as grey), or P-buffer `fb`.
    Image read_gbuffer(int target);
    // After geometry_stage, on the depth-texture path: the G-buffer's depth texture as its raw
    // GL_UNSIGNED_INT codes (24-bit depth in the high bits: window depth = code / (2^32 - 1)),
    // w x h, row 0 at the bottom; no float rounding on the way. Throws on the packed path.
    std::vector<uint32_t> read_gbuffer_depth_codes();
    // After geometry_stage: the eye-space position each pixel's depth reconstructs to, exactly as
    // the light pass computes it (same decoder, planes and view rays), in float: rgb = (x, y, z),
    // alpha 1 where the G-buffer has a surface, 0 elsewhere.
    Image reconstructed_positions();
    Image read_pbuffer(int fb);
    int pbuffer_width(int fb) const { return targets_->pbuffer(fb).width(); }
    int pbuffer_height(int fb) const { return targets_->pbuffer(fb).height(); }
    GLuint pbuffer_texture(int fb) const { return targets_->pbuffer(fb).texture(0); }

    int width() const { return targets_->width(); }
    int height() const { return targets_->height(); }
    // The options as run: depth `automatic` resolved by choose_paths.
    const ShaderOptions& options() const { return opts_; }
    TimingSource timing() const { return timer_.source(); }
    const Paths& paths() const { return paths_; }
    // Eye-space camera of the current frame.
    const glm::mat4& view_matrix() const { return view_; }
    const glm::mat4& proj_matrix() const { return proj_; }

    // Listing 6: G-buffer and P-buffer management.
    void mrt_bind_render();
    void mrt_unbind_render();
    void mrt_bind_texture(int target, int unit);
    void mrt_unbind_texture(int target, int unit);
    void fb_bind_render(int buffer);
    void fb_unbind_render(int buffer);
    void fb_bind_texture(int buffer, int unit);
    void fb_unbind_texture(int buffer, int unit);

private:
    // Stage slots of the frame timer, in StageTimes order.
    enum Slot { S_GEOMETRY, S_AMBIENT, S_LIGHTS, S_BLOOM, S_AA, S_FINAL, S_DEPTH_COPY, S_SSAO, S_FORWARD, S_COUNT };
    // Each pass's fixed-function state (gl/state.h), declared in its stage's file.
    static RenderState depth_pass_state();
    static RenderState material_pass_state();
    static RenderState ambient_pass_state();
    static RenderState light_pass_state(GLuint program, bool scissor);
    void draw_depth();
    void draw_material(int target);
    void draw_ambient(const Scene& scene);
    // With SSAO on: P-buffer 0 (the ambient pass's image, bound) multiplied by the blurred AO
    // buffer, fixed function (ssao_stage.cpp).
    void modulate_ambient_by_ssao();
    void build_ssao_programs();
    void set_ssao_ortho();
    void begin_ssao_pass(PBuffer& target, Program& prog);
    void draw_lighting(const Scene& scene, bool scissors, FrameStats& stats);
    void draw_light_markers(const Scene& scene, FrameStats& stats);
    // The programs and buffers the paths need for the depth hand-off (the gl_FragDepth pass).
    void build_depth_handoff();
    // One visible light of the frame: its shader parameters, eye-space volume and scissor rectangle.
    struct LightDraw {
        const Light* light;
        LightParams params;
        LightVolume eye;   // light_volume.h, in eye space
        ScissorRect rect;  // the whole viewport when `full`
        bool full;
    };
    std::vector<LightDraw> visible_lights(const Scene& scene, bool scissors, FrameStats& stats);
    std::vector<LightDraw> frame_lights_;  // this frame's visible_lights (draw_lighting; the forward stage reads them)
    void set_light_uniforms(Program& prog);
    static void set_light_params(Program& prog, const LightParams& lp);
    // One file per geometry (light_geometry_*.cpp).
    void draw_lights_quad(const std::vector<LightDraw>& lights, FrameStats& stats);
    void draw_lights_volume(const std::vector<LightDraw>& lights, FrameStats& stats);
    void draw_lights_stencil(const std::vector<LightDraw>& lights, FrameStats& stats);
    void begin_light_meshes(const std::vector<LightDraw>& lights, class LightQueries& q, FrameStats& stats);
    void draw_light_mesh_pass(const LightDraw& l, class LightQueries& q, Program& prog);
    void end_light_meshes(class LightQueries& q, FrameStats& stats);
    void draw_lights_tiles(const std::vector<LightDraw>& lights, FrameStats& stats);
    // The light's quad over its scissor rectangle (Listing 16): quad geometry, and the volume
    // geometries' lights whose mesh the far plane would clip.
    void draw_light_quad(const LightDraw& l, class LightQueries& q);
    // A light's volume mesh (light_volume.h volume_mesh), in eye space: spheres as the unit
    // sphere's mesh scaled and moved by the model-view, cones as their own mesh.
    void draw_light_mesh(const LightDraw& l);
    // Lights the volume geometries draw as quads: directional (full screen, no mesh) and volumes
    // whose mesh reaches past the far plane, where its back faces would be clipped away.
    bool mesh_past_far(const LightDraw& l) const;
    void build_volume_mesh();
    // Screen-aligned quad over [x0,x1]x[y0,y1] (window pixels), texcoord 0 = 0..1;
    // with rays, texcoord 1 = eye-space view ray of each corner (Listing 19).
    void draw_rect(float x0, float y0, float x1, float y1, bool rays);
    // The eye-space view ray (x, y, -1) at window position (x, y): bilinear in the corner rays.
    glm::vec3 view_ray_at(float x, float y) const;
    // The view ray's affine map of window coordinates, as the light shaders take it from
    // gl_FragCoord: (x, y) = window.xy * ray_map.xy + ray_map.zw, z = -1.
    glm::vec4 ray_map() const;
    // G-buffer texture coordinates per window pixel (its textures may be padded to powers of two).
    glm::vec2 gbuffer_uv_scale() const;
    void set_ortho(int w, int h);
    // Shader defines of the depth path and packed encoding (glsl120/depth_codec.glsl).
    std::vector<std::string> depth_defines() const;
    // The G-buffer target the passes read eye z or position from (surface_eye_z / surface_eye_pos).
    int depth_target() const { return opts_.depth == DepthPath::texture ? PBuffer::DEPTH : G_DEPTH_PACKED; }
    // The material program a material draws with into `target` (-1: all, MRT).
    Program& material_program(const GpuMaterial& m, int target);
    PBuffer& gbuf() { return targets_->gbuffer(); }
    const PBuffer& gbuf() const { return targets_->gbuffer(); }
    PBuffer& pbuf(int role) { return targets_->pbuffer(role); }

    Caps caps_;
    int w_, h_;
    ShaderOptions opts_;
    Paths paths_;
    std::unique_ptr<RenderTargets> targets_;  // G-buffer and P-buffers 0-3
    std::map<MaterialKey, Program> material_progs_;
    Program position_prog_;             // light.frag with OUTPUT_POSITION, built on first use
    std::unique_ptr<PBuffer> position_buf_;
    std::string shader_dir_;
    glm::vec3 zrange_{0};
    // The light pass (light.frag): light_prog_ for the tutorial's point lights with Equation 2
    // (LIGHT_POINT_ONLY: no type or law selection, the tutorial's cost), light_any_prog_ for spot,
    // directional and attenuated lights (lighting.glsl light_contribution).
    Program light_prog_;
    Program light_any_prog_;
    static bool tutorial_light(const Light& l) { return l.type == Light::Type::point && !l.attenuation; }
    Program light_volume_prog_;         // light.vert/.frag with VOLUME (any type): drawn over the volume mesh
    Program light_stencil_prog_;        // the same without the in-shader light tests: stencil's light pass
    Program light_tiles_prog_;          // light_tiles.frag: up to tile_lights lights per pass (LIGHT_POINT_ONLY)
    Program light_tiles_any_prog_;      // the same for frames with spot, directional or attenuated lights
    int tile_batch_ = 0;                // lights light_tiles.frag holds in its uniform arrays
    float tile_round_ = 0.5f;           // light_tiles.frag's quantize_round (gl/rounding_probe.h)
    Program tile_depth_prog_;           // tile_depth.frag: each tile's span of surface eye z (tile_depth.cpp)
    Program tile_reduce_prog_;          // tile_depth_reduce.frag: a tile's rows together
    std::unique_ptr<PBuffer> tile_depth_rows_;  // RGBA32F: a texel per tile column and window row
    std::unique_ptr<PBuffer> tile_depth_buf_;   // RGBA32F: a texel per tile, read back
    std::vector<std::unique_ptr<StreamBuffer>> tile_vertices_;  // each batch's tile quads (light_geometry_tiles.cpp)
    std::vector<float> tile_verts_;     // their CPU copy, kept for its storage
    void make_tile_depth_buf();
    std::vector<DepthSpan> tile_depth_spans();
    Program depth_copy_prog_;           // depth_copy.frag: the depth hand-off
    Program ssao_prog_;                 // ssao.frag (with --ssao)
    Program ssao_blur_prog_;            // ssao_blur.frag (with --ssao)
    VolumeMesh unit_sphere_mesh_;       // volume_mesh of the unit sphere at the origin
    float volume_mesh_reach_ = 1;       // its farthest vertex from the centre
    int light_passes_drawn_ = 0;
    bool counting_ = true;              // set_counting        // this frame's light-shader draws (FrameStats::light_passes)
    Program blur_prog_[2];              // [select]
    Program aa_prog_[2];                // [factor only]
    std::unique_ptr<GpuScene> gpu_;
    std::vector<ObjectBounds> bounds_;                   // object_bounds(scene), set_scene
    std::unique_ptr<TransparentPass> transparent_;  // scenes with transparent materials
    Mesh marker_mesh_;                                   // --show-lights: the unit sphere
    glm::mat4 view_{1}, proj_{1};
    glm::vec2 planes_{0};
    glm::vec3 corner_rays_[4];
    FrameTimer timer_;
};

}  // namespace dsr
