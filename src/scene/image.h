// Images as the renderer sees them, and the one interface to image files.
// Every OpenImageIO call lives behind load_image/write_image (image_io.cpp),
// so the renderer core never includes OpenImageIO headers.
#pragma once
#include <string>
#include <vector>

namespace dsr {

// RGBA, 32-bit float per channel, rows stored bottom row first (OpenGL order:
// row 0 is texture coordinate t = 0). Files are top row first; load_image and
// write_image flip.
struct Image {
    int width = 0, height = 0;
    std::vector<float> rgba;  // width * height * 4
    float* at(int x, int y) { return &rgba[(size_t(y) * width + x) * 4]; }
    const float* at(int x, int y) const { return &rgba[(size_t(y) * width + x) * 4]; }
};

// The image with every alpha set to 1: what dsr writes (a read-back frame's alpha is whatever
// the passes left in it).
inline Image opaque(Image img) {
    for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 1.0f;
    return img;
}

// ".png" for "dir/Name.PNG": the extension lower-cased with its dot, "" when there is none
// (both image backends pick the format by it).
std::string image_extension(const std::string& path);

// Reads any format OpenImageIO reads. Grey becomes RGB, a missing alpha is 1.
// Throws dsr::Error naming the path and what went wrong.
Image load_image(const std::string& path);

// Writes by extension (.png 8-bit, .exr half float, anything else OIIO knows).
// Writes to a temporary file beside the target, then renames: never half-written.
// Throws dsr::Error naming the path on failure.
void write_image(const std::string& path, const Image& img);

}  // namespace dsr
