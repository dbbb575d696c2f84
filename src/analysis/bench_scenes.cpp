#include "analysis/bench_scenes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dsr_error.h"
#include "scene/hash.h"

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

}  // namespace dsr
