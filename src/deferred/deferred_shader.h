// The tutorial's pDeferredShader (§3, Appendix A): one G-buffer, four P-buffers, and the
// stages that fill and consume them. One .cpp per stage:
//   geometry_stage.cpp  §3.3  depth pre-pass (L8) + material pass (L9-13)
//   lighting_stage.cpp  §3.4  ambient pass (L15) + one scissored quad per light (L16-20)
//   final_stage.cpp     §3.6  P-buffer 0 to the main frame buffer, fixed function
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/caps.h"
#include "gl/pbuffer.h"
#include "gl/program.h"
#include "scene/image.h"
#include "scene/scene.h"

namespace dsr {

class GpuScene;

enum class DepthPath { texture, packed };

struct ShaderOptions {
    DepthPath depth = DepthPath::texture;
    bool packed_literal = false;    // Listings 11/18 exactly (k/256 bytes); default: corrected codec
    bool listing2_literal = false;  // Listing 2's v and h exactly; default: Equations 1-5
    bool scissor = true;            // §3.4.2 light scissor rectangles
};

// Per-stage wall time of one frame, in milliseconds (glFinish after each stage).
struct StageTimes {
    double geometry = 0, ambient = 0, lights = 0, final = 0, frame = 0;
};

struct FrameStats {
    int lights_total = 0, lights_culled = 0, lights_drawn = 0;
    long long light_fragments = 0;  // fragments the light passes shaded (occlusion queries)
    long long scissor_pixels = 0;   // sum of the rectangles the light quads were limited to
    StageTimes ms;
};

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
    void final_stage(int out_w, int out_h);

    // Read a buffer back (views and tests): a G-buffer target, its depth texture
    // (PBuffer::DEPTH, as grey), or P-buffer `fb`.
    Image read_gbuffer(int target);
    Image read_pbuffer(int fb);

    int width() const { return w_; }
    int height() const { return h_; }
    const ShaderOptions& options() const { return opts_; }
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
    void draw_material();
    void draw_ambient(const Scene& scene);
    void draw_lighting(const Scene& scene, bool scissors, FrameStats& stats);
    // Screen-aligned quad over [x0,x1]x[y0,y1] (window pixels), texcoord 0 = 0..1;
    // with rays, texcoord 1 = eye-space view ray of each corner (Listing 19).
    void draw_rect(float x0, float y0, float x1, float y1, bool rays);
    void set_ortho(int w, int h);
    int depth_target() const { return opts_.depth == DepthPath::texture ? PBuffer::DEPTH : G_DEPTH_PACKED; }

    Caps caps_;
    int w_, h_;
    ShaderOptions opts_;
    std::unique_ptr<PBuffer> mrt_;      // G-buffer
    std::unique_ptr<PBuffer> fb_[4];    // P-buffers 0-3
    Program material_prog_[2];          // [normal map?]
    Program light_prog_;
    std::unique_ptr<GpuScene> gpu_;
    glm::mat4 view_{1}, proj_{1};
    glm::vec2 planes_{0};
    glm::vec3 corner_rays_[4];
};

}  // namespace dsr
