#include "scene/bounds.h"

#include <algorithm>

namespace dsr {

std::vector<ObjectBounds> object_bounds(const Scene& scene) {
    std::vector<ObjectBounds> local(scene.meshes.size());
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        const Mesh& m = scene.meshes[i];
        ObjectBounds& b = local[i];
        if (m.vertices.empty()) continue;
        glm::vec3 lo = m.vertices[0].pos, hi = lo;
        for (const Vertex& v : m.vertices) {
            lo = glm::min(lo, v.pos);
            hi = glm::max(hi, v.pos);
        }
        b.centre = 0.5f * (lo + hi);
        for (const Vertex& v : m.vertices) b.radius = std::max(b.radius, glm::length(v.pos - b.centre));
    }
    std::vector<ObjectBounds> out;
    out.reserve(scene.objects.size());
    for (const Object& o : scene.objects) {
        const ObjectBounds& l = local.at(o.mesh);
        ObjectBounds b;
        b.centre = glm::vec3(o.model * glm::dvec4(glm::dvec3(l.centre), 1.0));
        b.radius = float(double(l.radius) * glm::length(glm::dvec3(o.model[0])));
        // float rounding of the lengths and of the world centre: keep the sphere conservative
        b.radius = b.radius * 1.0001f + 1e-7f * glm::length(b.centre);
        out.push_back(b);
    }
    return out;
}

}  // namespace dsr
