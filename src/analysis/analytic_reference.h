// The analytic reference: the scene's exact shapes ray-traced in double precision on the CPU,
// shaded with Equations 1-6 in double (docs/errata.md #1-2: v towards the viewer, h from the
// unit l). What the rasteriser approximates, without its float math, without its tessellation,
// without the G-buffer's 8-bit quantisation and without any 8-bit accumulation: one ray through
// each pixel centre (where GL samples coverage), the nearest front-facing hit (back faces culled
// as GL does, the near and far planes clip), then ambient * M_diff + the sum of the lights,
// clamped to [0, 1]; the background colour where nothing is hit. No GL, and none of the
// renderer's code: the camera, shapes, texture filtering and shading are written here again.
//
// Shadows. For each light with shadow.on (and AnalyticOptions::shadows), a shadow ray from the
// hit towards the light (point and spot: to its position; directional: along -dir, unbounded)
// against the same exact shapes, or triangles, both faces: if anything lies on it, the light adds
// nothing at that pixel. The epsilon that keeps the hit's own surface out is argued where it is
// set (shadow_ray_blocked).
//
// Geometry. An object added by add_plane/add_box/add_sphere carries its ShapeDesc, and the trace
// intersects that shape (ray-plane, ray-box slabs, ray-sphere) with the shape's exact normal at
// the hit. An object without one (hand-made, OBJ) is traced as its mesh's triangles, moved to
// world space by its model matrix in double, with the barycentric
// mix of the vertex normals (Phong shading, §2.3). Planes and boxes are exactly their two
// triangles per face, so only spheres differ from what the renderer draws: the 48x24 sphere's
// flat facets lie inside the sphere by at most sphere_tessellation_gap() (0.43% of r for
// 48x24), and its interpolated normal is the radial direction of the facet point
// (p_i = c + r n_i makes the mix of the n_i parallel to the facet point minus c), so at a
// pixel whose ray meets the sphere at incidence theta the renderer's normal is off by at most
// about gap / ((r - gap) cos theta) rad (0.25 degrees head-on, 1 degree at 76 degrees) and its
// position by gap / cos theta. That error is part of what the exact trace measures;
// AnalyticOptions::triangles traces the renderer's triangles instead, to separate it out.
//
// Materials. Phong (Equations 3-4) or glTF's metallic-roughness (metal_rough_brdf below; its
// ambient term is ambient x base colour x occlusion plus the emissive colour, as the material pass
// writes it where it writes the ambient term). Constant materials, plus two kinds of texture map that have a closed form here:
// a diffuse map on a plane, sampled as GL_LINEAR at level 0 (bilinear, GL_REPEAT, texels
// rounded to RGBA8 as the upload stores them; valid only where the map is magnified, which
// AnalyticTrace::max_texel_footprint reports), with AnalyticOptions::bilinear_diffuse_maps;
// and a normal map on a plane made from a BumpMap formula (make_bump_normal_map), shaded with
// the formula's exact normal at the hit's uv, not the texture, when the map's texture index is
// registered in AnalyticOptions::bump_maps. Any other map (specular maps, normal maps without
// a formula, maps on shapes other than planes) is refused with dsr::Error.
#pragma once
#include <cstdint>
#include <map>
#include <vector>

#include <glm/glm.hpp>

#include "analysis/image_metrics.h"
#include "deferred/options.h"
#include "scene/image.h"
#include "scene/scene.h"

