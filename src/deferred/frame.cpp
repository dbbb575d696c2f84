// make_frame: the per-frame values every stage reads (frame.h).
#include "deferred/frame.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "deferred/culling.h"
#include "deferred/reconstruct.h"
#include "deferred/scissor.h"
#include "dsr_error.h"

namespace dsr {

glm::mat4 pixel_ortho(float w, float h) { return glm::ortho(0.0f, w, 0.0f, h, -1.0f, 1.0f); }

glm::mat4 FrameDef::pixels() const { return pixel_ortho(float(width), float(height)); }

glm::vec3 FrameDef::view_ray_at(float x, float y) const {
    const float u = x / float(width), v = y / float(height);
    return (1 - v) * ((1 - u) * corner_rays[0] + u * corner_rays[1]) +
           v * ((1 - u) * corner_rays[3] + u * corner_rays[2]);
}

namespace {

// Listing 17 lines 11-31: frustum culling, the empty-light skip and each light's scissor
// rectangle (Listing 16), whatever geometry then draws the light. Culling and the rectangle come
// from the light's volume (light_volume.h): a sphere as in the tutorial, a spot's cone, or a
// directional light's full screen (never culled, never scissored). Three sweeps: the lights that
// survive culling, then their rectangles (the spheres' all at once, light_scissors), then the
// lights whose rectangle is empty dropped.
void visible_lights(FrameDef& f, const std::vector<Light>& lights, bool skip_empty, bool shadows) {
    const FrustumTest in_frustum(frustum_planes(f.proj * f.view));
    const int w = f.width, h = f.height;
    const EyeTransform eye_of(f.camera);
    f.lights.reserve(lights.size());
    f.lights_total = int(lights.size());
    std::vector<EyeSphere> spheres;
    std::vector<size_t> sphere_of;  // the f.lights entry of each sphere
    spheres.reserve(lights.size());
    sphere_of.reserve(lights.size());
    for (size_t i = 0; i < lights.size(); ++i) {
        const Light& light = lights[i];
        const LightVolume volume = light_volume(light);
        if (volume_outside(in_frustum, volume)) {
            ++f.lights_culled;
            continue;
        }
        if (skip_empty && light.color.r <= 0 && light.color.g <= 0 && light.color.b <= 0) {
            ++f.lights_culled;  // adds nothing
            continue;
        }
        // In double, rounded once (Camera::to_eye): far from the origin, view * pos in float would
        // lose the light's position to the world coordinates' rounding (stress case coords).
        const LightVolume eye = to_eye(volume, eye_of);
        // The volume's eye-space position is the light's (Camera::to_eye's arithmetic), but for a
        // directional light, whose volume has none.
        const glm::vec3 eye_pos = volume.kind == LightVolume::Kind::full_screen ? eye_of.to_eye(light.pos) : eye.pos;
        if (eye.kind == LightVolume::Kind::sphere) {
            sphere_of.push_back(f.lights.size());
            spheres.push_back(EyeSphere{eye.pos, eye.radius});
        }
        f.lights.push_back(LightDraw{&light, i, light_params(light, eye_of.view, eye_pos), eye, {}, false});
    }

    std::vector<ScissorRect> sphere_rects(spheres.size());
    light_scissors(spheres.data(), spheres.size(), f.proj[0][0], f.proj[1][1], f.camera.near_plane, w, h,
                   sphere_rects.data());
    for (size_t k = 0; k < spheres.size(); ++k) f.lights[sphere_of[k]].rect = sphere_rects[k];

    size_t kept = 0;
    for (size_t j = 0; j < f.lights.size(); ++j) {
        LightDraw& l = f.lights[j];
        ScissorRect r = l.eye.kind == LightVolume::Kind::sphere
                            ? l.rect
                            : volume_scissor(l.eye, f.proj[0][0], f.proj[1][1], f.camera.near_plane, w, h);
        long long n = r.area();
        if (n <= 0) {
            if (skip_empty) {  // the volume reaches no visible pixel: Listing 17 line 31
                ++f.lights_culled;
                continue;
            }
            r = ScissorRect{0, 0, w, h};  // without the skip: shade the screen for nothing
            n = (long long)w * h;
        }
        l.full = !f.scissors || n == (long long)w * h;
        l.rect = l.full ? ScissorRect{0, 0, w, h} : r;
        f.scissor_pixels += l.rect.area();
        // Maps only for the visible shadowed lights: the shadow stage draws one per index.
        if (shadows && l.light->shadow.on) l.shadow = f.shadowed_lights++;
        if (kept != j) f.lights[kept] = l;
        ++kept;
    }
    f.lights.erase(f.lights.begin() + std::ptrdiff_t(kept), f.lights.end());
}

}  // namespace

FrameDef make_frame(const Camera& camera, const std::vector<Light>& lights, const FrameSetup& s) {
    FrameDef f;
    f.width = s.width;
    f.height = s.height;
    f.camera = camera;
    f.view = camera.view();
    // The buffers' pixels need not be square: the final stage scales them to the output, so
    // the rays, planes and rectangles below all follow this one projection.
    f.aspect = s.aspect > 0 ? s.aspect : float(s.width) / float(s.height);
    f.proj = camera.projection(f.aspect);
    f.planes = planes_uniform(camera.near_plane, camera.far_plane);
    f.zrange = glm::vec3(camera.near_plane, camera.far_plane, std::log2(camera.far_plane / camera.near_plane));
    const auto rays = corner_rays(f.proj[0][0], f.proj[1][1]);
    for (int i = 0; i < 4; ++i) f.corner_rays[size_t(i)] = rays[size_t(i)];
    const glm::vec3 lo = f.corner_rays[0], hi = f.corner_rays[2];
    f.ray_map = glm::vec4((hi.x - lo.x) / float(s.width), (hi.y - lo.y) / float(s.height), lo.x, lo.y);
    f.gbuffer_extent = s.gbuffer_extent;
    f.uv_scale = glm::vec2(s.gbuffer_extent.x / float(s.width), s.gbuffer_extent.y / float(s.height));
    f.scissors = s.scissors;
    visible_lights(f, lights, s.skip_empty, s.shadows);
    return f;
}

void add_visible_lights(FrameDef& f, const std::vector<Light>& lights, const FrameSetup& s) {
    if (f.lights_total != 0 || !f.lights.empty()) throw Error("add_visible_lights: the frame already has its lights");
    visible_lights(f, lights, s.skip_empty, s.shadows);
}

}  // namespace dsr
