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

namespace {

// The largest magnitude of a box's coordinates: sphere_meets_box's margin, computed once per tile
// by the plans (at 1920x1080 they test hundreds of thousands of (light, tile) pairs).
float box_magnitude(const TileBox& box) {
    const glm::vec3 m = glm::max(glm::abs(box.lo), glm::abs(box.hi));
    return std::max({m.x, m.y, m.z});
}

bool meets(const LightBound& light, const TileBox& box, float box_mag) {
    if (box.empty) return false;
    if (light.radius < 0) return true;
    const glm::vec3 c = light.centre;
    // 1e-5 relative: a thousand times float's rounding of the shader's and this arithmetic.
    const float margin = 1e-5f * (box_mag + std::fabs(c.x) + std::fabs(c.y) + std::fabs(c.z) + light.radius);
    const float r = light.radius + margin;
    // Depth first: most pairs a rectangle gives are culled by z alone.
    if (c.z - r > box.hi.z || c.z + r < box.lo.z) return false;
    const glm::vec3 d = glm::max(glm::max(box.lo - c, c - box.hi), glm::vec3(0));  // per axis, to the box
    return glm::dot(d, d) <= r * r;
}

}  // namespace

bool sphere_meets_box(const LightBound& light, const TileBox& box) { return meets(light, box, box_magnitude(box)); }

namespace {

// Which tiles of a light's rectangle its sphere may shade: all of them without depth culling;
// with it, the tiles whose box the sphere meets (meets, as sphere_meets_box). Two levels: a light
// is first tested against the union box of each block of kBlock x kBlock tiles, whose failure
// implies every member's (the union holds each member box and its magnitude bounds theirs), so
// the result is the same as testing every tile; at 1920x1080 with 1024-overlap's lights the plan
// made 521560 tile tests a frame one by one.
class TileCuller {
public:
    static constexpr int kBlock = 4;

    TileCuller(const TileDepth* depth, int tiles_x, int tiles_y) : depth_(depth), tx_(tiles_x), ty_(tiles_y) {
        if (!depth_) return;
        bx_ = (tx_ + kBlock - 1) / kBlock;
        const int by = (ty_ + kBlock - 1) / kBlock;
        mags_.resize(depth_->tiles.size());
        blocks_.assign(size_t(bx_) * by, TileBox{});
        for (int y = 0; y < ty_; ++y)
            for (int x = 0; x < tx_; ++x) {
                const TileBox& t = depth_->tiles[size_t(y) * tx_ + x];
                mags_[size_t(y) * tx_ + x] = box_magnitude(t);
                if (t.empty) continue;
                TileBox& b = blocks_[size_t(y / kBlock) * bx_ + x / kBlock];
                b.lo = b.empty ? t.lo : glm::min(b.lo, t.lo);
                b.hi = b.empty ? t.hi : glm::max(b.hi, t.hi);
                b.empty = false;
            }
        for (const TileBox& b : blocks_) block_mags_.push_back(box_magnitude(b));
    }

    // Calls f(x, y) for each tile of rectangle r (clipped to the screen, in pixels; tile size ts)
    // that light l may shade, row by row within each block; stops when f returns true.
    template <class F>
    void each(int l, const ScissorRect& r, int ts, F f) const {
        const int x0 = r.x0 / ts, x1 = (r.x1 - 1) / ts, y0 = r.y0 / ts, y1 = (r.y1 - 1) / ts;
        if (!depth_) {
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                    if (f(x, y)) return;
            return;
        }
        const LightBound& light = depth_->lights[size_t(l)];
        for (int by = y0 / kBlock; by <= y1 / kBlock; ++by)
            for (int bx = x0 / kBlock; bx <= x1 / kBlock; ++bx) {
                const size_t b = size_t(by) * bx_ + bx;
                if (!meets(light, blocks_[b], block_mags_[b])) continue;
                for (int y = std::max(y0, by * kBlock); y <= std::min(y1, by * kBlock + kBlock - 1); ++y)
                    for (int x = std::max(x0, bx * kBlock); x <= std::min(x1, bx * kBlock + kBlock - 1); ++x) {
                        const size_t t = size_t(y) * tx_ + x;
                        if (meets(light, depth_->tiles[t], mags_[t]) && f(x, y)) return;
                    }
            }
    }

private:
    const TileDepth* depth_;
    int tx_, ty_, bx_ = 0;
    std::vector<float> mags_, block_mags_;
    std::vector<TileBox> blocks_;
};

// The rectangles clipped to the screen, and the indices of the lights that reach some tile
// (non-empty rectangle; with depth, a tile of it whose span meets the light's) in Morton order of
// their centre's tile (stable: equal codes keep the input order).
std::vector<int> morton_order(const std::vector<ScissorRect>& rects, int width, int height, int ts,
                              std::vector<ScissorRect>& clipped, const TileCuller& culler) {
    clipped.assign(rects.size(), ScissorRect{});
    std::vector<int> order;
    for (size_t i = 0; i < rects.size(); ++i) {
        ScissorRect r = rects[i];
        r.x0 = std::max(r.x0, 0), r.y0 = std::max(r.y0, 0);
        r.x1 = std::min(r.x1, width), r.y1 = std::min(r.y1, height);
        clipped[i] = r;
        if (r.empty()) continue;
        bool reaches = false;
        culler.each(int(i), r, ts, [&](int, int) { return reaches = true; });
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
    const TileCuller culler(depth, tx, ty);
    const std::vector<int> order = morton_order(rects, width, height, ts, clipped, culler);
    std::vector<char> covered(size_t(tx) * ty);
    for (size_t s = 0; s < order.size(); s += size_t(n)) {
        plan.batches.emplace_back(order.begin() + long(s), order.begin() + long(std::min(order.size(), s + size_t(n))));
        const std::vector<int>& group = plan.batches.back();
        std::fill(covered.begin(), covered.end(), 0);
        for (int l : group)
            culler.each(l, clipped[size_t(l)], ts, [&](int x, int y) { return !(covered[size_t(y) * tx + x] = 1); });
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
    const TileCuller culler(depth, tx, ty);
    const std::vector<int> order = morton_order(rects, width, height, ts, clipped, culler);
    for (size_t s = 0; s < order.size(); s += size_t(batch_size))
        plan.batches.emplace_back(order.begin() + long(s), order.begin() + long(std::min(order.size(), s + size_t(batch_size))));

    std::vector<std::vector<int>> bins(size_t(tx) * ty);
    for (int b = 0; b < int(plan.batches.size()); ++b) {
        for (auto& bin : bins) bin.clear();
        size_t most = 0;
        const std::vector<int>& batch = plan.batches[size_t(b)];
        for (int slot = 0; slot < int(batch.size()); ++slot) {
            const int l = batch[size_t(slot)];
            culler.each(l, clipped[size_t(l)], ts, [&](int x, int y) {
                std::vector<int>& bin = bins[size_t(y) * tx + x];
                bin.push_back(slot);
                most = std::max(most, bin.size());
                return false;
            });
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
