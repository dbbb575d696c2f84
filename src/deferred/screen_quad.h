// Screen quads, shared by the image-space stages: over a P-buffer's content (post §3.5, SSAO),
// whose textures may be padded to powers of two, so texture coordinates stop at its extent; and
// over a rectangle of the frame's window, carrying the G-buffer's coordinates and view rays.
#pragma once
#include <glm/glm.hpp>

#include "deferred/frame.h"
#include "gl/pbuffer.h"

namespace dsr {

// Screen-aligned quad over [x0,x1]x[y0,y1] (window pixels, in the frame's pixel camera):
// texcoord 0 = the G-buffer's coordinates there; with rays, texcoord 1 = the eye-space view ray
// of each corner (Listing 19), which the rasteriser interpolates exactly (it is affine).
void draw_rect(const FrameDef& f, float x0, float y0, float x1, float y1, bool rays);

// [0,w]x[0,h] in the current ortho camera, texture coordinates 0..(sx,sy).
void draw_quad(float w, float h, float sx, float sy);
// [0,w]x[0,h] sampling b's content bilinearly (fixed function) as CLAMP_TO_EDGE does on an
// unpadded texture, also when b is padded.
void draw_quad_clamped(float w, float h, const PBuffer& b);
// Texel centres of b's content in texture coordinates: (first u, first v, last u, last v).
glm::vec4 uv_clamp(const PBuffer& b);

}  // namespace dsr
