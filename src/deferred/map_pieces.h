// Without framebuffer objects a shadow map is drawn through the main frame buffer and copied into
// its texture (main_buffer_map.h), as the copy P-buffers do for the G-buffer (gl/pbuffer.h); pure
// math (no GL): how a map larger than the drawable is cut into pieces that each fit it, and which
// depth path such maps take.
#pragma once
#include <vector>

namespace dsr {

// A rectangle of texels (x, y its lower-left corner; GL rows, 0 at the bottom).
struct MapPiece {
    int x = 0, y = 0, width = 0, height = 0;
    bool operator==(const MapPiece& o) const { return x == o.x && y == o.y && width == o.width && height == o.height; }
};

// A map_w x map_h map in pieces of at most buf_w x buf_h, row by row from the lower left: every
// texel in exactly one piece; one piece (the whole map) where it fits. Empty for an empty map or
// buffer.
std::vector<MapPiece> map_pieces(int map_w, int map_h, int buf_w, int buf_h);

// Whether the overlap of a and b is non-empty (a cube face's tile and a piece).
bool pieces_overlap(const MapPiece& a, const MapPiece& b);

// The main frame buffer's depth bits below which maps copied from it take the packed path: a
// depth texture copied from a 16-bit depth buffer keeps 16 bits of the stored depth (one part in
// 65536 of the light's range), where the packed path stores all 24 in colour and uses the depth
// buffer only to pick the nearest caster.
constexpr int kCopiedDepthBits = 24;

// The packed path for maps: without depth textures or ARB_shadow (as with framebuffer objects),
// or copied from a main frame buffer of fewer than kCopiedDepthBits depth bits.
bool maps_packed(bool depth_texture, bool shadow, bool main_buffer, int depth_bits);

}  // namespace dsr
