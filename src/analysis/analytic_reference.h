// The analytic reference: the scene's own triangles ray-traced in double precision on the CPU,
// shaded with Equations 1-6 in double (docs/errata.md #1-2: v towards the viewer, h from the
// unit l). What the rasteriser approximates, without its float math, without the G-buffer's
// 8-bit quantisation and without any 8-bit accumulation: one ray through each pixel centre
// (where GL samples coverage), the nearest front-facing hit (back faces culled as GL does,
// the near and far planes clip), the normal the barycentric mix of the vertex normals
// (Phong shading, §2.3), then ambient * M_diff + the sum of the lights, clamped to [0, 1];
// the background colour where nothing is hit. No GL.
//
// Only scenes with constant materials (no diffuse, normal or specular map): it checks the
// lighting math, not texture filtering.
#pragma once
#include <cstdint>
#include <vector>

#include "analysis/image_metrics.h"
#include "scene/image.h"
#include "scene/scene.h"

namespace dsr {

// Off by default (the reference). Each switch makes the trace round one quantity the way the
// deferred path does, so that path's error can be attributed term by term; it is an error
// model, not a reference.
struct AnalyticOptions {
    bool gbuffer_normals_8bit = false;    // G-buffer target 0: n*0.5+0.5 in RGBA8, renormalised
    bool gbuffer_materials_8bit = false;  // targets 1-2: M_diff, M_spec in RGBA8; M_shi as its
                                          // 8-bit log2(M_shi)/11 code (encode_shininess)
    bool passes_8bit = false;             // P-buffer 0 is RGBA8: the ambient pass and each light
                                          // pass are rounded to 8 bits before they are added
};

struct AnalyticTrace {
    Image image;             // RGBA, alpha 1, row 0 = bottom (like dsr::read_pixels)
    std::vector<int> mesh;   // per pixel: index into Scene::meshes of the hit, -1 for background
    std::vector<double> eye_depth;  // per pixel: -z of the hit in eye space (exact, double), 0 for background
};

// Throws dsr::Error if a material has a texture map or the size is not positive.
AnalyticTrace analytic_trace(const Scene& scene, int width, int height, const AnalyticOptions& opts = {});
Image analytic_reference(const Scene& scene, int width, int height);

// 1 where the pixel and its 8 neighbours (those inside the image) saw the same mesh (or all
// background) in the trace: pixels away from silhouettes and contacts, where coverage at
// triangle edges (the rasteriser's float edge functions and tie rules against the exact trace)
// cannot make the compared images show different surfaces.
std::vector<uint8_t> interior_mask(const AnalyticTrace& trace, int width, int height);

// compare_images limited to pixels with mask != 0; `pixels` counts those.
ImageDiff compare_images_masked(const Image& a, const Image& b, const std::vector<uint8_t>& mask,
                                double fail_threshold);

}  // namespace dsr
