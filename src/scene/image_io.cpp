// The one file that talks to OpenImageIO: image files behind one small interface (scene/image.h).
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "dsr_error.h"
#include "scene/image.h"
#include "scene/stderr_capture.h"
#include "scene/user_file.h"

namespace dsr {

namespace {

// OIIO keeps a per-thread error string; read it so the message says what went wrong.
std::string oiio_message(const std::string& fallback) {
    std::string m = OIIO::geterror();
    if (m.empty()) m = fallback;
    while (!m.empty() && (m.back() == '\n' || m.back() == ' ')) m.pop_back();
    return m;
}

// What the decoders print for a file that is cut short or damaged although the read "worked"
// (libjpeg fills the missing rows with grey and says so): an error, not a warning.
bool is_damage(const std::string& said) {
    for (const char* sign : {"Premature end", "Corrupt", "corrupt", "truncated", "Truncated", "bad ", "Bad ", "error",
                             "Error", "invalid", "Invalid"})
        if (said.find(sign) != std::string::npos) return true;
    return false;
}

// "cannot read image NAME: WHY" as one line, with what the decoders printed meanwhile (`chatter`)
// beside WHY, or as WHY when there is none.
[[noreturn]] void fail_reading(const std::string& name, StderrCapture& chatter, std::string why) {
    const std::string said = chatter.text();
    if (why.empty()) why = said.empty() ? "read failed" : said;
    else if (!said.empty() && why.find(said) == std::string::npos) why += " (" + said + ")";
    for (size_t at; (at = why.find('\n')) != std::string::npos;) why.replace(at, 1, "; ");
    throw Error("cannot read image " + name + ": " + one_line(why));
}

// A PNG ends with its IEND chunk: length 0, "IEND", CRC AE 42 60 82.
bool ends_with_png_iend(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return false;
    unsigned char tail[12] = {0};
    const bool ok = std::fseek(f, -12, SEEK_END) == 0 && std::fread(tail, 1, 12, f) == 12;
    std::fclose(f);
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
    return ok && std::memcmp(tail, iend, 12) == 0;
}

// An opened image read whole: the size checked against the limits and `max_texels` before
// anything is allocated (a header can claim any size), the first four channels (alpha where the
// file puts it later), grey made RGB, rows flipped to bottom first. `fail` throws the one line;
// `complete` says whether the whole file was read (OpenImageIO stops reading a PNG after its
// pixels: a file cut in its last chunk would pass).
Image read_opened(OIIO::ImageInput& in, const OIIO::ImageSpec& spec, const std::string& name, size_t max_texels,
                  StderrCapture& chatter, const std::function<void(std::string)>& fail,
                  const std::function<bool()>& complete) {
    const int w = spec.width, h = spec.height, nc = spec.nchannels;
    if (w <= 0 || h <= 0 || nc <= 0 || spec.depth > 1) fail("unsupported size or channel layout");
    if (nc > 64) fail(std::to_string(nc) + " channels, expected at most 64 (an absurd size)");
    if (w > kMaxImageSide || h > kMaxImageSide || size_t(w) * size_t(h) > kMaxImageTexels)
        fail(std::to_string(w) + " x " + std::to_string(h) + " pixels, expected at most " +
             std::to_string(kMaxImageSide) + " a side and " + std::to_string(kMaxImageTexels) + " in all (an absurd size)");
    if (size_t(w) * size_t(h) > max_texels)
        throw ImageTooLarge("cannot read image " + name + ": " + std::to_string(w) + " x " + std::to_string(h) +
                                " pixels, expected at most " + std::to_string(max_texels) + " (the caller's budget)",
                            w, h);
    int alpha = spec.alpha_channel;
    if (alpha < 0 && (nc == 2 || nc >= 4)) alpha = nc == 2 ? 1 : 3;
    const int colour = std::min(nc, 4);
    const bool grey = nc <= 2;
    std::vector<float> raw(size_t(w) * h * size_t(colour)), alpha_raw;
    bool ok = in.read_image(0, 0, 0, colour, OIIO::TypeDesc::FLOAT, raw.data());
    if (ok && alpha >= colour) {
        alpha_raw.resize(size_t(w) * h);
        ok = in.read_image(0, 0, alpha, alpha + 1, OIIO::TypeDesc::FLOAT, alpha_raw.data());
    }
    // A truncated file can leave read_image true with an error recorded (and the missing rows
    // grey): the error state, not the return value alone, decides.
    if (!ok || in.has_error()) fail(in.geterror());
    if (!in.close() || in.has_error()) fail(in.geterror());
    const std::string stray = OIIO::geterror();
    if (!stray.empty()) fail(stray);
    const std::string said = chatter.text();
    if (is_damage(said)) fail(said);
    if (!complete()) fail("cut short: no IEND chunk at its end");

    Image img;
    img.width = w;
    img.height = h;
    img.rgba.resize(size_t(w) * h * 4);
    for (int y = 0; y < h; ++y) {
        // File row y (top first) lands in Image row h-1-y (bottom first).
        const float* src = &raw[size_t(y) * w * colour];
        for (int x = 0; x < w; ++x, src += colour) {
            float* d = img.at(x, h - 1 - y);
            d[0] = src[0];
            d[1] = grey ? src[0] : src[1];
            d[2] = grey ? src[0] : src[2];
            d[3] = alpha < 0 ? 1.0f : alpha < colour ? src[alpha] : alpha_raw[size_t(y) * w + x];
        }
    }
    return img;
}

}  // namespace

Image load_image(const std::string& path, size_t max_texels) {
    check_user_file(path, "image", kMaxImageFileBytes);
    // The decoders' own words (libpng's warnings, libjpeg's "Premature end of JPEG file") go
    // into the one error line, not onto the terminal.
    StderrCapture chatter;
    auto fail = [&](std::string why) { fail_reading(path, chatter, std::move(why)); };
    // Ask for the stored (unassociated) alpha: OIIO would otherwise premultiply PNG colour.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    (void)OIIO::geterror();  // an earlier call's error would read as this file's
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) fail(oiio_message(""));
    const OIIO::ImageSpec spec = in->spec();
    const bool png = std::strcmp(in->format_name(), "png") == 0;
    return read_opened(*in, spec, path, max_texels, chatter, fail, [&] { return !png || ends_with_png_iend(path); });
}

