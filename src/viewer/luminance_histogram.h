// The viewer's histogram of P-buffer 0's luminance (docs/hdr.md), from the final stage's reduced
// copy (FinalStage::reduce_luminance: each block's mean log2 L and its largest L). Pure.
#pragma once
#include <vector>

#include <glm/glm.hpp>

namespace dsr {

struct LuminanceHistogram {
    std::vector<float> bins;  // blocks per bin of mean log2 L over [lo, hi]; outside: the end bins; none without blocks
    double above_one = 0;     // share of blocks whose largest L is above 1: what RGBA8 clips
};

LuminanceHistogram luminance_histogram(const std::vector<glm::vec2>& blocks, int bins, float lo, float hi);

}  // namespace dsr
