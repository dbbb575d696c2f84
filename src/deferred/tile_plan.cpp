#include "deferred/tile_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace dsr {

unsigned morton2(unsigned x, unsigned y) {
    auto spread = [](unsigned v) {
        v &= 0xffffu;
        v = (v | (v << 8)) & 0x00ff00ffu;
        v = (v | (v << 4)) & 0x0f0f0f0fu;
        v = (v | (v << 2)) & 0x33333333u;
        v = (v | (v << 1)) & 0x55555555u;
        return v;
    };
    return spread(x) | (spread(y) << 1);
}

TileBox tile_box(const DepthSpan& span, float x0, float y0, float x1, float y1, glm::vec4 ray_map,
                 float xy_slack) {
    TileBox b;
    if (!(span.lo <= span.hi)) return b;  // empty (or NaN): no surface to light
    // Each coordinate of ray * (-z) is bilinear in (window x or y, z): its extremes are at corners.
    const float zs[2] = {-span.lo, -span.hi};
    const float rx[2] = {x0 * ray_map.x + ray_map.z, x1 * ray_map.x + ray_map.z};
    const float ry[2] = {y0 * ray_map.y + ray_map.w, y1 * ray_map.y + ray_map.w};
    b.lo = glm::vec3(std::numeric_limits<float>::infinity());
    b.hi = -b.lo;
    for (float z : zs)
        for (int i = 0; i < 2; ++i) {
            const glm::vec3 p(rx[i] * z, ry[i] * z, -z);
            b.lo = glm::min(b.lo, p), b.hi = glm::max(b.hi, p);
        }
    for (int a = 0; a < 2; ++a) {
        const float m = xy_slack * std::max(std::fabs(b.lo[a]), std::fabs(b.hi[a]));
        b.lo[a] -= m, b.hi[a] += m;
    }
    b.lo.z = span.lo, b.hi.z = span.hi;
    b.empty = false;
    return b;
}

bool sphere_meets_box(const LightBound& light, const TileBox& box) {
    if (box.empty) return false;
    if (light.radius < 0) return true;
    const glm::vec3 c = light.centre;
    const glm::vec3 d = glm::max(glm::max(box.lo - c, c - box.hi), glm::vec3(0));  // per axis, to the box
    // 1e-5 relative: a thousand times float's rounding of the shader's and this arithmetic.
    const glm::vec3 m = glm::max(glm::abs(box.lo), glm::abs(box.hi));
    const float margin = 1e-5f * (std::max({m.x, m.y, m.z}) + std::fabs(c.x) + std::fabs(c.y) + std::fabs(c.z) + light.radius);
    const float r = light.radius + margin;
    return glm::dot(d, d) <= r * r;
}

namespace {

// Whether light l may shade tile (x, y): always without depth culling.
bool depth_meets(const TileDepth* depth, int l, int x, int y, int tiles_x) {
    return !depth || sphere_meets_box(depth->lights[size_t(l)], depth->tiles[size_t(y) * tiles_x + x]);
}

// The rectangles clipped to the screen, and the indices of the lights that reach some tile
// (non-empty rectangle; with depth, a tile of it whose span meets the light's) in Morton order of
// their centre's tile (stable: equal codes keep the input order).
std::vector<int> morton_order(const std::vector<ScissorRect>& rects, int width, int height, int ts,
                              std::vector<ScissorRect>& clipped, const TileDepth* depth) {
    clipped.assign(rects.size(), ScissorRect{});
    std::vector<int> order;
    const int tx = (width + ts - 1) / ts;
    for (size_t i = 0; i < rects.size(); ++i) {
        ScissorRect r = rects[i];
        r.x0 = std::max(r.x0, 0), r.y0 = std::max(r.y0, 0);
        r.x1 = std::min(r.x1, width), r.y1 = std::min(r.y1, height);
        clipped[i] = r;
        if (r.empty()) continue;
        bool reaches = !depth;
        for (int y = r.y0 / ts; y <= (r.y1 - 1) / ts && !reaches; ++y)
            for (int x = r.x0 / ts; x <= (r.x1 - 1) / ts && !reaches; ++x) reaches = depth_meets(depth, int(i), x, y, tx);
        if (reaches) order.push_back(int(i));
    }
    std::vector<unsigned> key(rects.size(), 0);
    for (int i : order) {
        const ScissorRect& r = clipped[size_t(i)];
        key[size_t(i)] = morton2(unsigned((r.x0 + r.x1) / 2 / ts), unsigned((r.y0 + r.y1) / 2 / ts));
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[size_t(a)] < key[size_t(b)]; });
    return order;
}

}  // namespace

