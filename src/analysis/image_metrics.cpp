#include "analysis/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dsr_error.h"

namespace dsr {

// Plain C++ (it was OpenImageIO's ImageBufAlgo::compare): the renderer core stays free of
// OpenImageIO but for the image-file seam (scene/image_io.cpp), so a libpng build can travel.
// Same definitions: over RGB, the mean and RMS of the per-channel absolute differences, their
// maximum, and the pixels where any channel differs by more than fail_threshold.
ImageDiff compare_images(const Image& a, const Image& b, double fail_threshold) {
    if (a.width != b.width || a.height != b.height)
        throw Error("compare_images: sizes differ (" + std::to_string(a.width) + "x" + std::to_string(a.height) +
                    " vs " + std::to_string(b.width) + "x" + std::to_string(b.height) + ")");
    // Differences in float, sums in double. A difference of exactly the threshold passes: in
    // float, k/255 - j/255 for codes one apart lands on either side of float(1/255) depending on
    // k (OpenImageIO's compare counted some 1-code differences as "over 1 LSB"), so the threshold
    // gets a slack of 1e-3 LSB, far below the 1-LSB steps of 8-bit images.
    double sum = 0, sum_sq = 0;
    float max_err = 0;
    const float threshold = float(fail_threshold + 1e-3 / 255.0);
    long long failing = 0;
    const size_t n = size_t(a.width) * a.height;
    for (size_t p = 0; p < n; ++p) {
        float worst = 0;
        for (int c = 0; c < 3; ++c) {
            const float e = std::fabs(a.rgba[p * 4 + c] - b.rgba[p * 4 + c]);
            sum += e;
            sum_sq += double(e) * e;
            worst = std::max(worst, e);
        }
        max_err = std::max(max_err, worst);
        if (worst > threshold) ++failing;
    }
    ImageDiff d;
    d.max_abs = max_err;
    d.mean_abs = n ? sum / double(n * 3) : 0;
    const double rms = n ? std::sqrt(sum_sq / double(n * 3)) : 0;
    d.psnr_db = max_err > 0 ? 20.0 * std::log10(1.0 / rms) : std::numeric_limits<double>::infinity();
    d.failing = failing;
    d.pixels = (long long)n;
    return d;
}

Image difference_image(const Image& a, const Image& b, float gain) {
    Image d = a;
    for (size_t i = 0; i < d.rgba.size(); ++i)
        d.rgba[i] = (i % 4 == 3) ? 1.0f : std::min(1.0f, std::fabs(a.rgba[i] - b.rgba[i]) * gain);
    return d;
}

}  // namespace dsr
