#include "analysis/image_metrics.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "dsr_error.h"

namespace dsr {

namespace {
OIIO::ImageBuf rgb_buf(const Image& img) {
    OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf buf(spec);
    buf.set_pixels(OIIO::ROI(0, img.width, 0, img.height, 0, 1, 0, 4), OIIO::TypeDesc::FLOAT, img.rgba.data());
    return buf;
}
}  // namespace

ImageDiff compare_images(const Image& a, const Image& b, double fail_threshold) {
    if (a.width != b.width || a.height != b.height)
        throw Error("compare_images: sizes differ (" + std::to_string(a.width) + "x" + std::to_string(a.height) +
                    " vs " + std::to_string(b.width) + "x" + std::to_string(b.height) + ")");
    OIIO::ImageBuf A = rgb_buf(a), B = rgb_buf(b);
    OIIO::ROI rgb(0, a.width, 0, a.height, 0, 1, 0, 3);
    auto r = OIIO::ImageBufAlgo::compare(A, B, float(fail_threshold), 1e30f, rgb);
    ImageDiff d;
    d.max_abs = r.maxerror;
    d.mean_abs = r.meanerror;
    d.psnr_db = r.maxerror > 0 ? 20.0 * std::log10(1.0 / r.rms_error) : std::numeric_limits<double>::infinity();
    d.failing = (long long)r.nfail;
    d.pixels = (long long)a.width * a.height;
    return d;
}

Image difference_image(const Image& a, const Image& b, float gain) {
    Image d = a;
    for (size_t i = 0; i < d.rgba.size(); ++i)
        d.rgba[i] = (i % 4 == 3) ? 1.0f : std::min(1.0f, std::fabs(a.rgba[i] - b.rgba[i]) * gain);
    return d;
}

}  // namespace dsr
