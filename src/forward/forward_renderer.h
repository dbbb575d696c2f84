// Forward renderers (§2.4.1): the two approaches the tutorial sets deferred shading against,
// used here as the accuracy reference and as the baseline a user would otherwise pick.
//   single  Listing 3: one pass per object with all lights touching it in the shader
//           (uniform arrays; more lights than fit go to further additive passes, GL_EQUAL).
//   multi   Listing 4: a depth pre-pass, an ambient pass, then one additive pass per light
//           over the objects whose bounding sphere meets the light's sphere.
// Both shade per pixel with glsl120/lighting.glsl (Equations 1-5, the function the deferred
// light pass calls) from the interpolated eye-space position and normal: no G-buffer, no
// depth reconstruction, float math, the material's shininess exactly. By default the passes
// accumulate in an RGBA32F target copied to the main frame buffer at the end, so the 8-bit
// output is the only rounding besides float math and texture filtering, and both forms give
// the same image. Transparent objects (opacity < 1) are drawn after the opaque ones by the same
// TransparentPass the deferred renderer's forward stage uses (transparent_pass.h).
// Shadows (docs/shadows.md): the lights whose scene line says `shadow` get a map from the same
// ShadowStage the deferred renderer draws them with, and are shaded by forward.frag's SHADOW form,
// one light a pass: single adds each shadowed light that reaches an object by a pass of its own on
// that object (GL_EQUAL, as its overflow passes), multi's pass of a shadowed light is that form.
// What a model brings (scene.h) is drawn as the deferred renderer draws it: a two-sided object
// without culling, a back face's normal flipped; vertex colours times the diffuse colour; cut-out
// fragments discarded in every pass (multi's depth pre-pass included), through forward.frag's
// forms of shader_table.h surface_defines.
#pragma once
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "deferred/frame.h"
#include "deferred/light_params.h"
#include "deferred/options.h"
#include "gl/caps.h"
#include "gl/pbuffer.h"
#include "gl/program.h"
#include "gl/state.h"
#include "scene/bounds.h"
#include "scene/scene.h"

namespace dsr {

class GpuScene;
class ShadowStage;
class TransparentPass;

enum class ForwardMode { single, multi };

struct ForwardOptions {
    ForwardMode mode = ForwardMode::single;
    bool listing2_literal = false;  // Listing 2's v and h exactly (docs/errata.md #1-2)
    // true: accumulate in an RGBA32F P-buffer (ARB_texture_float + EXT_framebuffer_object) and
    // round once when copying to the main buffer. false: render straight into the main frame
    // buffer, so every additive pass of `multi` rounds to 8 bits, as Listing 4 did in 2005.
    bool float_target = true;
    // Single mode: lights per pass (the uniform arrays' size), lowered to what
    // GL_MAX_FRAGMENT_UNIFORM_COMPONENTS holds.
    int max_lights_per_pass = 64;
    // The deferred renderer's switches (options.h): on honours the scene's `shadow` lights, the
    // filter is the lookup's, reuse keeps a still light's map between frames.
    ShadowOptions shadows;
};

struct ForwardStats {
    double ms_frame = 0;         // wall time of render(), glFinish included
    double ms_cpu = 0;           // the thread's CPU time up to the final glFinish (dsr_clock.h)
    int passes = 0;              // geometry submissions (draw calls), the depth pre-pass included
    int light_object_pairs = 0;  // (light, object) pairs shaded: §3's O(objects x lights)
    int lights_culled = 0;       // lights outside the view frustum (Listing 17's test)
    int shadow_maps = 0;         // maps drawn this frame (a point light's six faces count six)
    long long shadow_triangles = 0;
};

class ForwardRenderer {
public:
    // Needs a current OpenGL context with GLSL 1.20; throws dsr::Error naming a missing capability.
    ForwardRenderer(const Caps& caps, int width, int height, const ForwardOptions& opts,
                    const std::string& shader_dir);
    ForwardRenderer(const Caps& caps, int width, int height, ForwardMode mode, const std::string& shader_dir,
                    bool listing2_literal = false);
    ~ForwardRenderer();

    void set_scene(const Scene& scene);
    // The whole frame into the current main frame buffer (framebuffer 0) of width x height:
    // background where there is no surface. Read it back with dsr::read_pixels.
    ForwardStats render(const Scene& scene);

    const ForwardOptions& options() const { return opts_; }
    int lights_per_pass() const { return batch_; }

private:
    static RenderState surface_state();
    static RenderState add_state(GLuint program);
    void draw_single(const Scene& scene, ForwardStats& st);
    void draw_multi(const Scene& scene, ForwardStats& st);
    // Program for object `object`, bound, with its material's uniforms and textures set.
    Program& use_material(const Scene& scene, size_t object);
    void set_lights(Program& prog, const std::vector<int>& lights, size_t first, size_t count, glm::vec3 ambient);
    void draw_object(size_t object, ForwardStats& st);
    // The SHADOW form for object `object`'s material, bound, with light i (one, its map on unit 4).
    Program& use_shadowed(const Scene& scene, size_t object, size_t light);
    bool wants_shadows(const Scene& scene) const;  // a light with `shadow`, and ShadowOptions::on
    void update_shadow_stage(const Scene& scene);   // shadow_stage_ built or dropped to match
    void draw_shadow_maps(const Scene& scene, ForwardStats& st);
    bool touches(size_t object, const Light& light) const;
    void build_programs(bool any_light);         // prog_ and loc_light_, with or without LIGHT_POINT_ONLY
    // forward.frag's defines for a material with or without a normal map (prog_'s) and a surface.
    std::vector<std::string> program_defines(bool normal_map, int surface) const;
    // The program of a surface form (DrawRange::surface() != 0), built on first use.
    Program& surface_program(bool normal_map, int surface);
    // The light arrays' locations in prog (prog_'s or a surface form's).
    const GLint* light_locations(const Program& prog);
    static bool needs_any_light(const Scene& scene);  // a light other than the tutorial's point light
    void copy_to_main();

    Caps caps_;
    int w_, h_;
    ForwardOptions opts_;
    int batch_ = 1;
    std::string shader_dir_;
    bool any_light_ = false;  // prog_ built for every light type (else LIGHT_POINT_ONLY)
    Program prog_[2];  // [normal map?]
    GLint loc_light_[2][5] = {{-1, -1, -1, -1, -1}, {-1, -1, -1, -1, -1}};  // [nm][LightParams field]
    std::unique_ptr<PBuffer> target_;  // RGBA32F accumulation, when opts_.float_target
    std::unique_ptr<GpuScene> gpu_;
    std::unique_ptr<TransparentPass> transparent_;  // scenes with transparent materials
    std::unique_ptr<ShadowStage> shadow_stage_;     // scenes with `shadow` lights, shadows on
    Program shadow_prog_[2];                        // forward.frag's SHADOW form [normal map?]
    std::map<int, Program> surface_progs_;          // surface forms by normal map + 2 x surface
    std::map<int, Program> surface_shadow_progs_;   // the same of the SHADOW form
    std::map<GLuint, std::array<GLint, 5>> surface_locs_;  // light_locations of the surface forms
    std::vector<ShadowLookup> maps_;                // this frame's, by LightDraw::shadow
    std::vector<const ShadowLookup*> light_map_;    // per frame, per scene light: its map (null: none)
    std::vector<ObjectBounds> bounds_;  // per object, world space: light-object culling
    glm::mat4 view_{1};
    std::vector<LightParams> light_params_;  // per frame, eye space
    std::vector<char> light_visible_;   // per frame: not culled by the frustum
};

}  // namespace dsr
