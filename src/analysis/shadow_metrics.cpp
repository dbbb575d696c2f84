// Shadow measures against the traced reference (shadow_metrics.h).
#include "analysis/shadow_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/analytic_reference.h"
#include "dsr_error.h"

namespace dsr {

namespace {

void check(const Mask& m, int w, int h, const char* what) {
    if (w <= 0 || h <= 0 || m.size() != size_t(w) * size_t(h)) throw Error(std::string("shadow metrics: ") + what + " has the wrong size");
}
void check(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height) throw Error("shadow metrics: image sizes differ");
}

}  // namespace

Mask shadow_considered(const Image& lit, const Image& dark, const Mask& interior, double min_contrast) {
    check(lit, dark);
    check(interior, lit.width, lit.height, "the interior mask");
    Mask m(interior.size(), 0);
    for (size_t p = 0; p < m.size(); ++p) {
        if (!interior[p]) continue;
        double c = 0;
        for (int k = 0; k < 3; ++k) c = std::max(c, double(lit.rgba[p * 4 + k]) - double(dark.rgba[p * 4 + k]));
        m[p] = c >= min_contrast;
    }
    return m;
}

Mask shadow_class(const Image& on, const Image& off, const Image& dark) {
    check(on, off);
    check(on, dark);
    Mask m(size_t(on.width) * on.height, 0);
    for (size_t p = 0; p < m.size(); ++p) {
        double removed = 0, adds = 0;
        for (int k = 0; k < 3; ++k) {
            removed += double(off.rgba[p * 4 + k]) - double(on.rgba[p * 4 + k]);
            adds += double(off.rgba[p * 4 + k]) - double(dark.rgba[p * 4 + k]);
        }
        m[p] = adds > 0 && removed > 0.5 * adds;
    }
    return m;
}

long long ShadowEdgeError::beyond(double px) const {
    return std::count_if(distances.begin(), distances.end(), [&](double d) { return d > px; });
}

Mask shadow_boundary(const Mask& ref, const Mask& considered, int w, int h) {
    check(ref, w, h, "the reference mask");
    check(considered, w, h, "the boundary's domain");
    Mask b(ref.size(), 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t p = size_t(y) * w + x;
            if (!considered[p]) continue;
            const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
            for (int k = 0; k < 4 && !b[p]; ++k) {
                const int nx = x + dx[k], ny = y + dy[k];
                if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                const size_t q = size_t(ny) * w + nx;
                b[p] = considered[q] && (ref[q] != 0) != (ref[p] != 0);
            }
        }
    return b;
}

ShadowEdgeError shadow_edge_error(const Mask& ref, const Mask& got, const Mask& considered, int w, int h,
                                  const Mask* domain) {
    check(got, w, h, "the renderer's mask");
    check(considered, w, h, "the considered mask");
    const Mask b = shadow_boundary(ref, domain ? *domain : considered, w, h);
    std::vector<std::pair<int, int>> edge;
    ShadowEdgeError e;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t p = size_t(y) * w + x;
            if (b[p]) edge.push_back({x, y});
            if (!considered[p]) continue;
            ++e.considered;
            e.ref_shadowed += ref[p] != 0;
            e.got_shadowed += got[p] != 0;
        }
    e.boundary = (long long)edge.size();
    double sum = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t p = size_t(y) * w + x;
            if (!considered[p] || (ref[p] != 0) == (got[p] != 0)) continue;
            ++e.mismatched;
            double best = std::numeric_limits<double>::infinity();
            for (const auto& [bx, by] : edge) best = std::min(best, std::hypot(double(bx - x), double(by - y)));
            e.distances.push_back(best);
            e.pixels.push_back(p);
            e.max_px = std::max(e.max_px, best);
            sum += best;
        }
    e.mean_px = e.mismatched ? sum / double(e.mismatched) : 0;
    return e;
}

Mask dilate(const Mask& m, int w, int h, double radius) {
    check(m, w, h, "the mask");
    const int r = int(std::floor(radius));
    Mask out(m.size(), 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!m[size_t(y) * w + x]) continue;
            for (int dy = -r; dy <= r; ++dy)
                for (int dx = -r; dx <= r; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h || dx * dx + dy * dy > radius * radius) continue;
                    out[size_t(ny) * w + nx] = 1;
                }
        }
    return out;
}

Mask occlusion_edges(const Mask& occluded, int w, int h) {
    check(occluded, w, h, "the occluded mask");
    Mask e(occluded.size(), 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t p = size_t(y) * w + x;
            for (int dy = -1; dy <= 1 && !e[p]; ++dy)
                for (int dx = -1; dx <= 1 && !e[p]; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    e[p] = (occluded[size_t(ny) * w + nx] != 0) != (occluded[p] != 0);
                }
        }
    return e;
}

AcneCount acne(const Image& got, const Image& ref, const Mask& where, double threshold_lsb) {
    check(got, ref);
    check(where, got.width, got.height, "the acne mask");
    AcneCount a;
    for (size_t p = 0; p < where.size(); ++p) {
        if (!where[p]) continue;
        ++a.pixels;
        double d = 0;
        for (int k = 0; k < 3; ++k) d = std::max(d, double(ref.rgba[p * 4 + k]) - double(got.rgba[p * 4 + k]));
        a.max_darker_lsb = std::max(a.max_darker_lsb, d * 255.0);
        a.darker += d * 255.0 > threshold_lsb;
    }
    return a;
}

ContactLeak contact_leak(const Mask& ref, const Mask& got, const Mask& considered, const Mask& receiver,
                         const Mask& occluder, int w, int h, double reach) {
    check(receiver, w, h, "the receiver mask");
    const Mask near = dilate(occluder, w, h, reach);
    ContactLeak c;
    for (size_t p = 0; p < ref.size(); ++p) {
        if (!considered[p] || !receiver[p] || !near[p] || !ref[p]) continue;
        ++c.contact;
        c.leaked += !got[p];
    }
    return c;
}

ShadowMeasure measure_shadow(const Scene& scene, const AnalyticTrace& trace, const Image& rendered, int receiver,
                             int occluder, double min_contrast) {
    if (scene.lights.size() != 1 || trace.occluded.size() != 1 || trace.occluded[0].empty())
        throw Error("measure_shadow: the scene must have one light, traced with its shadow");
    const int w = rendered.width, h = rendered.height;
    check(rendered, trace.image);
    AnalyticOptions unshadowed;
    unshadowed.shadows = false;
    const Image lit = analytic_trace(scene, w, h, unshadowed).image;
    Scene none = scene;
    none.lights.clear();
    const Image dark = analytic_trace(none, w, h).image;
    const Mask interior = interior_mask(trace, w, h);
    const Mask considered = shadow_considered(lit, dark, interior, min_contrast);
    const Mask got = shadow_class(rendered, lit, dark);
    const Mask& ref = trace.occluded[0];
    ShadowMeasure m;
    m.edge = shadow_edge_error(ref, got, considered, w, h, &interior);
    const Mask band = dilate(occlusion_edges(ref, w, h), w, h, 2);
    Mask where(ref.size());
    for (size_t p = 0; p < where.size(); ++p) where[p] = interior[p] && !band[p] && trace.mesh[p] >= 0;
    m.acne = acne(rendered, trace.image, where, 8);
    Mask rec(ref.size()), occ(ref.size());
    for (size_t p = 0; p < ref.size(); ++p) {
        rec[p] = trace.mesh[p] == receiver;
        occ[p] = trace.mesh[p] == occluder;
    }
    m.leak = contact_leak(ref, got, considered, rec, occ, w, h, 3);
    return m;
}

}  // namespace dsr
