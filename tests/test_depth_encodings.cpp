// CPU twins of the packed target's encodings (glsl120/depth_codec.glsl packed_encode /
// packed_eye_z): eye z -> RGB8 (stored as an 8-bit target stores it) -> eye z.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "deferred/depth_codec.h"
#include "dsr_error.h"

using namespace dsr;

namespace {
struct Err {
    double max = 0, mean = 0;
};

// Relative eye-z error over z log-spaced from near to far.
Err sweep(DepthEncoding e, float n, float f, int samples = 20000) {
    Err r;
    for (int i = 0; i < samples; ++i) {
        double t = (i + 0.5) / samples;
        float z = -float(n * std::pow(double(f) / n, t));
        float back = decode_eye_z(e, store_unorm8(encode_eye_z(e, z, n, f)), n, f);
        double rel = std::fabs(double(back) - z) / std::fabs(double(z));
        r.max = std::max(r.max, rel);
        r.mean += rel / samples;
    }
    return r;
}
}  // namespace

TEST(DepthEncodings, NamesRoundTrip) {
    for (DepthEncoding e : {DepthEncoding::literal, DepthEncoding::corrected, DepthEncoding::linear, DepthEncoding::log})
        EXPECT_EQ(encoding_from_name(encoding_name(e)), e);
    EXPECT_THROW(encoding_from_name("cubic"), Error);
}

// The tables docs/accuracy.md measures, docs/depth_precision.md explains: log keeps a constant relative error (~ln(f/n)/2^24),
// the window-depth packings lose it near the far plane (~f/n/2^24), linear near the camera.
TEST(DepthEncodings, RelativeEyeZErrorOnTheCpu) {
    const float n = 0.1f;
    std::printf("[ z error  ] %-10s %12s %12s %12s   (max relative eye-z error, z log-spaced near..far)\n", "encoding",
                "f/n 1e2", "f/n 1e4", "f/n 1e6");
    Err worst[4];
    for (DepthEncoding e : {DepthEncoding::literal, DepthEncoding::corrected, DepthEncoding::linear, DepthEncoding::log}) {
        Err at[3];
        for (int k = 0; k < 3; ++k) at[k] = sweep(e, n, n * float(std::pow(10.0, 2 + 2 * k)));
        std::printf("[ z error  ] %-10s %12.3g %12.3g %12.3g\n", encoding_name(e), at[0].max, at[1].max, at[2].max);
        worst[int(e)] = at[2];
        if (e == DepthEncoding::log) {
            for (int k = 0; k < 3; ++k) EXPECT_LE(at[k].max, 2e-6) << "log at ratio index " << k;
        }
        if (e == DepthEncoding::literal) {
            EXPECT_GT(at[0].max, 1e-3);  // Listings 11/18's byte loss
        }
    }
    EXPECT_GT(worst[int(DepthEncoding::corrected)].max, 1e-2);  // the far-plane cancellation at 1e6
    EXPECT_GT(worst[int(DepthEncoding::linear)].max, 1e-2);     // near the camera at 1e6
}
