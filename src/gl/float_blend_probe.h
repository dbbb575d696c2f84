// Whether this GL adds into a float target without clamping, measured: ARB_texture_float gives
// float textures, but blending into them was a GPU's own (NV40-class GPUs blended half floats,
// not 32-bit ones), and a GL may clamp the blend to [0, 1]. --accum half/float need it.
#pragma once
#include "gl/gl.h"

namespace dsr {

// 0.75 cleared, 0.75 added by an additive blend into a 1x1 target of `format` (GL_RGBA16F_ARB or
// GL_RGBA32F_ARB): true when 1.5 is read back. Needs a current context with
// EXT_framebuffer_object and ARB_texture_float (false without them); leaves gl_state() reset.
bool probe_float_blend(GLenum format);

}  // namespace dsr
