// A texture drawn over the whole main frame buffer by fixed function (the tutorial's final
// stage, §3.6): nearest when 1:1, bilinear when scaled. Leaves the texture's filter as it was.
#pragma once
#include <glm/glm.hpp>

#include "gl/gl.h"

namespace dsr {

// tex_scale: the content's extent in texture coordinates ((1,1) unless padded to powers of
// two). has_fbo: framebuffer objects exist, so framebuffer 0 is bound first (without them
// it is the only one).
void draw_texture_to_framebuffer0(GLuint texture, int out_w, int out_h, glm::vec2 tex_scale, bool has_fbo);

// The clip-space square [-1, 1]^2 by fixed function in the current colour: the whole viewport
// under identity matrices (the capability probes' fills).
void draw_clip_square();

}  // namespace dsr
