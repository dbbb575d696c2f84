// The image seam's second backend, for builds that must travel (the GPU machine has libpng at
// run time and cannot take OpenImageIO's dependencies): PNG (8-bit RGBA, as the OpenImageIO
// backend writes it) and binary PPM, through libpng. Chosen at build time instead of
// image_io.cpp (tests/gpu_bench.sh builds with it); the same interface, scene/image.h.
#include <png.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include "dsr_error.h"
#include "scene/image.h"
#include "scene/user_file.h"

namespace dsr {

namespace {

struct File {
    FILE* f = nullptr;
    ~File() {
        if (f) std::fclose(f);
    }
};

uint8_t to_byte(float v) {
    v = std::isnan(v) ? 0.0f : std::min(1.0f, std::max(0.0f, v));
    return uint8_t(std::lround(v * 255.0f));
}

[[noreturn]] void png_fail(png_structp, png_const_charp msg) {
    throw Error(std::string(msg ? msg : "libpng error"));
}

// libpng's warnings, kept for the error line instead of printed (its default).
void png_warn(png_structp png, png_const_charp msg) {
    auto* said = static_cast<std::string*>(png_get_error_ptr(png));
    if (said && msg && said->size() < 1024) *said += (said->empty() ? "" : "; ") + std::string(msg);
}

// libpng reads decode_image's bytes through this.
struct MemRead {
    const std::string* bytes;
    size_t pos = 0;
};
void mem_read(png_structp png, png_bytep out, png_size_t n) {
    auto* m = static_cast<MemRead*>(png_get_io_ptr(png));
    if (n > m->bytes->size() - m->pos) png_error(png, "cut short: read past the end of the data");
    std::memcpy(out, m->bytes->data() + m->pos, n);
    m->pos += n;
}

// A PNG read whole, from wherever `set_io` points libpng (a file or bytes in memory): the size
// checked against the limits and `max_texels` before anything is allocated, everything to 8-bit
// RGBA (palette and grey expanded, 16-bit stripped, alpha 255 added), rows flipped to bottom first.
// Errors name `name`, with libpng's warnings beside them.
Image read_png(const std::string& name, size_t max_texels, const std::function<void(png_structp)>& set_io) {
    std::string warnings;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &warnings, png_fail, png_warn);
    png_infop info = png_create_info_struct(png);
    Image img;
    try {
        set_io(png);
        png_read_info(png, info);
        const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
        const size_t limit = std::min(max_texels, kMaxImageTexels);
        if (w == 0 || h == 0) throw Error(std::to_string(w) + " x " + std::to_string(h) + " pixels (no pixels)");
        if (w > png_uint_32(kMaxImageSide) || h > png_uint_32(kMaxImageSide) || size_t(w) * h > kMaxImageTexels)
            throw Error(std::to_string(w) + " x " + std::to_string(h) + " pixels, expected at most " +
                        std::to_string(kMaxImageSide) + " a side and " + std::to_string(kMaxImageTexels) +
                        " in all (an absurd size)");
        if (size_t(w) * h > limit)
            throw ImageTooLarge("cannot read image " + name + ": " + std::to_string(w) + " x " + std::to_string(h) +
                                    " pixels, expected at most " + std::to_string(limit) + " (the caller's budget)",
                                int(w), int(h));
        png_set_expand(png);
        png_set_strip_16(png);
        png_set_gray_to_rgb(png);
        png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
        png_read_update_info(png, info);
        std::vector<uint8_t> pixels(size_t(w) * h * 4);
        std::vector<png_bytep> rows(h);
        for (png_uint_32 y = 0; y < h; ++y) rows[y] = &pixels[size_t(y) * w * 4];
        png_read_image(png, rows.data());
        png_read_end(png, nullptr);
        img.width = int(w);
        img.height = int(h);
        img.rgba.resize(pixels.size());
        for (png_uint_32 y = 0; y < h; ++y)  // file row y (top first) -> Image row h-1-y
            for (size_t i = 0; i < size_t(w) * 4; ++i)
                img.rgba[size_t(h - 1 - y) * w * 4 + i] = pixels[size_t(y) * w * 4 + i] / 255.0f;
    } catch (const ImageTooLarge&) {
        png_destroy_read_struct(&png, &info, nullptr);
        throw;
    } catch (const Error& e) {
        png_destroy_read_struct(&png, &info, nullptr);
        std::string why = e.what();
        if (!warnings.empty()) why += " (" + warnings + ")";
        throw Error("cannot read image " + name + ": " + one_line(why));
    }
    png_destroy_read_struct(&png, &info, nullptr);
    return img;
}

}  // namespace

Image load_image(const std::string& path, size_t max_texels) {
    const std::string ext = image_extension(path);
    if (ext != ".png") throw Error("cannot read image " + path + ": this build reads PNG only (libpng backend)");
    const int fd = open_user_file(path, "image", kMaxImageFileBytes);
    File in;
    in.f = fdopen(fd, "rb");
    if (!in.f) {
        close(fd);
        throw Error("cannot read image " + path + ": " + std::strerror(errno));
    }
    return read_png(path, max_texels, [&](png_structp png) { png_init_io(png, in.f); });
}

Image decode_image(const std::string& bytes, const std::string& name, size_t max_texels) {
    if (bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0)
        throw Error("cannot read image " + name + ": " +
                    (bytes.compare(0, 3, "\xFF\xD8\xFF") == 0 ? std::string("this build reads PNG only (libpng backend), got JPEG")
                                                              : std::string("expected PNG data, got no PNG signature")));
    MemRead src{&bytes, 0};
    return read_png(name, max_texels, [&](png_structp png) { png_set_read_fn(png, &src, mem_read); });
}

void encode_image(const std::string& file, const std::string& name, const Image& img) {
    auto fail = [&](const std::string& why) { throw Error("cannot write " + name + ": " + one_line(why)); };
    if (img.width <= 0 || img.height <= 0 || img.rgba.size() != size_t(img.width) * img.height * 4)
        fail("image has no pixels or the wrong buffer size");
    const std::string ext = image_extension(name);
    if (ext != ".png" && ext != ".ppm") fail("this build writes .png and .ppm only (libpng backend)");
    const int w = img.width, h = img.height;
    const int nc = ext == ".png" ? 4 : 3;
    std::vector<uint8_t> bytes(size_t(w) * h * nc);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < nc; ++c) bytes[(size_t(y) * w + x) * nc + c] = to_byte(img.at(x, h - 1 - y)[c]);

    File out;
    out.f = std::fopen(file.c_str(), "wb");
    if (!out.f) fail(std::strerror(errno));
    if (nc == 3) {
        std::fprintf(out.f, "P6\n%d %d\n255\n", w, h);
        if (std::fwrite(bytes.data(), 1, bytes.size(), out.f) != bytes.size()) fail(std::strerror(errno));
    } else {
        std::string warnings;
        png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &warnings, png_fail, png_warn);
        png_infop info = png_create_info_struct(png);
        try {
            png_init_io(png, out.f);
            png_set_IHDR(png, info, png_uint_32(w), png_uint_32(h), 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
                         PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
            png_write_info(png, info);
            for (int y = 0; y < h; ++y) png_write_row(png, &bytes[size_t(y) * w * 4]);
            png_write_end(png, nullptr);
        } catch (const Error& e) {
            png_destroy_write_struct(&png, &info);
            fail(e.what());
        }
        png_destroy_write_struct(&png, &info);
    }
    if (std::fflush(out.f) != 0 || std::ferror(out.f)) fail(std::strerror(errno));
}

}  // namespace dsr
