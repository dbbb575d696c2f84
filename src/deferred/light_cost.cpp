// The auto geometry's cost model (light_cost.h).
#include "deferred/light_cost.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "dsr_error.h"

namespace dsr {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMpx = 1e-6;
}  // namespace

const char* light_path_name(LightPath p) {
    switch (p) {
        case LightPath::quad: return "quad";
        case LightPath::volume: return "volume";
        case LightPath::tiles: return "tiles";
    }
    return "?";
}

LightCostModel default_light_costs(bool software_rasterizer) {
    LightCostModel m;
    if (software_rasterizer) {
        // llvmpipe: the light stage's ms of each geometry on the bench scenes fitted to the terms;
        // the ratios are what the choice uses (docs/light_cost.md, "A CPU rasteriser").
        m.quad_draw_ms = 0.045, m.quad_mpx_ms = 21;
        // Against the depth: the pixels behind the light rejected before the shader runs.
        m.quad_depth_mpx_ms = 16;
        // Volumes in batches (LightVolumeBatch), fitted to `render --light-geometry volume` on the
        // bench scenes.
        m.volume_draw_ms = 0.049, m.volume_mpx_ms = 6.1;
        // The hand-off by a pass (--depth-handoff pass, or no blit); writing the ambient term too,
        // priced less the ambient pass it replaces (handoff_ms).
        m.handoff_mpx_ms = 0.5, m.handoff_pass_mpx_ms = 4.6;
        m.handoff_ambient_mpx_ms = 9, m.ambient_mpx_ms = 5;
        // The spans read back and reduced on the CPU (tile_spans.h), with the two passes before
        // them.
        m.spans_mpx_ms = 2;
        m.tile_pass_mpx_ms = 20, m.tile_light_mpx_ms = 13.5;
        // A path drawn at all: its programs and state, and on llvmpipe the scene it flushes (so a
        // few lights by a second path can cost more than they save).
        m.path_ms = 0.4;
        m.shadow_mpx_ms = 13.5;  // estimated, not fitted: about a light term in the tiles loop
    } else {
        // An NVIDIA GPU through EGL, each path forced (tests/gpu_bench.sh part auto;
        // docs/light_cost.md, "A GPU"): batched quads cost the CPU almost nothing a light; the
        // tiles' spans are a read-back the GPU drains for.
        m.quad_draw_ms = 0.0001, m.quad_mpx_ms = 0.075;
        // Against the depth: quad_mpx_ms less the mean of what two light counts saved per Mpx; the
        // hand-off it needs is priced apart (handoff_mpx_ms).
        m.quad_depth_mpx_ms = 0.055;
        // Volumes in batches (LightVolumeBatch).
        m.volume_draw_ms = 0.00014, m.volume_mpx_ms = 0.062;
        // The hand-off's pass writing the ambient term costs no more than the ambient pass it
        // replaces, so it costs the frame nothing more. The pass without the term (a GPU takes it
        // only with SSAO and no blit) is not measured: priced as the pass with it.
        m.handoff_mpx_ms = 0.072, m.handoff_pass_mpx_ms = 0.13;
        m.handoff_ambient_mpx_ms = 0.13, m.ambient_mpx_ms = 0.139;
        m.spans_mpx_ms = 0.35;
        m.tile_pass_mpx_ms = 0.3, m.tile_light_mpx_ms = 0.12;
        m.path_ms = 0.02;
        m.shadow_mpx_ms = 0.05;  // not measured on the GPU: about a light term's
    }
    return m;
}

std::string describe(const LightCostModel& m) {
    std::ostringstream o;
    o << "  quad           " << m.quad_draw_ms << " ms a light + " << m.quad_mpx_ms << " ms per Mpx of its rectangle ("
      << m.quad_depth_mpx_ms << " against the scene's depth)\n"
      << "  volume         " << m.volume_draw_ms << " ms a light + " << m.volume_mpx_ms
      << " ms per Mpx of its rectangle; hand-off " << m.handoff_mpx_ms << " ms per Mpx of screen\n"
      << "                 (a pass " << m.handoff_pass_mpx_ms << "; one that writes the ambient term "
      << m.handoff_ambient_mpx_ms << " less the ambient pass's " << m.ambient_mpx_ms << ")\n"
      << "  tiles          " << m.tile_pass_mpx_ms << " ms per Mpx of tile pixels per pass + " << m.tile_light_mpx_ms
      << " ms per Mpx of (tile pixel, light) pairs; depth spans " << m.spans_mpx_ms << " ms per Mpx of screen,\n"
      << "                 measured where the lights would cost over " << m.spans_worth << "x that\n"
      << "  each path used " << m.path_ms << " ms a frame\n"
      << "  a path not yet measured is tried where predicted within " << m.explore_within << "x the best plan\n"
      << "  shadowed light " << m.shadow_mpx_ms << " ms per Mpx of its rectangle more, on every path\n";
    return o.str();
}

