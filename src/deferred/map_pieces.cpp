// Shadow maps drawn in pieces (map_pieces.h).
#include "deferred/map_pieces.h"

#include <algorithm>

namespace dsr {

std::vector<MapPiece> map_pieces(int map_w, int map_h, int buf_w, int buf_h) {
    std::vector<MapPiece> out;
    if (map_w <= 0 || map_h <= 0 || buf_w <= 0 || buf_h <= 0) return out;
    for (int y = 0; y < map_h; y += buf_h)
        for (int x = 0; x < map_w; x += buf_w) out.push_back({x, y, std::min(buf_w, map_w - x), std::min(buf_h, map_h - y)});
    return out;
}

bool pieces_overlap(const MapPiece& a, const MapPiece& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

bool maps_packed(bool depth_texture, bool shadow, bool main_buffer, int depth_bits) {
    if (!(depth_texture && shadow)) return true;
    return main_buffer && depth_bits < kCopiedDepthBits;
}

}  // namespace dsr
