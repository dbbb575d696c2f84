// How a rendered shadow is measured against the analytic reference's shadow rays
// (AnalyticTrace::occluded). Pure functions of images and masks, no GL; the accuracy tests
// (tests/test_shadow_accuracy.cpp) and the stress sweep's shadow cases use them.
//
// Per light, with the scene rendered three times with that light alone (shadows on, shadows off,
// the light removed):
//   - considered pixels: interior pixels (analytic_reference.h) where the light, unshadowed,
//     adds at least `min_contrast` to some channel in the reference, so "shadowed" has a meaning;
//   - the renderer's class: shadowed where shadows on removes more than half of what the light
//     adds (off - on > (off - dark) / 2, summed over RGB): a filtered edge is cut where its
//     coverage crosses one half, as the traced edge is where the ray grazes the occluder;
//   - the reference's class: the trace's occluded mask;
//   - boundary pixels: pixels of the edge's domain with a 4-neighbour, also in it, of the other
//     reference class (both sides of the traced edge). The domain is every interior pixel, not
//     only the considered ones: where the light is too faint to judge the renderer the traced
//     edge still runs on, and a wrong pixel beside it is that far from it, not from where the
//     considered region ends;
//   - boundary error: for each considered pixel the two classes disagree on, the distance in
//     pixels (between centres) to the nearest boundary pixel; its max is the shadow edge's error.
// Acne and peter-panning are the two ways a depth bias goes wrong:
//   - acne: pixels darker than the reference by more than a threshold on surfaces the light
//     reaches, away from every boundary (a band of `band` pixels around the traced edges of
//     every light, and silhouettes, excluded): self-shadowing;
//   - peter-panning: reference-shadowed receiver pixels next to the occluder's contact (within
//     `reach` pixels of a pixel of the occluder) that the renderer lights: light leaking under
//     the occluder.
#pragma once
#include <cstdint>
#include <vector>

#include "scene/image.h"
#include "scene/scene.h"

namespace dsr {

using Mask = std::vector<uint8_t>;  // one byte per pixel, row 0 = bottom, non-zero = set

// Pixels where `lit` (the light alone, reference) exceeds `dark` (no light) by min_contrast in
// some channel, restricted to `interior`.
Mask shadow_considered(const Image& lit, const Image& dark, const Mask& interior, double min_contrast);

// The renderer's class (1 = shadowed) from its three images; see above.
Mask shadow_class(const Image& on, const Image& off, const Image& dark);

struct ShadowEdgeError {
    long long considered = 0, boundary = 0;  // pixels
    long long ref_shadowed = 0, got_shadowed = 0;
    long long mismatched = 0;                // considered pixels the classes disagree on
    double max_px = 0, mean_px = 0;          // distance of mismatches to the nearest boundary
                                             // pixel (infinite when there is no boundary)
    long long beyond(double px) const;       // mismatches further than px
    std::vector<double> distances;           // one per mismatch
    std::vector<size_t> pixels;              // the mismatches' pixels (y * w + x), as distances
};

// Boundary pixels of `ref` among `domain` (width w, height h).
Mask shadow_boundary(const Mask& ref, const Mask& domain, int w, int h);

// Mismatches counted on `considered`, their distances to the boundary among `domain` (null:
// considered itself).
ShadowEdgeError shadow_edge_error(const Mask& ref, const Mask& got, const Mask& considered, int w, int h,
                                  const Mask* domain = nullptr);

// Pixels within `radius` (Euclidean, between centres) of a set pixel of `m`.
Mask dilate(const Mask& m, int w, int h, double radius);

// Edges of the reference's occluded mask over all pixels (a pixel whose occluded value differs
// from one of its 8 neighbours), for the acne band.
Mask occlusion_edges(const Mask& occluded, int w, int h);

struct AcneCount {
    long long pixels = 0;   // pixels compared
    long long darker = 0;   // of them, darker than the reference by more than the threshold
    double max_darker_lsb = 0;
};
// Pixels set in `where`: how many are darker in `got` than in `ref` by more than threshold_lsb in
// some channel.
AcneCount acne(const Image& got, const Image& ref, const Mask& where, double threshold_lsb);

struct ContactLeak {
    long long contact = 0;  // reference-shadowed considered receiver pixels near the occluder
    long long leaked = 0;   // of them, lit by the renderer
    double fraction() const { return contact ? double(leaked) / double(contact) : 0; }
};
// receiver / occluder: per-pixel masks of the two meshes (from AnalyticTrace::mesh).
ContactLeak contact_leak(const Mask& ref, const Mask& got, const Mask& considered, const Mask& receiver,
                         const Mask& occluder, int w, int h, double reach);

// The three measures of one light's shadow in one rendered image, against the trace: what the
// stress sweep's shadow cases record (stress_cases.h). `scene` has one light, with shadow.on;
// `trace` is analytic_trace(scene) at the image's size; `rendered` the renderer's final image.
// The renderer's class comes from `rendered` against the reference's images with the light
// unshadowed and without it (one render per case; the light's term is at least min_contrast
// where it is judged, far above the deferred path's few LSB, so the half cut is not moved by them).
// receiver / occluder: the objects (Scene::objects indices) the shadow falls on and is cast by.
struct ShadowMeasure {
    ShadowEdgeError edge;
    AcneCount acne;     // darker than the trace by more than 8 LSB, 2 pixels or more from an edge
    ContactLeak leak;   // within 3 pixels of the occluder
};
struct AnalyticTrace;
ShadowMeasure measure_shadow(const Scene& scene, const AnalyticTrace& trace, const Image& rendered, int receiver,
                             int occluder, double min_contrast = 24.0 / 255.0);

}  // namespace dsr
