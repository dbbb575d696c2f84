// The ideal light-pass fragment count of a frame: for each light, the pixels whose surface
// point lies inside the light's sphere, summed over lights. What a light pass with a perfect
// per-pixel test would shade; `dsr bench` sets FrameStats::light_fragments (occlusion queries)
// against it. Pure math, no GL.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "deferred/light_volume.h"
#include "scene/image.h"
#include "scene/scene.h"

namespace dsr {

// Eye-space surface positions from a depth-texture read-back (DeferredShader::read_gbuffer(
// PBuffer::DEPTH): window depth in r), rebuilt as the light pass does (Listing 20: eye z from
// `planes`, x and y along the view ray through the pixel centre). rgb = position, alpha 1 where
// there is a surface, 0 where depth is 1 (cleared: background). Same layout as
// DeferredShader::reconstructed_positions(). p00, p11: the projection's P[0][0] and P[1][1].
Image positions_from_depth(const Image& depth, glm::vec2 planes, float p00, float p11);

// lights: eye-space centre in xyz, radius in w. A pixel counts for a light when its position
// (alpha > 0.5) lies strictly inside the sphere: Equation 2's attenuation is zero on and beyond
// it. Lights of radius <= 0 count nothing. Uses 16x16-pixel tiles with eye-space bounding boxes
// to skip most (light, pixel) pairs; the result equals the brute-force count exactly.
long long ideal_fragments(const Image& positions, const std::vector<glm::vec4>& lights);

// The same count by testing every (light, pixel) pair: the definition, for tests.
long long ideal_fragments_brute(const Image& positions, const std::vector<glm::vec4>& lights);

// The bench's ideal count is made from exact surface points in double, not from the light
// shader's reconstruction: the analytic trace's exact eye depth where the scene allows,
// otherwise the G-buffer's 24-bit depth codes decoded in double. Eye-space points, one per
// pixel (row 0 at the bottom), on the ray through the pixel's centre.
struct SurfacePoints {
    int width = 0, height = 0;
    std::vector<glm::dvec3> p;     // eye space
    std::vector<uint8_t> surface;  // 1 where the pixel sees a surface, 0 for background
};

// The projection's P[0][0] and P[1][1] in double for a camera and a w x h frame
// (glm::perspective: 1 / (aspect tan(fov/2)), 1 / tan(fov/2)).
glm::dvec2 projection_scale(const Camera& camera, int width, int height);

// From exact eye depths (AnalyticTrace::eye_depth: -z of the hit, 0 for background): the point at
// that depth on each pixel-centre ray, x = x_ndc * depth / p00, y = y_ndc * depth / p11, z = -depth.
SurfacePoints surface_from_eye_depth(const std::vector<double>& eye_depth, int width, int height, glm::dvec2 p);

// From a depth texture's GL_UNSIGNED_INT codes (read_depth_codes) of a 24-bit depth buffer: window
// depth d = (code >> 8) / (2^24 - 1) in double, eye z inverted through glm::perspective's depth
// mapping with these near and far planes (z = -P32 / (2d - 1 + P22)), x and y along the pixel-centre
// ray. d = 1 (the clear value) is background.
SurfacePoints surface_from_depth_codes(const std::vector<uint32_t>& codes, int width, int height, double near_plane,
                                       double far_plane, glm::dvec2 p);

// Lights in eye space, in double: the camera's view (glm::lookAt in double) applied to each light
// with non-zero colour (a light with no colour needs no fragment); w = radius.
std::vector<glm::dvec4> eye_lights(const Scene& scene);

// The count on exact points: a pixel counts for a light when its point lies strictly inside the
// sphere (|p - c|^2 < r^2, in double). Tiled like the float count; equal to ideal_fragments_brute's
// definition applied in double.
long long ideal_fragments(const SurfacePoints& s, const std::vector<glm::dvec4>& lights);
long long ideal_fragments_brute(const SurfacePoints& s, const std::vector<glm::dvec4>& lights);

// Any light type (issue 12): its volume in eye space, in double (deferred/light_volume.h's kinds).
// A pixel counts when its point lies strictly inside: the sphere as above; the cone when also
// strictly within the half-angle of the axis (the spot adds nothing on or outside it); full screen
// (directional) at every surface pixel.
struct EyeVolume {
    LightVolume::Kind kind = LightVolume::Kind::sphere;
    glm::dvec3 pos{0}, axis{0, 0, -1};  // eye space; axis unit
    double radius = 0, cos_angle = 0;
};
// The camera's view (glm::lookAt in double) applied to each light with non-zero colour.
std::vector<EyeVolume> eye_volumes(const Scene& scene);
bool inside(const EyeVolume& v, const glm::dvec3& p);
long long ideal_fragments(const SurfacePoints& s, const std::vector<EyeVolume>& lights);
long long ideal_fragments_brute(const SurfacePoints& s, const std::vector<EyeVolume>& lights);

}  // namespace dsr
