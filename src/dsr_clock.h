// Wall-clock milliseconds and medians: how every stage time and benchmark row is measured.
#pragma once
#include <algorithm>
#include <chrono>
#include <vector>

namespace dsr {

inline double now_ms() {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Median of v (0 for none); the mean of the middle two for an even count.
inline double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace dsr
