// Image comparison for tests and reports (OpenImageIO's ImageBufAlgo::compare behind a
// small interface). Values are on [0,1]; "LSB" means 1/255.
#pragma once
#include <string>

#include "scene/image.h"

namespace dsr {

struct ImageDiff {
    double max_abs = 0;       // largest per-channel difference (RGB)
    double mean_abs = 0;      // mean per-channel difference (RGB)
    double psnr_db = 0;       // of RGB, infinity when identical
    long long failing = 0;    // pixels with any channel differing by more than fail_threshold
    long long pixels = 0;
    double max_lsb() const { return max_abs * 255.0; }
    double mean_lsb() const { return mean_abs * 255.0; }
    double failing_fraction() const { return pixels ? double(failing) / pixels : 0; }
};

// Compares RGB of two images of equal size; throws dsr::Error if sizes differ.
ImageDiff compare_images(const Image& a, const Image& b, double fail_threshold);

// |a-b| * gain per channel, alpha 1: the amplified difference image written on test failure.
Image difference_image(const Image& a, const Image& b, float gain);

}  // namespace dsr
