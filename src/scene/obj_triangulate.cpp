// Faces of more than three corners as triangles (obj_triangulate.h).
#include "scene/obj_triangulate.h"

#include <cmath>

namespace dsr::obj {

bool quad_splits_02(const std::array<glm::vec3, 4>& p) {
    // tinyobjloader's arithmetic, in float and in its order (no FMA: the build targets plain x86-64).
    const float e02x = p[2].x - p[0].x, e02y = p[2].y - p[0].y, e02z = p[2].z - p[0].z;
    const float e13x = p[3].x - p[1].x, e13y = p[3].y - p[1].y, e13z = p[3].z - p[1].z;
    const float sqr02 = e02x * e02x + e02y * e02y + e02z * e02z;
    const float sqr13 = e13x * e13x + e13y * e13y + e13z * e13z;
    return sqr02 < sqr13;
}

void triangulate_quad(const std::array<glm::vec3, 4>& p, std::vector<uint32_t>& out) {
    static const uint32_t split02[6] = {0, 1, 2, 0, 2, 3}, split13[6] = {0, 1, 3, 1, 2, 3};
    const bool by02 = quad_splits_02(p);
    const uint32_t* chosen = by02 ? split02 : split13;
    const uint32_t* other = by02 ? split13 : split02;
    glm::dvec3 q[4];
    for (int i = 0; i < 4; ++i) q[i] = glm::dvec3(p[size_t(i)]) - glm::dvec3(p[0]);
    const glm::dvec3 n = glm::cross(q[1], q[2]) + glm::cross(q[2], q[3]);  // Newell normal (q[0] = 0)
    auto flipped = [&](const uint32_t* t) {
        for (int k = 0; k < 6; k += 3)
            if (glm::dot(glm::cross(q[t[k + 1]] - q[t[k]], q[t[k + 2]] - q[t[k]]), n) < 0) return true;
        return false;
    };
    // A concave quad: the shorter diagonal may lie outside it, the other never does.
    if (flipped(chosen) && !flipped(other)) chosen = other;
    out.insert(out.end(), chosen, chosen + 6);
}

Polygon triangulate_polygon(const std::vector<glm::dvec3>& p, std::vector<uint32_t>& out, size_t& work) {
    const size_t n = p.size();
    std::vector<uint32_t> next(n), prev(n);
    for (size_t i = 0; i < n; ++i) next[i] = uint32_t((i + 1) % n), prev[i] = uint32_t((i + n - 1) % n);
    size_t remaining = n;
    auto fan = [&](uint32_t from) {
        for (uint32_t j = next[from]; next[j] != from; j = next[j]) out.insert(out.end(), {from, j, next[j]});
    };

    // The plane: the Newell normal (relative to the first corner, for precision).
    glm::dvec3 normal(0);
    for (size_t i = 0; i < n; ++i) normal += glm::cross(p[i] - p[0], p[(i + 1) % n] - p[0]);
    const double len = std::sqrt(glm::dot(normal, normal));
    if (!(len > 0) || !std::isfinite(len)) {
        fan(0);
        return Polygon::fan_no_area;
    }
    normal /= len;
    const glm::dvec3 a = std::fabs(normal.x) <= std::fabs(normal.y) && std::fabs(normal.x) <= std::fabs(normal.z)
                             ? glm::dvec3(1, 0, 0)
                             : std::fabs(normal.y) <= std::fabs(normal.z) ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    const glm::dvec3 u = glm::normalize(glm::cross(normal, a)), v = glm::cross(normal, u);  // u x v = normal
    std::vector<glm::dvec2> q(n);
    for (size_t i = 0; i < n; ++i) q[i] = {glm::dot(p[i] - p[0], u), glm::dot(p[i] - p[0], v)};

    auto orient = [&](uint32_t i, uint32_t j, uint32_t k) {
        const glm::dvec2 e1 = q[j] - q[i], e2 = q[k] - q[i];
        return e1.x * e2.y - e1.y * e2.x;
    };
    // A corner that adds no area: the sine of its turn within 1e-10, or an edge of length 0.
    auto no_area = [&](uint32_t i, uint32_t j, uint32_t k, double o) {
        const double l1 = glm::length(q[j] - q[i]), l2 = glm::length(q[k] - q[j]);
        return std::fabs(o) <= 1e-10 * l1 * l2;
    };

    // Reflex corners in a doubly linked list: only they can lie inside an ear.
    std::vector<uint8_t> is_reflex(n, 0);
    std::vector<uint32_t> rnext(n), rprev(n);
    const uint32_t none = uint32_t(-1);
    uint32_t rhead = none;
    auto reflex_remove = [&](uint32_t i) {
        if (!is_reflex[i]) return;
        is_reflex[i] = 0;
        if (rprev[i] != none) rnext[rprev[i]] = rnext[i];
        else rhead = rnext[i];
        if (rnext[i] != none) rprev[rnext[i]] = rprev[i];
    };
    auto classify = [&](uint32_t i) {
        const double o = orient(prev[i], i, next[i]);
        const bool r = o < 0 && !no_area(prev[i], i, next[i], o);
        if (r && !is_reflex[i]) {
            is_reflex[i] = 1;
            rprev[i] = none;
            rnext[i] = rhead;
            if (rhead != none) rprev[rhead] = i;
            rhead = i;
        } else if (!r) {
            reflex_remove(i);
        }
    };
    for (uint32_t i = 0; i < n; ++i) classify(i);
    auto unlink = [&](uint32_t i) {
        reflex_remove(i);
        next[prev[i]] = next[i];
        prev[next[i]] = prev[i];
        --remaining;
        classify(prev[i]);
        classify(next[i]);
    };
    auto is_ear = [&](uint32_t a0, uint32_t b, uint32_t c) {
        for (uint32_t r = rhead; r != none; r = rnext[r]) {
            if (r == a0 || r == c) continue;
            if (q[r] == q[a0] || q[r] == q[b] || q[r] == q[c]) continue;  // a corner touching the ear's own
            ++work;
            if (orient(a0, b, r) >= 0 && orient(b, c, r) >= 0 && orient(c, a0, r) >= 0) return false;
        }
        return true;
    };

    uint32_t i = 0;
    size_t stall = 0;
    while (remaining > 3) {
        if (work > kMaxEarClipWork) {
            fan(i);
            return Polygon::fan_over_budget;
        }
        const uint32_t a0 = prev[i], c = next[i];
        const double o = orient(a0, i, c);
        if (no_area(a0, i, c, o)) {
            unlink(i);
            i = a0;
            stall = 0;
            continue;
        }
        if (o > 0 && is_ear(a0, i, c)) {
            out.insert(out.end(), {a0, i, c});
            unlink(i);
            i = a0;
            stall = 0;
            continue;
        }
        i = c;
        if (++stall > remaining) {
            // No ear in a whole turn: the polygon crosses itself.
            fan(i);
            return Polygon::fan_not_simple;
        }
    }
    const double o = orient(prev[i], i, next[i]);
    if (!no_area(prev[i], i, next[i], o)) out.insert(out.end(), {prev[i], i, next[i]});
    return Polygon::ear_clipped;
}

}  // namespace dsr::obj
