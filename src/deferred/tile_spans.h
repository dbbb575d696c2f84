// The tiles' depth spans made on the CPU from the G-buffer read back (tile_depth.h): what
// tile_depth.frag and tile_depth_reduce.frag compute in two passes, for a CPU rasteriser, where
// reading the two targets back and taking each tile's span here costs less than the passes
// (llvmpipe, 32-large at 800x600: docs/tiles.md, "Depth culling of the tiles"). No GL.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "deferred/tile_plan.h"

namespace dsr {

// The G-buffer's targets as read back: the depth texture's values in [0, 1] and the normal
// target's RGBA8 bytes, `stride` texels a row, row 0 the window's bottom row, texel (x, y) the
// window pixel (x, y).
struct GbufferReadback {
    const float* depth = nullptr;
    const std::uint8_t* normal = nullptr;  // 4 bytes a texel
    int stride = 0;
};

// A pixel the light shaders light: its normal, byte / 255 - 0.5, longer than 0.1 (light_tiles.frag
// discards the rest: background and degenerate normals). In integers: with v = 2 byte - 255 (odd),
// |n| > 0.1 is v.v > 51^2; a sum of three odd squares is 3 mod 8, so none lies within 2 of 51^2 and
// the shader's float arithmetic cannot decide it otherwise.
inline bool lit_normal(const std::uint8_t* n) {
    const int x = 2 * n[0] - 255, y = 2 * n[1] - 255, z = 2 * n[2] - 255;
    return x * x + y * y + z * z > 51 * 51;
}

// Each tile's span of the eye z that surface_eye_z (depth_codec.glsl, the depth-texture path) gives
// its lit pixels, for a width x height frame of tile_size tiles in tile_boxes' order (row by row
// from the bottom); a tile with no lit pixel gets (1e30, -1e30), as the passes give it. Each span is
// widened past what the shader's float arithmetic can give: its depths moved out by 4 steps of a
// float and its ends by a millionth (the shader's z may differ from this arithmetic in the last
// bits; a span that missed a pixel would cull a light that lights it).
std::vector<DepthSpan> spans_from_depth(const GbufferReadback& g, int width, int height, int tile_size,
                                        glm::vec2 planes, float far_plane);

}  // namespace dsr