TilePlan plan_tile_groups(const std::vector<ScissorRect>& rects, int width, int height, int tile_size,
                          int lights_per_pass, const TileDepth* depth) {
    TilePlan plan;
    if (width <= 0 || height <= 0 || tile_size <= 0 || lights_per_pass <= 0) return plan;
    const int ts = tile_size, n = lights_per_pass;
    const int tx = (width + ts - 1) / ts, ty = (height + ts - 1) / ts;
    std::vector<ScissorRect> clipped;
    const std::vector<int> order = morton_order(rects, width, height, ts, clipped, depth);
    std::vector<char> covered(size_t(tx) * ty);
    for (size_t s = 0; s < order.size(); s += size_t(n)) {
        plan.batches.emplace_back(order.begin() + long(s), order.begin() + long(std::min(order.size(), s + size_t(n))));
        const std::vector<int>& group = plan.batches.back();
        std::fill(covered.begin(), covered.end(), 0);
        for (int l : group) {
            const ScissorRect& r = clipped[size_t(l)];
            for (int y = r.y0 / ts; y <= (r.y1 - 1) / ts; ++y)
                for (int x = r.x0 / ts; x <= (r.x1 - 1) / ts; ++x)
                    if (depth_meets(depth, l, x, y, tx)) covered[size_t(y) * tx + x] = 1;
        }
        TileDraw d;
        d.batch = int(plan.batches.size()) - 1;
        std::vector<int> all(group.size());
        std::iota(all.begin(), all.end(), 0);
        for (int y = 0; y < ty; ++y)
            for (int x = 0; x < tx; ++x)
                if (covered[size_t(y) * tx + x]) {
                    d.quads.push_back(TileQuad{x * ts, y * ts, std::min(width, (x + 1) * ts), std::min(height, (y + 1) * ts), all});
                    plan.tile_light_pairs += long(all.size());
                }
        plan.draws.push_back(std::move(d));
    }
    return plan;
}

TilePlan plan_tiles(const std::vector<ScissorRect>& rects, int width, int height, int tile_size,
                    int lights_per_pass, int batch_size, const TileDepth* depth) {
    TilePlan plan;
    if (width <= 0 || height <= 0 || tile_size <= 0 || lights_per_pass <= 0 || batch_size <= 0) return plan;
    const int ts = tile_size, n = lights_per_pass;
    const int tx = (width + ts - 1) / ts, ty = (height + ts - 1) / ts;
    std::vector<ScissorRect> clipped;
    const std::vector<int> order = morton_order(rects, width, height, ts, clipped, depth);
    for (size_t s = 0; s < order.size(); s += size_t(batch_size))
        plan.batches.emplace_back(order.begin() + long(s), order.begin() + long(std::min(order.size(), s + size_t(batch_size))));

    std::vector<std::vector<int>> bins(size_t(tx) * ty);
    for (int b = 0; b < int(plan.batches.size()); ++b) {
        for (auto& bin : bins) bin.clear();
        size_t most = 0;
        const std::vector<int>& batch = plan.batches[size_t(b)];
        for (int slot = 0; slot < int(batch.size()); ++slot) {
            const ScissorRect& r = clipped[size_t(batch[size_t(slot)])];
            for (int y = r.y0 / ts; y <= (r.y1 - 1) / ts; ++y)
                for (int x = r.x0 / ts; x <= (r.x1 - 1) / ts; ++x) {
                    if (!depth_meets(depth, batch[size_t(slot)], x, y, tx)) continue;
                    std::vector<int>& bin = bins[size_t(y) * tx + x];
                    bin.push_back(slot);
                    most = std::max(most, bin.size());
                }
        }
        for (size_t first = 0; first < most; first += size_t(n)) {
            TileDraw d;
            d.batch = b;
            for (int y = 0; y < ty; ++y)
                for (int x = 0; x < tx; ++x) {
                    const std::vector<int>& bin = bins[size_t(y) * tx + x];
                    if (bin.size() <= first) continue;
                    TileQuad q{x * ts, y * ts, std::min(width, (x + 1) * ts), std::min(height, (y + 1) * ts), {}};
                    q.slots.assign(bin.begin() + long(first), bin.begin() + long(std::min(bin.size(), first + size_t(n))));
                    plan.tile_light_pairs += long(q.slots.size());
                    d.quads.push_back(std::move(q));
                }
            plan.draws.push_back(std::move(d));
        }
    }
    return plan;
}

}  // namespace dsr
