// Wall-clock milliseconds and medians: how every stage time and benchmark row is measured.
#pragma once
#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

namespace dsr {

inline double now_ms() {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// CPU time of the calling thread, in milliseconds: what submitting a frame costs the CPU, apart
// from waiting for the GPU (the renderers read it before their end-of-frame wait).
inline double thread_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// Median of v (0 for none); the mean of the middle two for an even count.
inline double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace dsr