void tile_cover(const std::vector<ScissorRect>& rects, int width, int height, int tile_size, const TileDepth* depth,
                std::vector<LightFeature>& lights, TileGrid& grid) {
    const int tx = (width + tile_size - 1) / tile_size, ty = (height + tile_size - 1) / tile_size;
    grid.tile_px = tile_size * tile_size;
    grid.lights.assign(size_t(tx) * size_t(ty), 0);
    lights.resize(rects.size());
    std::vector<std::vector<int>> kept = tiles_kept(rects, width, height, tile_size, depth);  // the plans' culling
    for (size_t i = 0; i < rects.size(); ++i) {
        lights[i].tiles = std::move(kept[i]);
        for (int t : lights[i].tiles) ++grid.lights[size_t(t)];
    }
}

std::array<double, kLightPaths> light_prices(const LightFeature& l, const TileGrid& grid, const LightCostModel& m,
                                             const std::array<double, kLightPaths>& scale) {
    // A shadowed light's lookups: the same pixels (those inside its volume) on every path.
    const double shadow = l.shadowed ? m.shadow_mpx_ms * l.rect_px * kMpx : 0;
    std::array<double, kLightPaths> p;
    p[int(LightPath::quad)] = scale[0] * (m.quad_draw_ms + m.quad_mpx_ms * l.rect_px * kMpx) + scale[0] * shadow;
    p[int(LightPath::volume)] =
        l.volume_ok ? scale[1] * (m.volume_draw_ms + m.volume_mpx_ms * l.rect_px * kMpx) + scale[1] * shadow : kInf;
    if (!l.tiles_ok) {
        p[int(LightPath::tiles)] = kInf;
        return p;
    }
    // Its share of each tile it keeps: the tile's passes (ceil(k / N) of them) divided among its
    // k lights, and its own term in the loop.
    double px = 0;
    for (int t : l.tiles) {
        const int k = std::max(1, grid.lights[size_t(t)]);
        const double passes = std::ceil(double(k) / grid.lights_per_pass);
        px += grid.tile_px * (m.tile_pass_mpx_ms * passes / k + m.tile_light_mpx_ms);
    }
    p[int(LightPath::tiles)] = scale[2] * px * kMpx + scale[2] * shadow;
    return p;
}

LightPrices price_lights(const std::vector<LightFeature>& lights, const TileGrid& grid, const LightCostModel& m) {
    // light_prices' tile term once per tile, not once per (light, tile) pair: the same expression
    // summed in the same order, so the same prices to the bit (LightCost.PriceLightsIsLightPrices).
    std::vector<double> share(grid.lights.size());
    for (size_t t = 0; t < share.size(); ++t) {
        const int k = std::max(1, grid.lights[t]);
        const double passes = std::ceil(double(k) / grid.lights_per_pass);
        share[t] = grid.tile_px * (m.tile_pass_mpx_ms * passes / k + m.tile_light_mpx_ms);
    }
    LightPrices p(lights.size());
    for (size_t i = 0; i < lights.size(); ++i) {
        const LightFeature& l = lights[i];
        LightFeature no_tiles;  // the quad and volume terms from light_prices itself
        no_tiles.rect_px = l.rect_px, no_tiles.volume_ok = l.volume_ok, no_tiles.tiles_ok = false;
        p[i] = light_prices(no_tiles, grid, m, {1, 1, 1});
        if (!l.tiles_ok) continue;
        double px = 0;
        for (int t : l.tiles) px += share[size_t(t)];
        p[i][int(LightPath::tiles)] = px * kMpx;
    }
    return p;
}

