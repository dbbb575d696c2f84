// Sample points of a light's sphere that can be visible surface points, for brute-force checks
// of the scissor rectangle (tests/test_scissor.cpp; check_scissor in stress_run.h): the surface
// (Fibonacci directions, randomly rotated so the lattice does not alias), points filling the
// ball (redundant by convexity, but cheap), and the disk where the sphere meets z = -near (its
// rim bounds the visible part of a sphere that crosses the near plane; points exactly on the
// plane count as visible, z <= -near). Pure: no GL. A cone sampler will sit beside it.
#pragma once
#include <random>
#include <vector>

#include <glm/glm.hpp>

namespace dsr {

struct SphereSampleCounts {
    int surface = 2000;    // Fibonacci directions on the sphere
    int interior = 200;    // uniform in the ball
    int near_disk = 200;   // on the disk at z = -near (every other one on its rim)
};

// n evenly spread unit directions (the Fibonacci lattice): the sampled extent is close to the
// true one.
std::vector<glm::dvec3> fibonacci_directions(int n);

// Points of the sphere (centre, radius; eye space, camera looking down -z) in the order surface,
// interior, near-plane disk (the disk only where the sphere reaches z = -near). Draws from rng,
// so a caller can run one random stream through many spheres.
std::vector<glm::dvec3> sphere_samples(const glm::dvec3& centre, double radius, double near_plane,
                                       const SphereSampleCounts& counts, std::mt19937_64& rng);

}  // namespace dsr
