// The ideal light-pass fragment count of a frame: for each light, the pixels whose surface
// point lies inside the light's volume, summed over lights. What a light pass with a perfect
// per-pixel test would shade; `dsr bench` sets LightCounts::fragments (occlusion queries)
// against it (docs/benchmarks.md, "ideal"). One count (ideal_count) for every caller. Pure math,
// no GL.
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
// DeferredShader::reconstructed_positions(camera). p00, p11: the projection's P[0][0] and P[1][1].
Image positions_from_depth(const Image& depth, glm::vec2 planes, float p00, float p11);

// lights: eye-space centre in xyz, radius in w. A pixel counts for a light when its position
// (alpha > 0.5) lies strictly inside the sphere: Equation 2's attenuation is zero on and beyond
// it. Lights of radius <= 0 count nothing. The positions and spheres are taken to double and
// counted by the one count below (ideal_fragments over EyeVolume), so this float form and the
// double one can never disagree on a pixel; the brute-force form is the definition, for tests.
long long ideal_fragments(const Image& positions, const std::vector<glm::vec4>& lights);
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

// From positions as the light shader reconstructs them (DeferredShader::reconstructed_positions:
// eye-space xyz, alpha > 0.5 where there is a surface), taken to double as they are.
SurfacePoints surface_from_positions(const Image& positions);

// A light's volume in eye space, in double (deferred/light_volume.h's kinds). A pixel counts when
// its point lies strictly inside: the sphere (|p - c|^2 < r^2); the cone when also strictly within
// the half-angle of the axis (the spot adds nothing on or outside it); full screen (directional)
// at every surface pixel.
struct EyeVolume {
    LightVolume::Kind kind = LightVolume::Kind::sphere;
    glm::dvec3 pos{0}, axis{0, 0, -1};  // eye space; axis unit
    double radius = 0, cos_angle = 0;
};
// The volumes of the lights a light pass draws (non-zero colour: a light with no colour needs no
// fragment), moved to eye space by `view` (the camera's view in double, Camera::view_d).
std::vector<EyeVolume> eye_volumes(const std::vector<Light>& lights, const glm::dmat4& view);
// The scene's lights through its camera.
std::vector<EyeVolume> eye_volumes(const Scene& scene);
bool inside(const EyeVolume& v, const glm::dvec3& p);

// The count, tiled: 16x16-pixel tiles with eye-space bounding boxes skip most (light, pixel) pairs
// (a tile is skipped only when its box misses the ball about the centre or apex, which holds the
// whole volume), so it equals the brute-force count exactly. Every other count here calls it.
long long ideal_fragments(const SurfacePoints& s, const std::vector<EyeVolume>& lights);
long long ideal_fragments_brute(const SurfacePoints& s, const std::vector<EyeVolume>& lights);

// THE ideal count of a frame, the one `dsr bench`, `dsr render --stats` (frame_ideal.h) and the
// viewer's panel report: the pixel-light pairs whose surface point lies strictly inside the volume
// of a light with non-zero colour (sphere, cone or full screen, by the light's type). `lights` in
// world space as the frame drew them; `view` the camera's view in double (Camera::view_d).
long long ideal_count(const SurfacePoints& s, const std::vector<Light>& lights, const glm::dmat4& view);
// The same on a depth texture's 24-bit codes of a w x h frame seen by `camera` (the surface points
// of surface_from_depth_codes with the camera's planes and projection_scale).
long long ideal_count_from_depth_codes(const std::vector<uint32_t>& codes, int width, int height,
                                       const Camera& camera, const std::vector<Light>& lights);

// Spheres only, in eye space (w = radius): eye_volumes' centres and radii, whatever the kind.
std::vector<glm::dvec4> eye_lights(const Scene& scene);

// Spheres in eye space (w = radius) counted as EyeVolume spheres.
long long ideal_fragments(const SurfacePoints& s, const std::vector<glm::dvec4>& lights);
long long ideal_fragments_brute(const SurfacePoints& s, const std::vector<glm::dvec4>& lights);

}  // namespace dsr