LightPathPlan choose_light_paths(const std::vector<LightFeature>& lights, const TileGrid& grid, double screen_px,
                                 const LightCostModel& m, const std::array<double, kLightPaths>& scale,
                                 const std::array<bool, kLightPaths>& allowed, bool spans_paid) {
    return choose_light_paths(price_lights(lights, grid, m), screen_px, m, scale, allowed, spans_paid);
}

double handoff_ms(const LightCostModel& m, double screen_px) {
    const double mpx_ms =
        m.handoff_writes_ambient ? std::max(0.0, m.handoff_ambient_mpx_ms - m.ambient_mpx_ms)
        : m.handoff_pass         ? m.handoff_pass_mpx_ms
                                 : m.handoff_mpx_ms;
    return mpx_ms * screen_px * kMpx;
}

namespace {

// What drawing a light's quad against the scene's depth saves it, unscaled (quad_depth_savings).
double quad_depth_saving(const LightFeature& l, const LightCostModel& m) {
    return l.shadowed ? 0 : (m.quad_mpx_ms - m.quad_depth_mpx_ms) * l.rect_px * kMpx;
}

// What a plan's paths add once a frame (choose_light_paths): each path used, the hand-off where a
// volume is drawn, the spans where the tiles are; and the total.
void add_frame_costs(LightPathPlan& p, const LightCostModel& m, double handoff, double spans) {
    for (int k = 0; k < kLightPaths; ++k)
        if (p.count[size_t(k)]) p.predicted_ms[size_t(k)] += m.path_ms;
    if (p.count[1])
        p.predicted_ms[1] += handoff;
    else if (p.quads_depth)
        p.predicted_ms[0] += handoff;
    if (p.count[2]) p.predicted_ms[2] += spans;
    p.predicted_total_ms = p.predicted_ms[0] + p.predicted_ms[1] + p.predicted_ms[2];
}

}  // namespace

LightPathPlan choose_light_paths(const LightPrices& raw, double screen_px, const LightCostModel& m,
                                 const std::array<double, kLightPaths>& scale,
                                 const std::array<bool, kLightPaths>& allowed, bool spans_paid,
                                 const std::vector<double>* quad_depth_saving) {
    const size_t n = raw.size();
    const double handoff = handoff_ms(m, screen_px);
    const double spans = spans_paid ? 0 : m.spans_mpx_ms * screen_px * kMpx;
    LightPathPlan best;
    best.predicted_total_ms = kInf;
    // The per-frame costs make the choice of one light depend on the others only through which
    // paths are used at all (and whether the quads test the depth): for each set of paths in use,
    // each light takes its cheapest in the set.
    for (const bool depth : {false, true}) {
        if (depth && !quad_depth_saving) break;
        LightPrices prices = raw;
        for (size_t i = 0; i < n; ++i) {
            if (depth) prices[i][0] -= (*quad_depth_saving)[i];
            for (int k = 0; k < kLightPaths; ++k) prices[i][size_t(k)] *= scale[size_t(k)];
        }
        for (int mask = 1; mask < (1 << kLightPaths); ++mask) {
            // A set without quads prices the same either way: the first pass has it.
            if (depth && !(mask & 1 << int(LightPath::quad))) continue;
            bool possible = true;
            for (int k = 0; k < kLightPaths; ++k) possible &= !(mask >> k & 1) || allowed[size_t(k)];
            if (!possible) continue;
            LightPathPlan p;
            p.path.resize(n);
            for (size_t i = 0; i < n && possible; ++i) {
                int c = -1;
                for (int k = 0; k < kLightPaths; ++k)
                    if ((mask >> k & 1) && prices[i][size_t(k)] < kInf && (c < 0 || prices[i][size_t(k)] < prices[i][size_t(c)]))
                        c = k;
                if (c < 0) {
                    possible = false;  // a light no path of the set can take
                    break;
                }
                p.path[i] = LightPath(c);
                ++p.count[size_t(c)];
                p.predicted_ms[size_t(c)] += prices[i][size_t(c)];
            }
            if (!possible) continue;
            p.quads_depth = depth && p.count[0] > 0;
            add_frame_costs(p, m, handoff, spans);
            if (p.predicted_total_ms < best.predicted_total_ms) best = std::move(p);
        }
    }
    return best;
}

