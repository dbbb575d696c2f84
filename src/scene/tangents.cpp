// compute_tangents: see tangents.h. Accumulates in double so large coordinates (up to the OBJ
// loader's 1e12 limit) cannot overflow the squared lengths.
#include "scene/tangents.h"

#include <cmath>
#include <vector>

namespace dsr {

namespace {

using glm::dvec3;

bool finite(const dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

double len(const dvec3& v) { return std::sqrt(glm::dot(v, v)); }

// Any unit vector perpendicular to unit n: the cross product with the axis least aligned with n.
dvec3 perpendicular(const dvec3& n) {
    const dvec3 a = std::fabs(n.x) <= std::fabs(n.y) && std::fabs(n.x) <= std::fabs(n.z) ? dvec3(1, 0, 0)
                    : std::fabs(n.y) <= std::fabs(n.z)                                   ? dvec3(0, 1, 0)
                                                                                        : dvec3(0, 0, 1);
    const dvec3 t = glm::cross(n, a);
    return t / len(t);
}

}  // namespace

void compute_tangents(Mesh& mesh) {
    const size_t nv = mesh.vertices.size();
    std::vector<dvec3> tan(nv, dvec3(0)), bin(nv, dvec3(0)), face_n(nv, dvec3(0));
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const uint32_t ia = mesh.indices[i], ib = mesh.indices[i + 1], ic = mesh.indices[i + 2];
        if (ia >= nv || ib >= nv || ic >= nv) continue;
        const Vertex &a = mesh.vertices[ia], &b = mesh.vertices[ib], &c = mesh.vertices[ic];
        const dvec3 e1 = dvec3(b.pos) - dvec3(a.pos), e2 = dvec3(c.pos) - dvec3(a.pos);
        const dvec3 fn = glm::cross(e1, e2);
        const double area = len(fn);
        if (!(area > 0) || !std::isfinite(area)) continue;
        for (uint32_t k : {ia, ib, ic}) face_n[k] += fn;
        const double du1 = double(b.uv.x) - a.uv.x, dv1 = double(b.uv.y) - a.uv.y;
        const double du2 = double(c.uv.x) - a.uv.x, dv2 = double(c.uv.y) - a.uv.y;
        const double det = du1 * dv2 - du2 * dv1;
        if (!(det != 0) || !std::isfinite(det)) continue;
        const dvec3 t = (e1 * dv2 - e2 * dv1) / det, bn = (e2 * du1 - e1 * du2) / det;
        const double lt = len(t), lb = len(bn);
        if (!(lt > 0) || !(lb > 0) || !std::isfinite(lt) || !std::isfinite(lb)) continue;
        for (uint32_t k : {ia, ib, ic}) {
            tan[k] += t * (area / lt);
            bin[k] += bn * (area / lb);
        }
    }
    for (size_t k = 0; k < nv; ++k) {
        Vertex& v = mesh.vertices[k];
        dvec3 n(v.normal);
        double ln = len(n);
        if (!(ln > 0) || !std::isfinite(ln)) {
            n = face_n[k];
            ln = len(n);
            if (!(ln > 0) || !std::isfinite(ln)) n = dvec3(0, 0, 1), ln = 1;
            v.normal = glm::vec3(n / ln);
        }
        n /= ln;
        dvec3 t = tan[k] - n * glm::dot(n, tan[k]);
        const double lt = len(t);
        // A tangent that is (nearly) parallel to the normal carries no direction: any perpendicular.
        t = lt > 1e-9 * len(tan[k]) && lt > 0 && finite(t) ? t / lt : perpendicular(n);
        const dvec3 b = glm::cross(n, t);
        const double sign = glm::dot(b, bin[k]) < 0 ? -1.0 : 1.0;
        v.tangent = glm::vec3(t);
        v.binormal = glm::vec3(sign * b);
    }
}

}  // namespace dsr
