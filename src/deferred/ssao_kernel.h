// The SSAO pass's sample kernel and rotation pattern (Vasilovici §5: hemisphere samples around
// the surface point, compared against the depth buffer, after Crytek): pure math, no GL, so the
// tests can check it (tests/test_ssao.cpp). Deterministic: the same n gives the same kernel on
// every machine (an own integer generator, not <random>'s distributions, whose output the
// standard leaves to the library).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace dsr {

// n sample offsets in the unit hemisphere about +z (tangent space: z along the normal), each
// with z >= kSsaoMinZ (not in the tangent plane, where a flat surface would occlude itself) and
// length <= 1; lengths grow from about 0.1 to 1 with the index (scale = lerp(0.1, 1, (i/n)^2)),
// so most samples lie near the centre, where occlusion matters most.
constexpr float kSsaoMinZ = 0.15f;
std::vector<glm::vec3> ssao_kernel(int n, uint32_t seed = 0x55a0u);

// The kSsaoTile x kSsaoTile rotation pattern: unit vectors in the xy plane (z = 0), one per
// pixel of the tile, row-major; the shader turns the kernel about the normal by the one of
// gl_FragCoord mod the tile, trading the kernel's banding for noise the blur removes.
constexpr int kSsaoTile = 4;
std::vector<glm::vec3> ssao_rotations(uint32_t seed = 0x0f0fu);

}  // namespace dsr
