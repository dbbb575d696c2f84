// Images as the renderer sees them, and the one interface to image files.
// Every OpenImageIO call lives behind load_image/write_image (image_io.cpp),
// so the renderer core never includes OpenImageIO headers.
#pragma once
#include <string>
#include <vector>

#include "dsr_error.h"

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

// The most texels (and pixels per side) load_image accepts from any file, whatever it claims.
constexpr size_t kMaxImageTexels = size_t(1) << 26;
constexpr int kMaxImageSide = 16384;

// load_image's refusal of an image over its max_texels, before anything is allocated, so the
// caller can name the budget it was checking.
struct ImageTooLarge : Error {
    ImageTooLarge(const std::string& what, int w, int h) : Error(what), width(w), height(h) {}
    int width, height;
};

// Reads any format OpenImageIO reads, from a regular file only (user_file.h). Grey becomes
// RGB, a missing alpha is 1. A truncated or damaged file is an error, and whatever the decoders
// print is caught into the one line: throws dsr::Error "cannot read image PATH: WHY" (one line).
// Over max_texels (or kMaxImageSide a side): ImageTooLarge.
Image load_image(const std::string& path, size_t max_texels = kMaxImageTexels);

// The same from an image file's bytes in memory (a glTF image: a data URI or a buffer view), with
// the same checks and errors; `name` names it in messages ("cannot read image NAME: WHY"). PNG
// and JPEG (glTF's formats), told by their first bytes; the size is checked on the header
// before any pixel is allocated (ImageTooLarge over max_texels).
Image decode_image(const std::string& bytes, const std::string& name, size_t max_texels = kMaxImageTexels);

// Encodes img into the file `file` (created or replaced), in the format `name`'s extension
// picks (.png 8-bit, .exr half float, anything else the backend knows). Errors name `name`, the
// user's path, and never `file`: "cannot write NAME: WHY". OutputSet (scene/output_set.h) writes
// every output through it to a temporary file and renames them all at the end.
void encode_image(const std::string& file, const std::string& name, const Image& img);

// One image as a whole output: encode_image to a temporary file beside `path`, then renamed.
// Never half-written; throws dsr::Error naming the path on failure.
void write_image(const std::string& path, const Image& img);

}  // namespace dsr
