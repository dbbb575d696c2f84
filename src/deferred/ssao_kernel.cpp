#include "deferred/ssao_kernel.h"

#include <cmath>

namespace dsr {

namespace {
// xorshift32: the same sequence everywhere; 24 bits to a float in [0, 1).
struct Rng {
    uint32_t s;
    float next() {
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        return float(s >> 8) / 16777216.0f;
    }
};
}  // namespace

std::vector<glm::vec3> ssao_kernel(int n, uint32_t seed) {
    Rng rng{seed ? seed : 1u};
    std::vector<glm::vec3> k;
    k.reserve(size_t(n > 0 ? n : 0));
    while (int(k.size()) < n) {
        // A direction in the hemisphere by rejection from the cube, kept off the tangent plane.
        const glm::vec3 d(rng.next() * 2 - 1, rng.next() * 2 - 1, rng.next());
        const float len = glm::length(d);
        if (len > 1 || len < 1e-3f || d.z / len < kSsaoMinZ) continue;
        const float t = float(k.size()) / float(n);
        const float scale = 0.1f + 0.9f * t * t;  // towards the centre
        k.push_back(d / len * (scale * (0.5f + 0.5f * rng.next())));
    }
    return k;
}

std::vector<glm::vec3> ssao_rotations(uint32_t seed) {
    Rng rng{seed ? seed : 1u};
    std::vector<glm::vec3> r;
    for (int i = 0; i < kSsaoTile * kSsaoTile; ++i) {
        const float a = rng.next() * 6.28318530718f;
        r.emplace_back(std::cos(a), std::sin(a), 0.0f);
    }
    return r;
}

}  // namespace dsr
