// Reading the main frame buffer back (final image of §3.6) into an Image.
#pragma once
#include "scene/image.h"

namespace dsr {

// glReadPixels of the current read framebuffer, RGBA8 converted to float exactly (b/255).
Image read_pixels(int width, int height);

}  // namespace dsr
