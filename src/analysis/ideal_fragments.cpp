#include "analysis/ideal_fragments.h"

#include <algorithm>
#include <limits>

#include "deferred/reconstruct.h"

namespace dsr {

Image positions_from_depth(const Image& depth, glm::vec2 planes, float p00, float p11) {
    Image out;
    out.width = depth.width;
    out.height = depth.height;
    out.rgba.assign(depth.rgba.size(), 0.0f);
    for (int y = 0; y < depth.height; ++y)
        for (int x = 0; x < depth.width; ++x) {
            const float d = depth.at(x, y)[0];
            if (!(d < 1.0f)) continue;  // the clear value: no surface
            const glm::vec3 ray = view_ray(float(x) + 0.5f, float(y) + 0.5f, depth.width, depth.height, p00, p11);
            const glm::vec3 p = reconstruct_position(d, planes, ray);
            float* q = out.at(x, y);
            q[0] = p.x, q[1] = p.y, q[2] = p.z, q[3] = 1.0f;
        }
    return out;
}

namespace {

// The one inside test both counts share, so they agree bit for bit.
inline bool inside(const float* p, const glm::vec4& l) {
    const float dx = p[0] - l.x, dy = p[1] - l.y, dz = p[2] - l.z;
    return dx * dx + dy * dy + dz * dz < l.w * l.w;
}

struct Tile {
    int x0, y0, x1, y1;
    glm::vec3 lo, hi;  // box of the tile's surface positions; empty (lo > hi) when none
};

}  // namespace

long long ideal_fragments(const Image& positions, const std::vector<glm::vec4>& lights) {
    constexpr int kTile = 16;
    std::vector<Tile> tiles;
    for (int ty = 0; ty < positions.height; ty += kTile)
        for (int tx = 0; tx < positions.width; tx += kTile) {
            Tile t{tx, ty, std::min(tx + kTile, positions.width), std::min(ty + kTile, positions.height),
                   glm::vec3(std::numeric_limits<float>::infinity()), glm::vec3(-std::numeric_limits<float>::infinity())};
            for (int y = t.y0; y < t.y1; ++y)
                for (int x = t.x0; x < t.x1; ++x) {
                    const float* p = positions.at(x, y);
                    if (!(p[3] > 0.5f)) continue;
                    t.lo = glm::min(t.lo, glm::vec3(p[0], p[1], p[2]));
                    t.hi = glm::max(t.hi, glm::vec3(p[0], p[1], p[2]));
                }
            if (t.lo.x <= t.hi.x) tiles.push_back(t);
        }
    long long n = 0;
    for (const glm::vec4& l : lights) {
        if (!(l.w > 0)) continue;
        const glm::vec3 c(l);
        for (const Tile& t : tiles) {
            // Distance from the centre to the tile's box; a margin keeps float rounding of the
            // box test from rejecting a pixel the exact per-pixel test below accepts.
            const glm::vec3 d = glm::max(glm::max(t.lo - c, c - t.hi), glm::vec3(0.0f));
            if (glm::dot(d, d) > l.w * l.w * 1.0001f + 1e-12f) continue;
            for (int y = t.y0; y < t.y1; ++y)
                for (int x = t.x0; x < t.x1; ++x) {
                    const float* p = positions.at(x, y);
                    n += p[3] > 0.5f && inside(p, l);
                }
        }
    }
    return n;
}

long long ideal_fragments_brute(const Image& positions, const std::vector<glm::vec4>& lights) {
    long long n = 0;
    for (const glm::vec4& l : lights) {
        if (!(l.w > 0)) continue;
        for (int y = 0; y < positions.height; ++y)
            for (int x = 0; x < positions.width; ++x) {
                const float* p = positions.at(x, y);
                n += p[3] > 0.5f && inside(p, l);
            }
    }
    return n;
}

}  // namespace dsr
