// Reading the main frame buffer back (final image of §3.6) into an Image.
#pragma once
#include <cstdint>
#include <vector>

#include "gl/gl.h"
#include "scene/image.h"

namespace dsr {

// glReadPixels of the current read framebuffer, RGBA8 converted to float exactly (b/255).
Image read_pixels(int width, int height);

// The w x h content (lower left) of a texture of tw x th texels (larger when padded to
// powers of two), as float RGBA; a depth texture (depth = true) comes back as grey, alpha 1.
Image read_texture(GLuint texture, int w, int h, int tw, int th, bool depth);

// The w x h content of an RGBA8 colour texture as 8-bit values converted as read_pixels converts
// them (b/255), so an image read from a P-buffer equals the one its 1:1 copy into the main frame
// buffer reads back, byte for byte.
Image read_texture_rgba8(GLuint texture, int w, int h, int tw, int th);

// The w x h content of a depth texture as GL_UNSIGNED_INT codes (window depth = code /
// (2^32 - 1); a 24-bit depth buffer fills the high 24 bits), row 0 at the bottom: read
// without the float conversion read_texture makes.
std::vector<uint32_t> read_depth_codes(GLuint texture, int w, int h, int tw, int th);

}  // namespace dsr
