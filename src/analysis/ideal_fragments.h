// The ideal light-pass fragment count of a frame: for each light, the pixels whose surface
// point lies inside the light's sphere, summed over lights. What a light pass with a perfect
// per-pixel test would shade; `dsr bench` sets FrameStats::light_fragments (occlusion queries)
// against it. Pure math, no GL.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "scene/image.h"

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

}  // namespace dsr
