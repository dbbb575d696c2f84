#include "deferred/tile_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

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

// The culling's working forms. A box as six floats and its magnitude, an empty one inverted
// (lo = +inf, hi = -inf) so that the depth test fails it without a branch of its own; a light with
// the sum of its terms of the margin. The plans test hundreds of thousands of pairs a frame at
// 1920x1080 (1024-overlap: 201536), so these are built once per tile and per light.
struct CullBox {
    glm::vec3 lo{std::numeric_limits<float>::infinity()}, hi{-std::numeric_limits<float>::infinity()};
    float mag = 0;
};
struct CullLight {
    glm::vec3 c{0};
    float r = -1, terms = 0;  // r < 0: unbounded (directional)
};

CullBox cull_box(const TileBox& b) {
    CullBox c;
    if (b.empty) return c;
    c.lo = b.lo, c.hi = b.hi, c.mag = box_magnitude(b);
    return c;
}

CullLight cull_light(const LightBound& l) {
    return CullLight{l.centre, l.radius, std::fabs(l.centre.x) + std::fabs(l.centre.y) + std::fabs(l.centre.z) + l.radius};
}

inline bool meets(const CullLight& l, const CullBox& b) {
    if (l.r < 0) return b.lo.z <= b.hi.z;  // unbounded: every box with a surface
    // 1e-5 relative: a thousand times float's rounding of the shader's and this arithmetic.
    const float r = l.r + 1e-5f * (b.mag + l.terms);
    // Depth first: most pairs a rectangle gives are culled by z alone (and every empty box).
    if (l.c.z - r > b.hi.z || l.c.z + r < b.lo.z) return false;
    const glm::vec3 d = glm::max(glm::max(b.lo - l.c, l.c - b.hi), glm::vec3(0));  // per axis, to the box
    return glm::dot(d, d) <= r * r;
}

// Four boxes side by side, a lane each (GCC's vector extensions: SSE2 on x86-64), and meets for
// all four at once: tiles_kept tests a light against hundreds of thousands of tiles a frame at
// 1920x1080 (1024-overlap, 32-large), one by one the most of the tiles' culling. Each lane's
// arithmetic is meets' operation for operation (glm's max as (a < b ? b : a), its dot as
// (x + y) + z), so each lane's answer is meets' (TilePlan.FourLaneTestIsMeets).
using F4 = float __attribute__((vector_size(16)));
using M4 = int __attribute__((vector_size(16)));  // a comparison's lanes: all ones or zero

inline F4 splat4(float v) { return F4{v, v, v, v}; }

struct CullBox4 {  // four CullBoxes, empty until set
    F4 lo[3] = {splat4(INFINITY), splat4(INFINITY), splat4(INFINITY)};
    F4 hi[3] = {splat4(-INFINITY), splat4(-INFINITY), splat4(-INFINITY)};
    F4 mag = splat4(0);
};
inline F4 max4(F4 a, F4 b) { return a < b ? b : a; }

inline M4 meets4(const CullLight& l, const CullBox4& b) {
    if (l.r < 0) return b.lo[2] <= b.hi[2];
    const F4 r = splat4(l.r) + splat4(1e-5f) * (b.mag + splat4(l.terms));
    const F4 cz = splat4(l.c.z), zero = splat4(0);
    const M4 in_z = ~((cz - r > b.hi[2]) | (cz + r < b.lo[2]));
    F4 d[3];
    for (int a = 0; a < 3; ++a) {
        const F4 c = splat4(l.c[a]);
        d[a] = max4(max4(b.lo[a] - c, c - b.hi[a]), zero);
    }
    return in_z & ((d[0] * d[0] + d[1] * d[1]) + d[2] * d[2] <= r * r);
}

}  // namespace

bool meets_four_lanes(const LightBound& light, const std::array<TileBox, 4>& boxes, int lane) {
    CullBox4 b4;
    for (int k = 0; k < 4; ++k) {
        const CullBox c = cull_box(boxes[size_t(k)]);
        for (int a = 0; a < 3; ++a) b4.lo[a][k] = c.lo[a], b4.hi[a][k] = c.hi[a];
        b4.mag[k] = c.mag;
    }
    return meets4(cull_light(light), b4)[lane] != 0;
}

