// Shared by the image tests: render a scene under OSMesa and compare with tolerances,
// writing the actual image and an amplified difference next to the build on failure.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <sys/stat.h>

#include "analysis/image_metrics.h"
#include "deferred/deferred_shader.h"
#include "gl/caps.h"
#include "gl/readback.h"
#include "platform/context.h"
#include "platform/resources.h"
#include "scene/scene.h"

namespace dsr::test {

struct RenderResult {
    Image image;
    FrameStats stats;
    std::string renderer;
    Paths paths;
};

// The default options on depth path p.
inline ShaderOptions with_depth(DepthPath p) {
    ShaderOptions o;
    o.depth = p;
    return o;
}

// A metallic-roughness material (glTF 2.0's model) of base colour `base`.
inline Material metal_rough(const std::string& name, glm::vec3 base, float metallic, float roughness) {
    Material m;
    m.name = name;
    m.model = Material::Model::metallic_roughness;
    m.diffuse = base;
    m.metallic = metallic;
    m.roughness = roughness;
    return m;
}

inline Scene default_scene() { return load_scene(resource_dir("data") + "/default.scene"); }
// A scene with a directional light added: a light drawn over the whole screen.
inline Scene with_directional(Scene s) {
    Light moon;
    moon.type = Light::Type::directional;
    moon.dir = glm::normalize(glm::vec3(0.4f, -1.0f, -0.3f));
    moon.color = {0.12f, 0.14f, 0.22f};
    s.lights.push_back(moon);
    return s;
}
// tests/data/analytic.scene: planes and spheres with constant materials, for the analytic reference.
inline Scene analytic_scene() { return load_scene(resource_dir("tests") + "/data/analytic.scene"); }

// For the analytic reference's hand checks: a plane seen from straight above, one light above its
// centre. At the centre pixel (odd size, so its ray is the axis) l = v = h = n = +Y, and
// everything is computable by hand. size: the plane's side.
inline Scene plane_from_above(float size = 4) {
    Scene s;
    s.camera.pos = {0, 5, 0};
    s.camera.target = {0, 0, 0};
    s.camera.up = {0, 0, -1};
    s.camera.fov_deg = 60;
    s.camera.near_plane = 0.5f;
    s.camera.far_plane = 20;
    s.ambient = glm::vec3(0.1f);
    s.background = {0.25f, 0.5f, 0.75f};
    Material m;
    m.name = "m";
    m.diffuse = glm::vec3(0.5f);
    m.specular = glm::vec3(0.25f);
    m.shininess = 10;
    s.materials.push_back(m);
    add_plane(s, size, {0, 0, 0}, 0);
    s.lights.push_back({{0, 1, 0}, {1, 1, 1}, 2.0f});
    return s;
}

// The best an 8-bit image can do: each value rounded to the nearest code. Measuring an 8-bit
// render against it counts whole codes; against the float reference the unavoidable output
// rounding (<= 0.5 LSB) is included.
inline Image rounded(Image img) {
    for (float& v : img.rgba) v = std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f;
    return img;
}

// A white sphere lit head-on by one large light, on background (0.2, 0.4, 0.6) with ambient
// 0.5: the corners show the background, the centre saturates.
inline Scene lit_sphere_scene() {
    Scene s;
    s.camera.pos = {0, 0, 5};
    s.camera.target = {0, 0, 0};
    s.background = {0.2f, 0.4f, 0.6f};
    s.ambient = {0.5f, 0.5f, 0.5f};
    Material m;
    m.name = "m";
    m.diffuse = {1, 1, 1};
    m.specular = {1, 1, 1};
    s.materials.push_back(m);
    add_sphere(s, 1.0f, {0, 0, 0}, 0);
    s.lights.push_back({{0, 0, 3}, {1, 1, 1}, 100.0f});
    return s;
}

inline RenderResult render_scene(const Scene& scene, int w, int h, const ShaderOptions& opts,
                                 const std::vector<std::string>& force_off = {}) {
    auto ctx = create_context(ContextDesc{"osmesa", w, h});
    Caps caps = probe_caps(force_off);
    DeferredShader ds(caps, w, h, opts, resource_dir("glsl120"));
    ds.set_scene(scene);
    RenderResult r;
    r.stats = ds.render(scene, w, h);
    r.image = read_pixels(w, h);
    r.renderer = caps.renderer;
    r.paths = ds.paths();
    return r;
}

inline std::string test_output_dir() {
    std::string d = resource_dir("build") + "/test-output";
    mkdir(d.c_str(), 0755);
    return d;
}

// Logs max/mean/PSNR; on failure of the caller's assertions the images are already on disk.
inline ImageDiff compare_logged(const std::string& name, const Image& actual, const Image& expected,
                                double fail_threshold) {
    ImageDiff d = compare_images(actual, expected, fail_threshold);
    std::printf("[ image    ] %s: max %.2f LSB, mean %.4f LSB, PSNR %.1f dB, %lld/%lld pixels over %.1f LSB\n",
                name.c_str(), d.max_lsb(), d.mean_lsb(), d.psnr_db, d.failing, d.pixels, fail_threshold * 255);
    return d;
}

inline void write_failure_images(const std::string& name, const Image& actual, const Image& expected) {
    std::string dir = test_output_dir();
    write_image(dir + "/" + name + ".actual.png", actual);
    write_image(dir + "/" + name + ".diff.png", difference_image(actual, expected, 16.0f));
    std::printf("[ image    ] wrote %s/%s.actual.png and .diff.png (difference x16)\n", dir.c_str(), name.c_str());
}

}  // namespace dsr::test