Image decode_image(const std::string& bytes, const std::string& name, size_t max_texels) {
    StderrCapture chatter;
    auto fail = [&](std::string why) { fail_reading(name, chatter, std::move(why)); };
    // glTF's formats, told by their signatures; the plugin is picked by a name with that extension.
    const bool png = bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
    const bool jpeg = bytes.compare(0, 3, "\xFF\xD8\xFF") == 0;
    if (!png && !jpeg) fail("expected PNG or JPEG data, got neither signature");
    // A PNG's chunks walked first, lengths and CRCs: OpenImageIO's PNG reader leaks its error
    // message when libpng reads past the end of the data, so a cut file never gets that far.
    if (png) {
        static const std::vector<uint32_t> table = [] {
            std::vector<uint32_t> t(256);
            for (uint32_t n = 0; n < 256; ++n) {
                uint32_t c = n;
                for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
                t[n] = c;
            }
            return t;
        }();
        auto be32 = [&](size_t at) {
            return uint32_t((unsigned char)bytes[at]) << 24 | uint32_t((unsigned char)bytes[at + 1]) << 16 |
                   uint32_t((unsigned char)bytes[at + 2]) << 8 | uint32_t((unsigned char)bytes[at + 3]);
        };
        size_t at = 8;
        bool iend = false;
        while (!iend) {
            if (bytes.size() - at < 12) fail("cut short: no IEND chunk at its end");
            const uint64_t len = be32(at);
            if (len > bytes.size() - at - 12)
                fail("cut short: the chunk at byte " + std::to_string(at) + " claims " + std::to_string(len) + " bytes");
            uint32_t crc = 0xFFFFFFFFu;
            for (size_t i = at + 4; i < at + 8 + len; ++i) crc = table[(crc ^ (unsigned char)bytes[i]) & 0xFF] ^ (crc >> 8);
            if (~crc != be32(at + 8 + size_t(len))) fail("damaged: the chunk at byte " + std::to_string(at) + " fails its CRC");
            iend = bytes.compare(at + 4, 4, "IEND") == 0;
            at += 12 + size_t(len);
        }
    }
    if (bytes.size() > kMaxImageFileBytes) fail("expected at most " + std::to_string(kMaxImageFileBytes) + " bytes");
    OIIO::Filesystem::IOMemReader proxy(bytes.data(), bytes.size());
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    (void)OIIO::geterror();
    // The plugin is created by its format name and reads through the proxy (open by file name
    // with a proxy fails for these plugins).
    auto in = OIIO::ImageInput::create(png ? "png" : "jpeg");
    if (!in) fail(oiio_message("no reader for this format"));
    if (!in->set_ioproxy(&proxy)) fail(oiio_message("the reader cannot read from memory"));
    OIIO::ImageSpec spec;
    if (!in->open(name, spec, config)) fail(in->geterror());
    static const char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', '\xAE', '\x42', '\x60', '\x82'};
    return read_opened(*in, spec, name, max_texels, chatter, fail, [&] {
        return !png || (bytes.size() >= 12 && bytes.compare(bytes.size() - 12, 12, iend, 12) == 0);
    });
}

void encode_image(const std::string& file, const std::string& name, const Image& img) {
    // Messages name the user's path: OIIO's would name the temporary file it wrote.
    auto fail = [&](std::string why) {
        for (size_t at; (at = why.find(file)) != std::string::npos;) why.replace(at, file.size(), name);
        throw Error("cannot write " + name + ": " + one_line(why));
    };
    if (img.width <= 0 || img.height <= 0 || img.rgba.size() != size_t(img.width) * img.height * 4)
        fail("image has no pixels or the wrong buffer size");

    const std::string ext = image_extension(name);
    StderrCapture chatter;
    // The output plugin is chosen by the user's name; it writes into `file`.
    auto out = OIIO::ImageOutput::create(name);
    if (!out) fail(oiio_message("no writer for this extension"));
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

    if (!out->open(file, spec)) {
        std::string m = out->geterror();
        fail(m.empty() ? oiio_message("open failed") : m);
    }
    bool ok = png ? out->write_image(OIIO::TypeDesc::UINT8, bytes.data(), 4 * sizeof(uint8_t))
                  : out->write_image(OIIO::TypeDesc::FLOAT, flipped.data(), 4 * sizeof(float));
    // The return values decide: OIIO's TIFF writer records an error about its Exif block on
    // files it writes whole.
    ok = out->close() && ok;
    if (!ok) {
        std::string m = out->geterror();
        if (m.empty()) m = chatter.text();
        fail(m.empty() ? oiio_message("write failed") : m);
    }
}

}  // namespace dsr