std::vector<double> quad_depth_savings(const std::vector<LightFeature>& lights, const LightCostModel& m) {
    std::vector<double> s(lights.size());
    for (size_t i = 0; i < lights.size(); ++i) s[i] = quad_depth_saving(lights[i], m);
    return s;
}

std::optional<LightExploration> exploration_plan(const LightPrices& raw, const LightPathPlan& best, double screen_px,
                                                 const LightCostModel& m, const std::array<double, kLightPaths>& scale,
                                                 const std::array<bool, kLightPaths>& explore, bool spans_paid) {
    if (raw.empty() || best.path.size() != raw.size() || !(best.predicted_total_ms < kInf)) return std::nullopt;
    const double handoff = handoff_ms(m, screen_px);
    const double spans = spans_paid ? 0 : m.spans_mpx_ms * screen_px * kMpx;
    std::optional<LightExploration> out;
    for (int k = 0; k < kLightPaths; ++k) {
        if (!explore[size_t(k)] || best.count[size_t(k)] > 0) continue;  // drawn by best: measured anyway
        LightPathPlan p;
        p.path = best.path;
        for (size_t i = 0; i < raw.size(); ++i) {
            if (raw[i][size_t(k)] < kInf) p.path[i] = LightPath(k);
            const int c = int(p.path[i]);
            ++p.count[size_t(c)];
            p.predicted_ms[size_t(c)] += raw[i][size_t(c)] * scale[size_t(c)];
        }
        if (p.count[size_t(k)] == 0) continue;
        add_frame_costs(p, m, handoff, spans);
        if (p.predicted_total_ms <= m.explore_within * best.predicted_total_ms &&
            (!out || p.predicted_total_ms < out->plan.predicted_total_ms))
            out = LightExploration{LightPath(k), std::move(p)};
    }
    return out;
}

QuadDepthChoice choose_quad_depth(const LightPathPlan& plan, const std::vector<LightFeature>& lights,
                                  double screen_px, const LightCostModel& m, double quad_scale) {
    QuadDepthChoice c;
    double saving = 0;
    for (size_t i = 0; i < lights.size() && i < plan.path.size(); ++i)
        if (plan.path[i] == LightPath::quad) saving += quad_depth_saving(lights[i], m);
    if (saving <= 0) return c;
    const double handoff = plan.count[int(LightPath::volume)] > 0 ? 0 : handoff_ms(m, screen_px);
    if (quad_scale * saving <= handoff && !plan.quads_depth) return c;
    c.on = true;
    c.raw_saving_ms = saving;
    c.handoff_ms = handoff;
    return c;
}

bool spans_worth_measuring(double best_without_tiles_ms, double screen_px, const LightCostModel& m) {
    return best_without_tiles_ms > m.spans_worth * m.spans_mpx_ms * screen_px * kMpx;
}

void LightCostCalibration::add(LightPath p, double measured_ms, double predicted_raw_ms) {
    if (!(predicted_raw_ms > 0) || !(measured_ms >= 0)) return;
    double& s = scale_[int(p)];
    const double ratio = measured_ms / predicted_raw_ms;
    // The first measurement replaces the guess; given scales, and later measurements, are averaged with.
    s = std::clamp(given_ || samples_[int(p)] > 0 ? 0.5 * s + 0.5 * ratio : ratio, 0.1, 10.0);
    ++samples_[int(p)];
}

std::array<double, kLightPaths> parse_cost_scale(const std::string& text) {
    std::array<double, kLightPaths> out{};
    std::istringstream in(text);
    for (int i = 0; i < kLightPaths; ++i) {
        char comma = ',';
        if ((i > 0 && !(in >> comma)) || comma != ',' || !(in >> out[size_t(i)]) || !(out[size_t(i)] > 0) ||
            !std::isfinite(out[size_t(i)]))
            throw Error("DSR_LIGHT_COST_SCALE '" + text + "': expected three positive numbers quad,volume,tiles");
    }
    std::string rest;
    if (in >> rest) throw Error("DSR_LIGHT_COST_SCALE '" + text + "': expected three positive numbers quad,volume,tiles");
    return out;
}

}  // namespace dsr
