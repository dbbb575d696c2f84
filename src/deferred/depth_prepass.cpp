// The depth pre-pass choice (depth_prepass.h).
#include "deferred/depth_prepass.h"

namespace dsr {

bool DepthPrepassChoice::run_next() const {
    if (!measured_ || frames_without_ >= remeasure_) return true;
    return *complexity() > threshold_;
}

void DepthPrepassChoice::measured_with_prepass(long long shaded, long long covered) {
    measured_ = true;
    shaded_ = shaded;
    covered_ = covered;
    frames_without_ = 0;
}

void DepthPrepassChoice::measured_without(long long shaded) {
    if (!measured_) return;  // no covered count to set it against: the next frame measures both
    shaded_ = shaded;
    ++frames_without_;
}

std::optional<double> DepthPrepassChoice::complexity() const {
    if (!measured_) return std::nullopt;
    if (covered_ <= 0) return 1.0;  // nothing drawn: no overdraw to save
    return double(shaded_) / double(covered_);
}

}  // namespace dsr
