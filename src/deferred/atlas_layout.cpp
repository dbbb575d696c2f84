// Atlas placement (atlas_layout.h).
#include "deferred/atlas_layout.h"

#include <algorithm>
#include <numeric>

namespace dsr {

namespace {

int next_pow2(int v) {
    int p = 1;
    while (p < v) p *= 2;
    return p;
}

}  // namespace

bool AtlasLayout::operator==(const AtlasLayout& o) const {
    return width == o.width && height == o.height && regions == o.regions;
}

AtlasLayout place_atlas(const std::vector<AtlasRegion>& sizes, int max_size) {
    AtlasLayout best;
    if (sizes.empty()) return best;
    std::vector<size_t> order(sizes.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return sizes[a].height > sizes[b].height; });
    int widest = 0;
    for (const AtlasRegion& s : sizes) widest = std::max(widest, s.width);
    for (long long w = next_pow2(std::max(1, widest)); w <= max_size; w *= 2) {
        AtlasLayout l;
        l.regions = sizes;
        int x = 0, y = 0, shelf = 0;
        for (size_t i : order) {
            AtlasRegion& r = l.regions[i];
            if (x + r.width > w) y += shelf, x = 0, shelf = 0;
            r.x = x, r.y = y;
            x += r.width;
            shelf = std::max(shelf, r.height);
        }
        const int h = next_pow2(std::max(1, y + shelf));
        if (h > max_size) continue;
        l.width = int(w), l.height = h;
        const long long area = w * h, best_area = (long long)best.width * best.height;
        if (!best.fits() || area < best_area || (area == best_area && std::max(l.width, h) < std::max(best.width, best.height)))
            best = l;
    }
    if (!best.fits()) best.regions.clear();
    return best;
}

}  // namespace dsr
