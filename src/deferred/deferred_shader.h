// The tutorial's pDeferredShader (§3, Appendix A): one G-buffer, four P-buffers, and the
// stages that fill and consume them. One .cpp per stage:
//   geometry_stage.cpp  §3.3  depth pre-pass (L8) + material pass (L9-13)
//   lighting_stage.cpp  §3.4  ambient pass (L15) + one scissored quad per light (L16-20)
//   post_stage.cpp      §3.5  bloom (L22) then anti-alias (L21, Eq. 7) on the P-buffers
//   final_stage.cpp     §3.6  P-buffer 0 to the main frame buffer, fixed function
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "deferred/depth_codec.h"
#include "gl/caps.h"
#include "gl/pbuffer.h"
#include "gl/program.h"
#include "scene/image.h"
#include "scene/scene.h"

namespace dsr {

class GpuScene;

enum class DepthPath { texture, packed };

enum class AaSource { normal, depth, both };
enum class AaKernel { text, listing };

// Post-processing (§3.5). Defaults are the tutorial's: a 7-tap separable blur at half size.
struct PostOptions {
    bool bloom = false;
    int bloom_scale = 2;           // P-buffers 2 and 3 at 1/2 or 1/4 of the frame (§3.5.2)
    int bloom_taps = 7;            // NUMPOINTS of Listing 22 (odd, 3..15)
    float bloom_strength = 1.0f;   // weight of the fixed-function add into P-buffer 0
    bool bloom_listing = false;    // Listing 22's grey dot(t,t) in both passes; default keeps colour
    bool aa = false;
    AaSource aa_source = AaSource::normal;  // Eq. 7 over the normal target, depth, or both
    AaKernel aa_kernel = AaKernel::text;    // text: all 8 neighbours; listing: Listing 21's table
    float aa_weight = 1.0f;        // Listing 21's `weight`: largest offset, in pixels
    float aa_depth_scale = 4.0f;   // relative eye-z step that counts as an edge: ((dz/z)*scale)^2
};

// Work a scene does not need, skipped (each on by default; bench measures each).
struct SkipOptions {
    bool material_variants = true;  // no normal map: no tangent-space work; no specular: no specular map read
    bool empty_lights = true;       // lights with zero colour or an empty scissor rectangle are not drawn
    bool light_depth_test = true;   // per light, pixels whose surface lies in front of or behind the
                                    // light's sphere (or is background) are rejected before shading
    bool light_sphere_test = true;  // then pixels whose surface point is outside the sphere (att = 0):
                                    // rejected after one depth fetch, before the G-buffer reads
};

struct ShaderOptions {
    DepthPath depth = DepthPath::texture;
    DepthEncoding encoding = DepthEncoding::corrected;  // what the packed target holds
    bool listing2_literal = false;  // Listing 2's v and h exactly; default: Equations 1-5
    bool scissor = true;            // §3.4.2 light scissor rectangles
    PostOptions post;
    SkipOptions skip;
    bool float_accum = false;       // P-buffer 0 as RGBA32F (stress tests: NaN/Inf survive)
    // G-buffer target precision: the tutorial's RGBA8 everywhere (Figure 3), or half-float
    // targets (ARB_texture_float + ARB_half_float_pixel) where 8-bit normals are the largest
    // error of the deferred image.
    bool gbuffer_half = false;
};

// Per-stage wall time of one frame, in milliseconds (glFinish after each stage).
struct StageTimes {
    double geometry = 0, ambient = 0, lights = 0, bloom = 0, aa = 0, final = 0, frame = 0;
};

// The path taken at each capability decision (issue: old GL 2.x hardware paths).
struct Paths {
    std::string depth;          // "texture" | "packed"
    std::string gbuffer;        // "mrt" (one pass, ARB_draw_buffers) | "per-target" (one pass per target)
    std::string render_target;  // "fbo" (EXT_framebuffer_object) | "copy" (main buffer + glCopyTexSubImage2D)
    std::string textures;       // "npot" | "pow2" (padded targets, rescaled material maps)
};

struct FrameStats {
    int lights_total = 0, lights_culled = 0, lights_drawn = 0;
    long long light_fragments = 0;  // fragments the light passes shaded (occlusion queries; with the
                                    // light depth test, those that passed it)
    long long scissor_pixels = 0;   // sum of the rectangles the light quads were limited to
    StageTimes ms;
};

// What `--view` shows (the same names in every interface): the final image, a G-buffer
// target (Figure 4), the anti-alias blur factor (Figure 8) or the bloom blur (Figure 10c).
enum class View { final, normal, diffuse, specular, depth, blur_factor, bloom };
// "final", "normal", …, "blur-factor", "bloom"; throws dsr::Error listing the names otherwise.
View view_from_name(const std::string& name);
const char* view_name(View v);

// G-buffer targets (Figure 3).
enum GTarget { G_NORMAL = 0, G_DIFFUSE = 1, G_SPECULAR = 2, G_DEPTH_PACKED = 3 };

class DeferredShader {
public:
    // width x height: the deferred buffers (G-buffer and P-buffers). Needs an OpenGL
    // context current. Throws dsr::Error naming a missing capability.
    DeferredShader(const Caps& caps, int width, int height, const ShaderOptions& opts,
                   const std::string& shader_dir);
    ~DeferredShader();

