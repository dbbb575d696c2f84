#include "analysis/bench_scenes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <cstdlib>

#include "dsr_error.h"
#include "scene/hash.h"
#include "scene/light_law.h"

namespace dsr {


namespace {

// Uniform in [0, 1) from light i's stream k.
float unit(uint32_t i, uint32_t k) { return float(hash32(i * 8u + k + 0x9e3779b9u) >> 8) / 16777216.0f; }

// A saturated hue (HSV with s = 0.7, v = 1): coloured lights make overlaps visible in the image.
glm::vec3 hue(float h) {
    const float s = 0.7f;
    const float n[3] = {5.0f, 3.0f, 1.0f};  // the usual HSV-to-RGB offsets for r, g, b
    glm::vec3 c;
    for (int k = 0; k < 3; ++k) {
        const float x = std::fmod(n[k] + h * 6.0f, 6.0f);
        c[k] = 1.0f - s * std::max(0.0f, std::min({x, 4.0f - x, 1.0f}));
    }
    return c;
}

// C's rand() as glibc makes it (its TYPE_3 additive feedback generator, srand's seeding), so the
// demo's srand(13) lights come out the same on every platform: r[0] = seed, r[i] = 16807 r[i-1]
// mod (2^31 - 1) for i < 31, r[i] = r[i-31] for i < 34, then r[i] = r[i-31] + r[i-3] (mod 2^32);
// outputs are r[i] >> 1 from i = 344 on.
class CRand {
public:
    explicit CRand(uint32_t seed) {
        r_[0] = int32_t(seed == 0 ? 1 : seed);
        for (int i = 1; i < 31; ++i) {
            const int64_t v = (16807 * int64_t(r_[i - 1])) % 2147483647;
            r_[i] = int32_t(v < 0 ? v + 2147483647 : v);
        }
        for (int i = 31; i < 34; ++i) r_[i] = r_[i - 31];
        for (int i = 34; i < 344; ++i) next();
    }
    int operator()() { return int(uint32_t(next()) >> 1); }

private:
    int32_t next() {
        const int32_t v = int32_t(uint32_t(r_[(i_ + 34 - 31) % 34]) + uint32_t(r_[(i_ + 34 - 3) % 34]));
        r_[i_] = v;
        i_ = (i_ + 1) % 34;
        return v;
    }
    int32_t r_[34] = {};
    int i_ = 0;  // the slot of r[i - 34], overwritten by r[i]
};

}  // namespace

Scene with_generated_lights(const Scene& scene, int n) {
    if (n < 0) throw Error("bench scenes: negative light count");
    if (scene.objects.empty()) throw Error("bench scenes: the scene has no geometry to spread lights over");
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
    for (const Object& o : scene.objects)
        for (const Vertex& v : scene.meshes.at(o.mesh).vertices) {
            const glm::vec3 p(o.model * glm::dvec4(glm::dvec3(v.pos), 1.0));
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    Scene out = scene;
    out.lights.clear();
    if (n == 0) return out;
    const float sx = std::max(hi.x - lo.x, 1e-3f), sz = std::max(hi.z - lo.z, 1e-3f);
    // Overlap k = n * pi r^2 / area: each floor point inside about k spheres.
    const float k = 2.5f;
    const float radius = std::sqrt(k * sx * sz / (float(n) * 3.14159265f));
    // Attenuation (Eq. 2) averages 1/3 over a disc, so k overlapping lights of brightness b sum to
    // about k*b/3 where they meet the floor: b = 1.2 keeps the typical sum near 1.
    const float brightness = 1.2f;
    // Stratified: a grid of cols x rows cells over the floor, one jittered light per cell.
    const int cols = std::max(1, int(std::ceil(std::sqrt(float(n) * sx / sz))));
    const int rows = (n + cols - 1) / cols;
    for (int i = 0; i < n; ++i) {
        const uint32_t u = uint32_t(i);
        const int cx = i % cols, cz = i / cols;
        Light l;
        l.pos.x = lo.x + sx * (float(cx) + unit(u, 0)) / float(cols);
        l.pos.z = lo.z + sz * (float(cz) + unit(u, 1)) / float(rows);
        // 0.25..0.75 of the radius above the floor: the sphere cuts the floor in a disc of at
        // least 0.66 r, and reaches walls and objects near it.
        l.pos.y = lo.y + radius * (0.25f + 0.5f * unit(u, 2));
        l.radius = radius * (0.8f + 0.4f * unit(u, 3));
        l.color = i % 8 == 7 ? glm::vec3(0.0f) : brightness * hue(unit(u, 4));
        out.lights.push_back(l);
    }
    return out;
}

std::optional<LightSpec> parse_light_spec(const std::string& item) {
    LightSpec s;
    if (item == "own") return s;
    if (item == "own-shadow") {
        s.set = LightSet::shadow;
        return s;
    }
    std::string num = item;
    for (auto [suffix, set] : {std::pair<const char*, LightSet>{"-overlap", LightSet::overlap}, {"-large", LightSet::large},
                               {"-shadow", LightSet::shadow}}) {
        const std::string suf(suffix);
        if (item.size() > suf.size() && item.compare(item.size() - suf.size(), suf.size(), suf) == 0) {
            num = item.substr(0, item.size() - suf.size());
            s.set = set;
        }
    }
    char* end = nullptr;
    const long n = std::strtol(num.c_str(), &end, 10);
    if (num.empty() || *end || num[0] == '-' || num[0] == '+' || n < 0 || n > 65536) return std::nullopt;
    if (s.set == LightSet::overlap && n % 8) return std::nullopt;
    s.count = int(n);
    return s;
}

Scene with_shadowed_spots(const Scene& scene, int n) {
    Scene s = with_generated_lights(scene, n);
    for (Light& l : s.lights) {
        l.type = Light::Type::spot;
        l.pos.y += 0.5f * l.radius;
        l.dir = glm::vec3(0, -1, 0);
        l.angle_deg = 50;
        l.shadow.on = true;
    }
    return s;
}

Scene with_shadowed_lights(Scene scene) {
    for (Light& l : scene.lights) l.shadow.on = true;
    return scene;
}

Scene bench_scene(const Scene& base, const LightSpec& spec) {
    if (spec.set == LightSet::large) return large_lights_scene(spec.count);
    if (spec.set == LightSet::shadow) return spec.count < 0 ? with_shadowed_lights(base) : with_shadowed_spots(base, spec.count);
    if (spec.count < 0) return base;
    if (spec.set == LightSet::overlap) return with_overlapping_lights(base, spec.count);
    return with_generated_lights(base, spec.count);
}

std::string bench_scene_name(const std::string& base_name, const LightSpec& spec) {
    if (spec.set == LightSet::large) return "large";
    if (spec.set == LightSet::overlap) return base_name + "-overlap";
    if (spec.set == LightSet::shadow) return base_name + "-shadow";
    return base_name;
}

Scene with_overlapping_lights(const Scene& scene, int n) {
    if (n % 8) throw Error("bench scenes: the overlap scene needs a multiple of 8 lights, got " + std::to_string(n));
    const Scene centres = with_generated_lights(scene, n / 8);
    Scene out = scene;
    out.lights.clear();
    for (size_t c = 0; c < centres.lights.size(); ++c)
        for (int k = 0; k < 8; ++k) {
            Light l = centres.lights[c];
            const uint32_t u = uint32_t(c * 8 + size_t(k));
            // About 20 lights meet at a pixel (8 x 2.5 clusters), at Eq. 2's mean 1/3: 0.15 each
            // keeps the typical sum near 1.
            l.color = 0.15f * hue(unit(u, 5));
            out.lights.push_back(l);
        }
    return out;
}

Scene linear_law_twin(Scene scene) {
    for (Light& l : scene.lights) l.attenuation = false;  // radius is the law's cut-off already
    return scene;
}

Scene metal_rough_twin(Scene scene) {
    for (Material& m : scene.materials) {
        if (m.metal_rough()) continue;
        m.model = Material::Model::metallic_roughness;
        m.metallic = 0;
        m.roughness = float(std::pow(2.0 / (double(m.shininess) + 2.0), 0.25));
        m.specular_map = -1;
    }
    return scene;
}

bool has_phong_material(const Scene& scene) {
    for (const Material& m : scene.materials)
        if (!m.metal_rough()) return true;
    return false;
}

Scene large_lights_scene(int n) {
    if (n < 0) throw Error("bench scenes: negative light count");
    Scene s;
    s.path = "";
    // The demo's camera: at (0, 0, 5) looking down -z, 45 degrees, near 0.1, far 100.
    s.camera.pos = {0, 0, 5};
    s.camera.target = {0, 0, 0};
    s.camera.up = {0, 1, 0};
    s.camera.fov_deg = 45;
    s.camera.near_plane = 0.1f;
    s.camera.far_plane = 100;
    // Its lighting shader's `lighting = Diffuse * 0.1`: the ambient pass's 0.1 x diffuse.
    s.ambient = glm::vec3(0.1f);
    s.background = glm::vec3(0);
    // Its G-buffer's albedo and specular intensity (a texture's; here a constant, so the scene keeps an
    // analytic reference) and its shader's shininess 16.
    Material m;
    m.name = "box";
    m.diffuse = glm::vec3(0.8f, 0.75f, 0.7f);
    m.specular = glm::vec3(0.5f);
    m.shininess = 16;
    s.materials.push_back(m);
    // Its light boxes (drawn with --show-lights): renderCube's +-1 scaled by 0.125.
    s.marker_shape = Scene::MarkerShape::box;
    s.marker_size = 0.125f;
    // Its objectPositions: a 3 x 3 grid of spacing 3 at y = -0.5.
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j) add_box(s, glm::vec3(1), glm::vec3(3.0f * i, -0.5f, 3.0f * j), 0);
    // Its lights: srand(13), then per light x, y, z, r, g, b from rand() % 100, in that order:
    // x, z in [-3, 2.94], y in [-4, 1.94], each colour channel in [0.5, 0.995].
    CRand rand(13);
    for (int i = 0; i < n; ++i) {
        Light l;
        const float x = float(rand() % 100), y = float(rand() % 100), z = float(rand() % 100);
        l.pos = glm::vec3(float(x / 100.0 * 6.0 - 3.0), float(y / 100.0 * 6.0 - 4.0), float(z / 100.0 * 6.0 - 3.0));
        for (int c = 0; c < 3; ++c) l.color[c] = float(rand() % 100) / 200.0f + 0.5f;
        l.attenuation = true;
        l.kc = 1.0f, l.kl = 0.7f, l.kq = 1.8f;
        l.radius = float(attenuation_radius(l.kc, l.kl, l.kq, l.threshold,
                                            std::max(l.color.r, std::max(l.color.g, l.color.b))));
        s.lights.push_back(l);
    }
    return s;
}

}  // namespace dsr
