// One frame's values, computed once at the top of DeferredShader::render and handed by const
// reference to every stage (Doom 3's viewDef_t / viewLight_t): the camera's matrices, the depth
// reconstruction's constants (§3.4.3), the view rays (Listing 19) and the visible lights with
// their volumes and scissor rectangles (Listings 16-17). Pure: no GL. A stage reads what it needs
// here and nowhere else, so none depends on what another left behind.
#pragma once
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "deferred/light_params.h"
#include "deferred/light_volume.h"
#include "deferred/scissor.h"
#include "scene/scene.h"

namespace dsr {

// The light shader a light needs (the shader table's specialised light rows): a point light with
// Equation 2 (the tutorial's, LIGHT_POINT_ONLY), a point light with the attenuation law
// (LIGHT_POINT_INVERSE), or any light (type and law selected per light).
enum class LightShader { point_linear, point_inverse, any };

// One visible light of the frame: its shader parameters, eye-space volume and scissor rectangle.
struct LightDraw {
    const Light* light = nullptr;  // in the scene the frame was made from
    size_t index = 0;              // its index in Scene::lights
    LightParams params;            // light_params.h, in eye space
    LightVolume eye;               // light_volume.h, in eye space
    ScissorRect rect;              // the whole viewport when `full`
    bool full = false;
    // Its shadow map among the frame's (shadow_stage.h), in order of the shadowed lights; -1
    // where it casts none (no `shadow`, or FrameSetup::shadows off).
    int shadow = -1;
    // The tutorial's point light with Equation 2 (no type or law selection): the light shaders'
    // cheaper LIGHT_POINT_ONLY variant shades it.
    bool tutorial() const { return light->type == Light::Type::point && !light->attenuation && !light->physical; }
    LightShader shader() const {
        if (light->type != Light::Type::point || light->physical) return LightShader::any;
        return light->attenuation ? LightShader::point_inverse : LightShader::point_linear;
    }
};

// One light's shadow map as the light passes read it (glsl120/shadow.glsl): what the shadow stage
// drew this frame (shadow_stage.h), in numbers. The map's layout is shadow_math.h's ShadowLayout.
struct ShadowLookup {
    unsigned texture = 0;        // the GL texture: depth compared by ARB_shadow, or depth packed in RGB8
    int kind = 0;                // ShadowKind: 0 perspective (spot), 1 orthographic (directional), 2 six faces
    glm::mat4 eye_to_light{1};   // this frame's eye space -> the map's light space (q)
    glm::mat4 proj{1};           // q -> the map's clip space (perspective, orthographic)
    glm::vec3 depth{0};          // stored depth = depth.x |q| + depth.y (-q.z) + depth.z
    glm::vec2 texel{0};          // a texel's world size at q = texel.x + texel.y * (depth along the map's axis)
    float bias = 0, slope = 0;   // the light's LightShadow
    int width = 0, height = 0, face = 0;  // the texture's texels, and one view's per side
    bool packed = false;         // RGB8 (compared in the shader), else a depth texture (ARB_shadow)
    // Which drawing of the texture this is: the shadow stage numbers every map it draws, a reused
    // map keeps its number, so a copy of it (the batches' atlas, shadow_atlas.h) knows when it is stale.
    unsigned generation = 0;
};

// What make_frame needs besides the scene.
struct FrameSetup {
    int width = 0, height = 0;         // the deferred buffers (G-buffer and P-buffer 0)
    // The projection's aspect: the output's width / height (§3.6: a 512x512 buffer shown on a
    // 640x480 screen keeps its proportions); 0: the buffers' own, width / height.
    float aspect = 0;
    glm::vec2 gbuffer_extent{1, 1};    // the G-buffer's content in texture coordinates (pow2 padding)
    bool scissors = true;              // §3.4.2's rectangles; off: every light over the whole screen
    bool skip_empty = true;            // SkipOptions::empty_lights: no pass for a light that adds nothing
    bool shadows = false;              // the lights' `shadow` honoured (ShadowOptions::on and a shadow stage)
};

struct FrameDef {
    int width = 0, height = 0;
    Camera camera;                     // the scene's, as this frame draws it
    float aspect = 1;                  // FrameSetup's, resolved: the projection's width / height
    glm::mat4 view{1}, proj{1};        // camera.view(), camera.projection(aspect)
    glm::vec2 planes{0};               // §3.4.3's `planes` (reconstruct.h planes_uniform)
    glm::vec3 zrange{0};               // near, far, log2(far / near): the depth codecs' (depth_codec.glsl)
    std::array<glm::vec3, 4> corner_rays{};  // eye-space view rays at the window corners (Listing 19)
    // The view ray as an affine map of window coordinates, as the light shaders take it from
    // gl_FragCoord: (x, y) = window.xy * ray_map.xy + ray_map.zw, z = -1.
    glm::vec4 ray_map{0};
    glm::vec2 gbuffer_extent{1, 1};    // FrameSetup's
    glm::vec2 uv_scale{0};             // G-buffer texture coordinates per window pixel
    bool scissors = true;
    // Listing 17's survivors in scene order: frustum-culled, the empty ones skipped.
    std::vector<LightDraw> lights;
    int lights_total = 0, lights_culled = 0;
    long long scissor_pixels = 0;      // the rectangles' area, summed
    int shadowed_lights = 0;           // lights with LightDraw::shadow >= 0
    // Their maps, by LightDraw::shadow: filled by the shadow stage before the light passes read them
    // (empty until then, and in frames without shadows).
    std::vector<ShadowLookup> shadows;

    // The eye-space view ray (x, y, -1) at window position (x, y): bilinear in the corner rays.
    glm::vec3 view_ray_at(float x, float y) const;
    // The image-space passes' camera: an orthographic projection in window pixels (§3.1,
    // Listing 14 lines 5-9), glOrtho(0, width, 0, height, -1, 1).
    glm::mat4 pixels() const;
};

// The frame of `camera` looking at `lights` (pass no lights for a frame that draws none).
FrameDef make_frame(const Camera& camera, const std::vector<Light>& lights, const FrameSetup& setup);
// Listing 17's culling, empty-light skip and rectangles of `lights` added to a frame made without
// lights (make_frame with none and the same setup): make_frame's result, in two steps, so that a
// renderer can submit the G-buffer, which needs only the camera, and cull while the GPU fills it.
// Throws dsr::Error where f already has lights.
void add_visible_lights(FrameDef& f, const std::vector<Light>& lights, const FrameSetup& setup);

// glOrtho(0, w, 0, h, -1, 1): window pixels.
glm::mat4 pixel_ortho(float w, float h);

}  // namespace dsr
