// Where a batch's shadow maps go in one atlas texture (shadow_atlas.h): pure, no GL. Each map is a
// region at whole texels of a power-of-two atlas, so the lookup's atlas coordinate
// (corner + uv * map size) / atlas size, scaled back by the atlas size as the texture unit does,
// lands on the map's own texels (glsl120/shadow.glsl SHADOW_ATLAS).
#pragma once
#include <vector>

namespace dsr {

struct AtlasRegion {
    int x = 0, y = 0;           // the lower-left texel
    int width = 0, height = 0;  // the map's texels
    bool operator==(const AtlasRegion& o) const {
        return x == o.x && y == o.y && width == o.width && height == o.height;
    }
};

struct AtlasLayout {
    int width = 0, height = 0;  // powers of two; 0: the maps fit no atlas of the largest size
    std::vector<AtlasRegion> regions;  // in the order of the sizes asked for
    bool fits() const { return width > 0; }
    bool operator==(const AtlasLayout& o) const;
};

// Shelves of maps (tallest first, left to right, a new shelf where the next one would cross the
// right edge) in the smallest power-of-two atlas of sides at most max_size (the least area, then
// the shorter longest side). sizes: each map's (width, height) in texels.
AtlasLayout place_atlas(const std::vector<AtlasRegion>& sizes, int max_size);

}  // namespace dsr