namespace dsr {

// Sinusoidal bumps over the map's [0,1]^2 (heights in units of the map's side):
// h(u,v) = amplitude * sin(2 pi k u) * sin(2 pi k v), k = periods (an integer, so the map
// tiles). The tangent-space normal is normalize(-dh/du, -dh/dv, 1).
struct BumpMap {
    double amplitude = 0.04;
    int periods = 2;
};
glm::dvec3 bump_normal(const BumpMap& b, double u, double v);
// The map as the renderer reads it: texel (i, j) holds bump_normal at its centre
// ((i + 0.5) / w, (j + 0.5) / h) as n * 0.5 + 0.5, rounded to 8-bit codes (k / 255).
Image make_bump_normal_map(const BumpMap& b, int w, int h);

// The terms of glTF's metallic-roughness BRDF (docs/metal_rough.md), each of which
// AnalyticOptions::perturb can put off by a relative amount, so a test can show that a render
// that matches the reference would not match it with that term wrong.
enum class BrdfTerm { none, D, V, F, diffuse, metallic_mix };

// The parts of a physical light's law (KHR_lights_punctual, docs/metal_rough.md) that
// AnalyticOptions::perturb_light can put off, as BrdfTerm does for the BRDF.
enum class LightTerm { none, range_window, spot_falloff };

// Off by default (the reference). Each 8-bit switch makes the trace round one quantity the way
// the deferred path does, so that path's error can be attributed term by term; they, and
// `triangles`, are an error model, not a reference.
struct AnalyticOptions {
    bool gbuffer_normals_8bit = false;    // G-buffer target 0: n*0.5+0.5 in RGBA8, renormalised
    bool gbuffer_materials_8bit = false;  // targets 1-2: M_diff, M_spec in RGBA8; M_shi as its
                                          // 8-bit log2(M_shi)/11 code (encode_shininess)
    bool passes_8bit = false;             // P-buffer 0 is RGBA8: the ambient pass and each light
                                          // pass are rounded to 8 bits before they are added
    bool triangles = false;               // trace every mesh's triangles, not its exact shape
    bool bilinear_diffuse_maps = false;   // allow diffuse maps on planes (GL_LINEAR, level 0)
    bool shadows = true;                  // a shadow ray for each light with shadow.on; false:
                                          // every light passes through everything (--shadows off)
    std::map<int, BumpMap> bump_maps;     // texture index -> the formula its normal map was made from
    // The final stage's mapping (docs/hdr.md), written again here from the formulas, in double:
    // the unclamped sum (background included) scaled by 2^exposure, mapped by the operator and
    // clamped, then sRGB-encoded with srgb_output. The defaults are the clamp of the plain trace.
    ToneMap tonemap = ToneMap::none;
    double exposure = 0;                  // stops
    bool srgb_output = false;
    // Metallic-roughness materials: one term of the BRDF put off by perturb_by. D, V: alpha in that
    // term alone scaled by 1 + perturb_by; F, diffuse ((1 - F) c_diff / pi): the term scaled by
    // 1 + perturb_by; metallic_mix: the metallic weight of both mixes (c_diff and F0) moved by
    // + perturb_by, clamped to [0, 1]. none: the BRDF as specified.
    BrdfTerm perturb = BrdfTerm::none;
    double perturb_by = 0;
    // Physical lights: range_window computes the window with the range scaled by
    // 1 + perturb_light_by; spot_falloff raises the cone's clamped term to 2 (1 + perturb_light_by)
    // instead of squaring it. none: the laws as the extension recommends them.
    LightTerm perturb_light = LightTerm::none;
    double perturb_light_by = 0;
};

// glTF 2.0's metallic-roughness BRDF times N.L (Appendix B; docs/metal_rough.md), in double, for
// unit n, l (towards the light) and v (towards the viewer): what one light of colour 1 adds before
// its attenuation. Roughness below kMinRoughness is raised to it, as the shader does.
constexpr double kMinRoughness = 0.03;
glm::dvec3 metal_rough_brdf(const glm::dvec3& n, const glm::dvec3& l, const glm::dvec3& v, const glm::dvec3& base,
                            double metallic, double roughness, BrdfTerm perturb = BrdfTerm::none,
                            double perturb_by = 0);

// That mapping of one linear colour (pure; analytic_trace applies it to every pixel).
glm::dvec3 analytic_output(glm::dvec3 c, const AnalyticOptions& opts);

struct AnalyticTrace {
    Image image;             // RGBA, alpha 1, row 0 = bottom (like dsr::read_pixels)
    std::vector<int> mesh;   // per pixel: index into Scene::objects of the hit, -1 for background
    std::vector<double> eye_depth;  // per pixel: -z of the hit in eye space (exact, double), 0 for background
    // Over the pixels that sampled a texture map: the largest footprint of a pixel in texels
    // (GL's scale factor rho, from the uv at the neighbouring pixel centres). Above 1 the
    // renderer minifies (mipmaps) and the level-0 bilinear reference does not hold there.
    // 0 when no map was sampled.
    double max_texel_footprint = 0;
    // Per light (Scene::lights' order): for the lights traced with shadow rays, per pixel 1 where
    // the light's law reaches the hit (attenuation > 0, inside a spot's cone) and something lies
    // between the hit and the light, so the light adds nothing there; 0 elsewhere. Empty for a
    // light without shadow rays.
    std::vector<std::vector<uint8_t>> occluded;
};

// Throws dsr::Error for a texture map the options do not allow (see above), a mesh without a
// valid material, or a size that is not positive.
AnalyticTrace analytic_trace(const Scene& scene, int width, int height, const AnalyticOptions& opts = {});
Image analytic_reference(const Scene& scene, int width, int height);

// The largest distance between a sphere and the flat facets of make_sphere(r, m, slices,
// stacks), as a fraction of r: 1 - (the least distance from the centre to any facet) / r.
double sphere_tessellation_gap(int slices = 48, int stacks = 24);

// 1 where the pixel and its 8 neighbours (those inside the image) saw the same mesh (or all
// background) in the trace: pixels away from silhouettes and contacts, where coverage at
// triangle edges (the rasteriser's float edge functions and tie rules against the exact trace)
// cannot make the compared images show different surfaces.
std::vector<uint8_t> interior_mask(const AnalyticTrace& trace, int width, int height);

// compare_images limited to pixels with mask != 0; `pixels` counts those.
ImageDiff compare_images_masked(const Image& a, const Image& b, const std::vector<uint8_t>& mask,
                                double fail_threshold);

}  // namespace dsr
