// The one file that talks to OpenImageIO: image files behind one small interface (scene/image.h).
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include "dsr_error.h"
#include "scene/image.h"

namespace dsr {

namespace {

// OIIO keeps a per-thread error string; read it so the message says what went wrong.
std::string oiio_message(const std::string& fallback) {
    std::string m = OIIO::geterror();
    if (m.empty()) m = fallback;
    while (!m.empty() && (m.back() == '\n' || m.back() == ' ')) m.pop_back();
    return m;
}

}  // namespace

Image load_image(const std::string& path) {
    // Ask for the stored (unassociated) alpha: OIIO would otherwise premultiply PNG colour.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) throw Error("cannot read image " + path + ": " + oiio_message("unknown format"));
    const OIIO::ImageSpec& spec = in->spec();
    const int w = spec.width, h = spec.height, nc = spec.nchannels;
    if (w <= 0 || h <= 0 || nc <= 0 || spec.depth > 1)
        throw Error("cannot read image " + path + ": unsupported size or channel layout");
    // Refused before anything is allocated: a header can claim any size.
    if (w > 16384 || h > 16384 || size_t(w) * size_t(h) > (size_t(1) << 26) || nc > 64)
        throw Error("cannot read image " + path + ": " + std::to_string(w) + " x " + std::to_string(h) + " pixels, " +
                    std::to_string(nc) + " channels; expected at most 16384 per side, 67108864 pixels and 64 channels "
                    "(an absurd size)");

    std::vector<float> raw(size_t(w) * h * nc);
    if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, raw.data())) {
        std::string m = in->geterror();
        if (m.empty()) m = oiio_message("read failed");
        throw Error("cannot read image " + path + ": " + m);
    }
    in->close();

    // Grey (and grey+alpha) become RGB; a missing alpha is opaque.
    int alpha = spec.alpha_channel;
    if (alpha < 0 && (nc == 2 || nc >= 4)) alpha = nc == 2 ? 1 : 3;
    const bool grey = nc <= 2;

    Image img;
    img.width = w;
    img.height = h;
    img.rgba.resize(size_t(w) * h * 4);
    for (int y = 0; y < h; ++y) {
        // File row y (top first) lands in Image row h-1-y (bottom first).
        const float* src = &raw[size_t(y) * w * nc];
        for (int x = 0; x < w; ++x, src += nc) {
            float* d = img.at(x, h - 1 - y);
            d[0] = src[0];
            d[1] = grey ? src[0] : src[1];
            d[2] = grey ? src[0] : src[2];
            d[3] = alpha >= 0 ? src[alpha] : 1.0f;
        }
    }
    return img;
}

void write_image(const std::string& path, const Image& img) {
    if (img.width <= 0 || img.height <= 0 || img.rgba.size() != size_t(img.width) * img.height * 4)
        throw Error("cannot write " + path + ": image has no pixels or the wrong buffer size");

    const std::string ext = image_extension(path);
    // The output plugin is chosen by the target's name; the temp name keeps the extension too.
    auto out = OIIO::ImageOutput::create(path);
    if (!out) throw Error("cannot write " + path + ": " + oiio_message("no writer for this extension"));

    const bool png = ext == ".png";
    const bool exr = ext == ".exr";
    OIIO::TypeDesc file_type = png ? OIIO::TypeDesc::UINT8 : exr ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT;
    // Formats without alpha (JPEG, ...) get RGB: the buffer keeps its stride of 4 channels.
    const int nc = out->supports("alpha") ? 4 : 3;
    OIIO::ImageSpec spec(img.width, img.height, nc, file_type);
    spec.alpha_channel = nc == 4 ? 3 : -1;
    // Write colour as stored; without this OIIO un-premultiplies PNG data by alpha.
    spec.attribute("oiio:UnassociatedAlpha", 1);

    // Flip to top row first; PNG is quantized here (round to nearest, clamp) so the bytes
    // do not depend on OIIO's conversion rules.
    const int w = img.width, h = img.height;
    std::vector<float> flipped;
    std::vector<uint8_t> bytes;
    if (png) {
        bytes.resize(size_t(w) * h * 4);
        for (int y = 0; y < h; ++y) {
            const float* src = img.at(0, h - 1 - y);
            uint8_t* dst = &bytes[size_t(y) * w * 4];
            for (int i = 0; i < w * 4; ++i) {
                float v = src[i];
                v = std::isnan(v) ? 0.0f : std::min(1.0f, std::max(0.0f, v));
                dst[i] = uint8_t(std::lround(v * 255.0f));
            }
        }
    } else {
        flipped.resize(img.rgba.size());
        for (int y = 0; y < h; ++y)
            std::copy_n(img.at(0, h - 1 - y), size_t(w) * 4, &flipped[size_t(y) * w * 4]);
    }

    const std::string tmp = path + ".tmp-" + std::to_string(long(getpid())) + ext;
    auto fail = [&](const std::string& why) {
        std::remove(tmp.c_str());
        throw Error("cannot write " + path + ": " + why);
    };
    if (!out->open(tmp, spec)) {
        std::string m = out->geterror();
        fail(m.empty() ? oiio_message("open failed") : m);
    }
    bool ok = png ? out->write_image(OIIO::TypeDesc::UINT8, bytes.data(), 4 * sizeof(uint8_t))
                  : out->write_image(OIIO::TypeDesc::FLOAT, flipped.data(), 4 * sizeof(float));
    ok = out->close() && ok;
    if (!ok) {
        std::string m = out->geterror();
        fail(m.empty() ? oiio_message("write failed") : m);
    }
    out.reset();
    if (std::rename(tmp.c_str(), path.c_str()) != 0) fail(std::string("rename failed: ") + std::strerror(errno));
}

}  // namespace dsr
