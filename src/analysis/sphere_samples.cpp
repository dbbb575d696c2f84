// The light-sphere sampler of sphere_samples.h.
#include "analysis/sphere_samples.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace dsr {

namespace {

// A fresh distribution per draw: the draws depend on the generator's state only.
double gauss(std::mt19937_64& rng) { return std::normal_distribution<double>(0, 1)(rng); }
double uni(std::mt19937_64& rng) { return std::uniform_real_distribution<double>(0, 1)(rng); }

}  // namespace

std::vector<glm::dvec3> fibonacci_directions(int n) {
    std::vector<glm::dvec3> v(size_t(std::max(n, 0)));
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / n, s = std::sqrt(1.0 - y * y);
        v[size_t(i)] = {s * std::cos(golden * i), y, s * std::sin(golden * i)};
    }
    return v;
}

std::vector<glm::dvec3> sphere_samples(const glm::dvec3& c, double r, double near_plane,
                                       const SphereSampleCounts& counts, std::mt19937_64& rng) {
    std::vector<glm::dvec3> pts;
    pts.reserve(size_t(std::max(0, counts.surface + counts.interior + counts.near_disk)));
    glm::dvec4 q(gauss(rng), gauss(rng), gauss(rng), gauss(rng));
    q /= glm::length(q);
    const glm::dmat3 rot = glm::mat3_cast(glm::dquat(q.w, q.x, q.y, q.z));
    for (const glm::dvec3& d : fibonacci_directions(counts.surface)) pts.push_back(c + r * (rot * d));
    for (int i = 0; i < counts.interior; ++i) {
        glm::dvec3 d(gauss(rng), gauss(rng), gauss(rng));
        d /= glm::length(d);
        pts.push_back(c + r * std::cbrt(uni(rng)) * d);
    }
    const double dz = -near_plane - c.z, rho2 = r * r - dz * dz;
    if (rho2 >= 0) {
        const double rho = std::sqrt(rho2);
        for (int i = 0; i < counts.near_disk; ++i) {
            const double a = 2 * M_PI * (i + uni(rng)) / counts.near_disk;
            const double k = (i % 2) ? 1.0 : std::sqrt(uni(rng));  // rim and inside
            pts.push_back({c.x + k * rho * std::cos(a), c.y + k * rho * std::sin(a), -near_plane});
        }
    }
    return pts;
}

}  // namespace dsr
