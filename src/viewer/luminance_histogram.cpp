#include "viewer/luminance_histogram.h"

#include <algorithm>
#include <cmath>

namespace dsr {

LuminanceHistogram luminance_histogram(const std::vector<glm::vec2>& blocks, int bins, float lo, float hi) {
    LuminanceHistogram h;
    // No blocks (no reduction ran: RGBA8 without --exposure auto): no bins, not empty ones, so the
    // panel says why there is no histogram instead of drawing an empty one.
    if (bins <= 0 || !(hi > lo) || blocks.empty()) return h;
    h.bins.assign(size_t(bins), 0.0f);
    size_t over = 0;
    for (const glm::vec2& b : blocks) {
        const int i = int(std::floor((b.x - lo) / (hi - lo) * float(bins)));
        h.bins[size_t(std::clamp(i, 0, bins - 1))] += 1;
        over += b.y > 1.0f;
    }
    h.above_one = blocks.empty() ? 0.0 : double(over) / double(blocks.size());
    return h;
}

}  // namespace dsr
