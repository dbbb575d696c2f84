#include "gl/readback.h"

#include <vector>

#include "gl/check.h"
#include "gl/gl.h"

namespace dsr {

Image read_pixels(int width, int height) {
    std::vector<unsigned char> px(size_t(width) * height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
    check_gl("reading the main frame buffer");
    Image img;
    img.width = width;
    img.height = height;
    img.rgba.resize(px.size());
    for (size_t i = 0; i < px.size(); ++i) img.rgba[i] = px[i] / 255.0f;
    return img;
}

}  // namespace dsr