bool sphere_meets_box(const LightBound& light, const TileBox& box) { return meets(cull_light(light), cull_box(box)); }

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
    static_assert(kBlock == 4, "row_major tests a block's row of tiles as one CullBox4");

    TileCuller(const TileDepth* depth, int tiles_x, int tiles_y) : depth_(depth), tx_(tiles_x) {
        if (!depth_) return;
        bx_ = (tx_ + kBlock - 1) / kBlock;
        const int by = (tiles_y + kBlock - 1) / kBlock;
        tiles_.resize(depth_->tiles.size());
        fours_.resize(size_t(tiles_y) * size_t(bx_));  // past the last column: empty lanes
        std::vector<TileBox> blocks(size_t(bx_) * by, TileBox{});
        for (int y = 0; y < tiles_y; ++y)
            for (int x = 0; x < tx_; ++x) {
                const TileBox& t = depth_->tiles[size_t(y) * tx_ + x];
                const CullBox c = cull_box(t);
                tiles_[size_t(y) * tx_ + x] = c;
                CullBox4& four = fours_[size_t(y) * bx_ + x / kBlock];
                for (int a = 0; a < 3; ++a) four.lo[a][x % kBlock] = c.lo[a], four.hi[a][x % kBlock] = c.hi[a];
                four.mag[x % kBlock] = c.mag;
                if (t.empty) continue;
                TileBox& b = blocks[size_t(y / kBlock) * bx_ + x / kBlock];
                b.lo = b.empty ? t.lo : glm::min(b.lo, t.lo);
                b.hi = b.empty ? t.hi : glm::max(b.hi, t.hi);
                b.empty = false;
            }
        for (const TileBox& b : blocks) blocks_.push_back(cull_box(b));
        for (const LightBound& l : depth_->lights) lights_.push_back(cull_light(l));
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
        const CullLight& light = lights_[size_t(l)];
        for (int by = y0 / kBlock; by <= y1 / kBlock; ++by)
            for (int bx = x0 / kBlock; bx <= x1 / kBlock; ++bx) {
                if (!meets(light, blocks_[size_t(by) * bx_ + bx])) continue;
                for (int y = std::max(y0, by * kBlock); y <= std::min(y1, by * kBlock + kBlock - 1); ++y)
                    for (int x = std::max(x0, bx * kBlock); x <= std::min(x1, bx * kBlock + kBlock - 1); ++x)
                        if (meets(light, tiles_[size_t(y) * tx_ + x]) && f(x, y)) return;
            }
    }

    // The tiles each() gives for light l and rectangle r, appended to `out` in row-major order
    // (ascending tile index) without sorting: each block of the rectangle is tested once, then the
    // rows are walked tile by tile within the blocks that passed.
    void row_major(int l, const ScissorRect& r, int ts, std::vector<int>& out, std::vector<char>& scratch) const {
        const int x0 = r.x0 / ts, x1 = (r.x1 - 1) / ts, y0 = r.y0 / ts, y1 = (r.y1 - 1) / ts;
        if (!depth_) {
            out.reserve(out.size() + size_t(x1 - x0 + 1) * size_t(y1 - y0 + 1));
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) out.push_back(y * tx_ + x);
            return;
        }
        const CullLight& light = lights_[size_t(l)];
        const int bx0 = x0 / kBlock, bx1 = x1 / kBlock, by0 = y0 / kBlock, by1 = y1 / kBlock, nbx = bx1 - bx0 + 1;
        scratch.assign(size_t(nbx) * size_t(by1 - by0 + 1), 0);
        bool any = false;
        for (int by = by0; by <= by1; ++by)
            for (int bx = bx0; bx <= bx1; ++bx) {
                const bool m = meets(light, blocks_[size_t(by) * bx_ + bx]);
                scratch[size_t(by - by0) * nbx + (bx - bx0)] = m;
                any |= m;
            }
        if (!any) return;
        for (int y = y0; y <= y1; ++y) {
            const char* row = &scratch[size_t(y / kBlock - by0) * nbx];
            for (int bx = bx0; bx <= bx1; ++bx) {
                if (!row[bx - bx0]) continue;
                // The block's four tiles of row y at once, those outside the rectangle dropped.
                const M4 m = meets4(light, fours_[size_t(y) * bx_ + bx]);
                for (int x = std::max(x0, bx * kBlock); x <= std::min(x1, bx * kBlock + kBlock - 1); ++x)
                    if (m[x - bx * kBlock]) out.push_back(y * tx_ + x);
            }
        }
    }

