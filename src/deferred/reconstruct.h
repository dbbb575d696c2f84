// Eye-space position from window depth (§3.4.3, Listings 19 and 20), as pure math.
#pragma once
#include <array>

#include <glm/glm.hpp>

namespace dsr {

// The `planes` uniform of §3.4.3: x = -f/(f-n), y = -f*n/(f-n). Throws dsr::Error unless
// 0 < near < far, both finite.
glm::vec2 planes_uniform(float near_plane, float far_plane);

// Eye-space z (< 0) from window depth in [0,1]: -planes.y / (planes.x + depth) (Listing 20
// line 21). Computed in double from the float inputs; its relative error still grows like
// eps(depth) * far/near near the far plane (docs/depth_precision.md), which the inputs already carry.
float eye_z_from_depth(float depth, glm::vec2 planes);

// The inverse: what GL's depth buffer holds (glDepthRange(0,1)) for eye z < 0, which is also
// Listing 13's d = (planes.x*z + planes.y)/(-z). Throws dsr::Error unless z < 0 and
// 0 < near < far.
float depth_from_eye_z(float z, float near_plane, float far_plane);

// The window depth a light quad is drawn at so that GL's depth test (GL_GEQUAL against the scene's
// depth) rejects only surfaces the light shader's depth test (LIGHT_DEPTH_TEST: pos.z below
// centre_z - radius) would reject: the depth of the sphere's back, moved away from the camera by
// 2^-9 of its distance (more than the reconstructed pos.z's error on every depth path, half-float
// positions included) and by 2^-20 in window depth (the depth buffer's rounding of the quad's depth), clamped
// to [0, 1]. 1 where the back lies at or beyond the far plane: then nothing is rejected.
float sphere_back_depth(float centre_z, float radius, float near_plane, float far_plane);

// The eye-space view ray (x, y, -1) through window position (win_x, win_y) in pixels, e.g. a
// pixel centre (i + 0.5, j + 0.5): the clean form of Listing 19, which unprojects at window
// z = 10, outside [0,1] (docs/errata.md #7). p00 = P[0][0], p11 = P[1][1] of a symmetric perspective.
glm::vec3 view_ray(float win_x, float win_y, int width, int height, float p00, float p11);

// view_ray at the window corners (0,0), (w,0), (w,h), (0,h), independent of the size:
// (-1/p00,-1/p11,-1), (1/p00,-1/p11,-1), (1/p00,1/p11,-1), (-1/p00,1/p11,-1). Given to the
// full-screen quad's vertices, the rasteriser's interpolation yields view_ray at each fragment.
std::array<glm::vec3, 4> corner_rays(float p00, float p11);

// Listing 20 lines 21-22: pos.z from depth, pos.xy = ray.xy / ray.z * pos.z. The ray need not
// be normalised (Listing 20 normalises first; the ratio is the same).
glm::vec3 reconstruct_position(float depth, glm::vec2 planes, glm::vec3 ray);

}  // namespace dsr