    void set_scene(const Scene& scene);
    // The whole pipeline (Appendix A) into the current main frame buffer of out_w x out_h.
    FrameStats render(const Scene& scene, int out_w, int out_h);

    // Appendix A stages, public so tests and figures can run them one by one.
    void geometry_stage(const Scene& scene);
    void draw_lights(const Scene& scene, bool scissors, FrameStats& stats);
    void post_stage(FrameStats& stats);
    void final_stage(int out_w, int out_h);
    // Any texture drawn into the main frame buffer the way the final stage draws P-buffer 0
    // (fixed function, bilinear when scaled): how `--view` shows the other buffers.
    void draw_texture_to_main(GLuint texture, int out_w, int out_h, glm::vec2 tex_scale = {1, 1});
    // After render(): replaces the main frame buffer's image with `view` (views.cpp).
    // Depth is shown encoded as colour (Figure 4d) on both depth paths.
    void draw_view(View view, int out_w, int out_h);

    // Post-processing passes, public for the figures (Figure 10 shows them one by one).
    // blur: Listing 22 from P-buffer `src` into `dst` along `dir` (1,0) or (0,1); `select`
    // applies the bright-pass weighting of the first bloom pass.
    void blur(int src, int dst, glm::vec2 dir, bool select);
    void draw_bloom();
    void draw_anti_alias(bool factor_only = false);

    // Read a buffer back (views and tests): a G-buffer target, its depth texture
    // (PBuffer::DEPTH, as grey), or P-buffer `fb`.
    Image read_gbuffer(int target);
    // After geometry_stage: the eye-space position each pixel's depth reconstructs to, exactly as
    // the light pass computes it (same decoder, planes and view rays), in float: rgb = (x, y, z),
    // alpha 1 where the G-buffer has a surface, 0 elsewhere.
    Image reconstructed_positions();
    Image read_pbuffer(int fb);
    int pbuffer_width(int fb) const { return fb_[fb]->width(); }
    int pbuffer_height(int fb) const { return fb_[fb]->height(); }
    GLuint pbuffer_texture(int fb) const { return fb_[fb]->texture(0); }

    int width() const { return w_; }
    int height() const { return h_; }
    const ShaderOptions& options() const { return opts_; }
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
    void draw_depth();
    void draw_material(int target);
    void draw_ambient(const Scene& scene);
    void draw_lighting(const Scene& scene, bool scissors, FrameStats& stats);
    // Screen-aligned quad over [x0,x1]x[y0,y1] (window pixels), texcoord 0 = 0..1;
    // with rays, texcoord 1 = eye-space view ray of each corner (Listing 19).
    void draw_rect(float x0, float y0, float x1, float y1, bool rays);
    void set_ortho(int w, int h);
    // Shader defines of the depth path and packed encoding (glsl120/depth_codec.glsl).
    std::vector<std::string> depth_defines() const;
    int depth_target() const { return opts_.depth == DepthPath::texture ? PBuffer::DEPTH : G_DEPTH_PACKED; }

    Caps caps_;
    int w_, h_;
    ShaderOptions opts_;
    Paths paths_;
    bool mrt_path_ = true;  // one material pass into all targets
    std::unique_ptr<PBuffer> mrt_;      // G-buffer
    std::unique_ptr<PBuffer> fb_[4];    // P-buffers 0-3
    Program material_prog_[2][2][5];    // [normal map?][no specular?][0: all targets (MRT), 1+t: target t]
    Program position_prog_;             // light.frag with OUTPUT_POSITION, built on first use
    std::unique_ptr<PBuffer> position_buf_;
    std::string shader_dir_;
    glm::vec3 zrange_{0};
    Program light_prog_;
    Program blur_prog_[2];              // [select]
    Program aa_prog_[2];                // [factor only]
    std::unique_ptr<GpuScene> gpu_;
    glm::mat4 view_{1}, proj_{1};
    glm::vec2 planes_{0};
    glm::vec3 corner_rays_[4];
};

}  // namespace dsr
