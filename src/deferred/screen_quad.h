// Screen quads over a P-buffer's content, shared by the post stage (§3.5) and the SSAO stage:
// the content may be padded to powers of two, so texture coordinates stop at its extent.
#pragma once
#include <glm/glm.hpp>

#include "gl/pbuffer.h"

namespace dsr {

// [0,w]x[0,h] in the current ortho camera, texture coordinates 0..(sx,sy).
void draw_quad(float w, float h, float sx, float sy);
// [0,w]x[0,h] sampling b's content bilinearly (fixed function) as CLAMP_TO_EDGE does on an
// unpadded texture, also when b is padded.
void draw_quad_clamped(float w, float h, const PBuffer& b);
// Texel centres of b's content in texture coordinates: (first u, first v, last u, last v).
glm::vec4 uv_clamp(const PBuffer& b);

}  // namespace dsr