private:
    const TileDepth* depth_;
    int tx_, bx_ = 0;
    std::vector<CullBox> tiles_, blocks_;
    // The tiles' boxes four a row at a time, a block's width (kBlock), for row_major; lanes past
    // the screen's last column hold empty boxes.
    std::vector<CullBox4> fours_;
    std::vector<CullLight> lights_;
};

}  // namespace

std::vector<std::vector<int>> tiles_kept(const std::vector<ScissorRect>& rects, int width, int height, int tile_size,
                                         const TileDepth* depth) {
    const int tx = (width + tile_size - 1) / tile_size, ty = (height + tile_size - 1) / tile_size;
    const TileCuller culler(depth, tx, ty);
    std::vector<std::vector<int>> out(rects.size());
    std::vector<char> scratch;
    for (size_t i = 0; i < rects.size(); ++i) {
        const ScissorRect r{std::max(0, rects[i].x0), std::max(0, rects[i].y0), std::min(width, rects[i].x1),
                            std::min(height, rects[i].y1)};
        if (r.x1 <= r.x0 || r.y1 <= r.y0) continue;
        culler.row_major(int(i), r, tile_size, out[i], scratch);  // ascending: no sort (it cost half the time)
    }
    return out;
}

namespace {

// The rectangles clipped to the screen, and the indices of the lights that reach some tile
// (non-empty rectangle; with depth, a tile of it whose span meets the light's) in Morton order of
// their centre's tile (stable: equal codes keep the input order).
std::vector<int> morton_order(const std::vector<ScissorRect>& rects, int width, int height, int ts,
                              std::vector<ScissorRect>& clipped, const TileCuller& culler,
                              const std::vector<std::vector<int>>* kept = nullptr) {
    clipped.assign(rects.size(), ScissorRect{});
    std::vector<int> order;
    for (size_t i = 0; i < rects.size(); ++i) {
        ScissorRect r = rects[i];
        r.x0 = std::max(r.x0, 0), r.y0 = std::max(r.y0, 0);
        r.x1 = std::min(r.x1, width), r.y1 = std::min(r.y1, height);
        clipped[i] = r;
        if (r.empty()) continue;
        bool reaches = kept && !(*kept)[i].empty();
        if (!kept) culler.each(int(i), r, ts, [&](int, int) { return reaches = true; });
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

std::vector<std::vector<int>> cut_batches(const std::vector<int>& order, int batch_size,
                                          const std::vector<bool>* shadowed, int max_shadowed) {
    if (shadowed && max_shadowed < 1) throw std::logic_error("cut_batches: shadowed lights need a slot a batch");
    std::vector<std::vector<int>> out;
    int in_batch = 0;  // shadowed lights in out.back()
    for (int l : order) {
        const bool s = shadowed && (*shadowed)[size_t(l)];
        if (out.empty() || int(out.back().size()) >= batch_size || (s && in_batch >= max_shadowed)) {
            out.emplace_back();
            in_batch = 0;
        }
        out.back().push_back(l);
        in_batch += s;
    }
    return out;
}

TilePlan plan_tile_groups(const std::vector<ScissorRect>& rects, int width, int height, int tile_size,
                          int lights_per_pass, const TileDepth* depth, const std::vector<bool>* shadowed,
                          int max_shadowed) {
    TilePlan plan;
    if (width <= 0 || height <= 0 || tile_size <= 0 || lights_per_pass <= 0) return plan;
    const int ts = tile_size, n = lights_per_pass;
    const int tx = (width + ts - 1) / ts, ty = (height + ts - 1) / ts;
    std::vector<ScissorRect> clipped;
    const TileCuller culler(depth, tx, ty);
    const std::vector<int> order = morton_order(rects, width, height, ts, clipped, culler);
    std::vector<char> covered(size_t(tx) * ty);
    plan.batches = cut_batches(order, n, shadowed, max_shadowed);
    for (size_t g = 0; g < plan.batches.size(); ++g) {
        const std::vector<int>& group = plan.batches[g];
        std::fill(covered.begin(), covered.end(), 0);
        for (int l : group)
            culler.each(l, clipped[size_t(l)], ts, [&](int x, int y) { return !(covered[size_t(y) * tx + x] = 1); });
        TileDraw d;
        d.batch = int(g);
        SlotList all;
        for (int k = 0; k < int(group.size()); ++k) all.push_back(k);
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

struct TilePlanner::Impl {
    int width = 0, height = 0, ts = 1, n = 1, tx = 0, ty = 0;
    std::vector<ScissorRect> clipped;
    TileCuller culler;
    const std::vector<std::vector<int>>* kept = nullptr;  // tiles_kept's lists, or null: cull here
    std::vector<std::vector<int>> batches;
    // Scratch reused across batches: each batch's (tile, slot) pairs, then sorted by tile with a
    // counting sort that keeps slot order (no container per tile).
    std::vector<std::pair<int, int>> pairs;
    std::vector<int> start, next, sorted;
    std::vector<TileQuad> row;            // a row's merged runs
    std::vector<size_t> open, next_open;  // quads that may grow down over the next row

    Impl(const TileDepth* depth, int tiles_x, int tiles_y) : culler(depth, tiles_x, tiles_y) {}
};

TilePlanner::TilePlanner(const std::vector<ScissorRect>& rects, int width, int height, int tile_size,
                         int lights_per_pass, int batch_size, const TileDepth* depth,
                         const std::vector<std::vector<int>>* kept, const std::vector<bool>* shadowed,
                         int max_shadowed) {
    if (width <= 0 || height <= 0 || tile_size <= 0 || lights_per_pass <= 0 || batch_size <= 0) return;
    if (kept && kept->size() != rects.size()) throw std::logic_error("TilePlanner: one kept list per rectangle");
    const int tx = (width + tile_size - 1) / tile_size, ty = (height + tile_size - 1) / tile_size;
    impl_ = std::make_unique<Impl>(depth, tx, ty);
    Impl& m = *impl_;
    m.width = width, m.height = height, m.ts = tile_size, m.n = lights_per_pass, m.tx = tx, m.ty = ty;
    m.kept = kept;
    const std::vector<int> order = morton_order(rects, width, height, tile_size, m.clipped, m.culler, kept);
    m.batches = cut_batches(order, batch_size, shadowed, max_shadowed);
    m.start.resize(size_t(tx) * ty + 1);
    m.next.resize(size_t(tx) * ty);
}

TilePlanner::~TilePlanner() = default;

const std::vector<std::vector<int>>& TilePlanner::batches() const {
    static const std::vector<std::vector<int>> none;
    return impl_ ? impl_->batches : none;
}

long long TilePlanner::plan_batch(int b, std::vector<TileDraw>& out) {
    Impl& m = *impl_;
    const int ts = m.ts, tx = m.tx, ty = m.ty, n = m.n;
    const std::vector<int>& batch = m.batches[size_t(b)];
    if (batch.empty()) return 0;
    // The rows and columns of tiles the batch's rectangles reach: the lists below are built and
    // walked there alone, not over the screen (a batch's lights lie near each other in Morton
    // order, and a frame of thousands of lights has tens of batches).
    int rx0 = tx, rx1 = -1, ry0 = ty, ry1 = -1;
    for (const int l : batch) {
        const ScissorRect& r = m.clipped[size_t(l)];
        rx0 = std::min(rx0, r.x0 / ts), rx1 = std::max(rx1, (r.x1 - 1) / ts);
        ry0 = std::min(ry0, r.y0 / ts), ry1 = std::max(ry1, (r.y1 - 1) / ts);
    }
    m.pairs.clear();
    for (int slot = 0; slot < int(batch.size()); ++slot) {
        const int l = batch[size_t(slot)];
        if (m.kept) {  // the order of a light's tiles does not matter: the sort below is by tile, stable in slot
            for (int t : (*m.kept)[size_t(l)]) m.pairs.emplace_back(t, slot);
            continue;
        }
        m.culler.each(l, m.clipped[size_t(l)], ts, [&](int x, int y) {
            m.pairs.emplace_back(y * tx + x, slot);
            return false;
        });
    }
    // Tiles [t0, t1), whole rows, hold every pair: start and next are set there alone.
    const size_t t0 = size_t(ry0) * tx, t1 = size_t(ry1 + 1) * tx;
    std::fill(m.start.begin() + std::ptrdiff_t(t0), m.start.begin() + std::ptrdiff_t(t1) + 1, 0);
    for (const auto& [t, slot] : m.pairs) ++m.start[size_t(t) + 1];
    int most = 0;
    for (size_t t = t0; t < t1; ++t) {
        most = std::max(most, m.start[t + 1]);
        m.start[t + 1] += m.start[t];
    }
    m.sorted.resize(m.pairs.size());
    std::copy(m.start.begin() + std::ptrdiff_t(t0), m.start.begin() + std::ptrdiff_t(t1), m.next.begin() + std::ptrdiff_t(t0));
    for (const auto& [t, slot] : m.pairs) m.sorted[size_t(m.next[size_t(t)]++)] = slot;
    long long pairs = 0;
    // Merged quads: a run of tiles along a row with the same lights is one quad, and a quad of the
    // row above with the same span and lights grows down over it. The same pixels shade the same
    // lights in the same order, with fewer quads to set up: lights as large as 32-large's give
    // most tiles the same list (docs/tiles.md, "Tiles as points").
    for (int first = 0; first < most; first += n) {
        TileDraw d;
        d.batch = b;
        m.open.clear();  // quads of d ending at this row's top, by x0
        for (int y = ry0; y <= ry1; ++y) {
            m.row.clear();
            for (int x = rx0; x <= rx1; ++x) {
                const size_t t = size_t(y) * tx + x;
                const int count = m.start[t + 1] - m.start[t];
                if (count <= first) continue;
                const int* bin = m.sorted.data() + m.start[t];
                const int* lo = bin + first;
                const int* hi = bin + std::min(count, first + n);
                pairs += long(hi - lo);
                if (!m.row.empty()) {
                    TileQuad& last = m.row.back();
                    if (last.x1 == x * ts && std::equal(lo, hi, last.slots.begin(), last.slots.end())) {
                        last.x1 = std::min(m.width, (x + 1) * ts);
                        continue;
                    }
                }
                m.row.push_back(TileQuad{x * ts, y * ts, std::min(m.width, (x + 1) * ts), std::min(m.height, (y + 1) * ts), {}});
                m.row.back().slots.assign(lo, hi);
            }
            m.next_open.clear();
            size_t k = 0;
            for (const TileQuad& q : m.row) {
                while (k < m.open.size() && d.quads[m.open[k]].x0 < q.x0) ++k;
                if (k < m.open.size()) {
                    TileQuad& above = d.quads[m.open[k]];
                    if (above.x0 == q.x0 && above.x1 == q.x1 &&
                        std::equal(q.slots.begin(), q.slots.end(), above.slots.begin(), above.slots.end())) {
                        above.y1 = q.y1;
                        m.next_open.push_back(m.open[k++]);
                        continue;
                    }
                }
                m.next_open.push_back(d.quads.size());
                d.quads.push_back(q);
            }
            m.open.swap(m.next_open);
        }
        out.push_back(std::move(d));
    }
    return pairs;
}

TilePlan plan_tiles(const std::vector<ScissorRect>& rects, int width, int height, int tile_size,
                    int lights_per_pass, int batch_size, const TileDepth* depth, const std::vector<bool>* shadowed,
                    int max_shadowed) {
    TilePlanner planner(rects, width, height, tile_size, lights_per_pass, batch_size, depth, nullptr, shadowed,
                        max_shadowed);
    TilePlan plan;
    plan.batches = planner.batches();
    for (int b = 0; b < int(plan.batches.size()); ++b) plan.tile_light_pairs += planner.plan_batch(b, plan.draws);
    return plan;
}

}  // namespace dsr
