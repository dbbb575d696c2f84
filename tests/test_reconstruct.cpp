// Eye-space position from depth (§3.4.3, Listings 19/20): depth <-> eye z are inverses, and a
// point projected to a window position and depth comes back from view_ray + depth.
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "deferred/reconstruct.h"
#include "dsr_error.h"

namespace {

const double kEps = std::numeric_limits<float>::epsilon();  // 2^-23

TEST(Reconstruct, PlanesAndDepthAtNearAndFar) {
    const glm::vec2 p = dsr::planes_uniform(0.5f, 200.0f);
    EXPECT_FLOAT_EQ(p.x, -200.0f / 199.5f);
    EXPECT_FLOAT_EQ(p.y, -200.0f * 0.5f / 199.5f);
    EXPECT_FLOAT_EQ(dsr::depth_from_eye_z(-0.5f, 0.5f, 200.0f), 0.0f);
    EXPECT_FLOAT_EQ(dsr::depth_from_eye_z(-200.0f, 0.5f, 200.0f), 1.0f);
    // Float planes: at the far end their rounding is magnified by ~far/near (docs/depth_precision.md).
    EXPECT_FLOAT_EQ(dsr::eye_z_from_depth(0.0f, p), -0.5f);
    EXPECT_NEAR(dsr::eye_z_from_depth(1.0f, p), -200.0f, 200 * 400 * 1.2e-7);
    // Listing 13's d = (planes.x*z + planes.y)/(-z) and GL's window depth, via glm::perspective.
    const glm::mat4 proj = glm::perspective(glm::radians(50.0f), 1.3f, 0.5f, 200.0f);
    for (float z : {-0.7f, -3.0f, -42.0f, -199.0f}) {
        const glm::vec4 clip = proj * glm::vec4(0.1f, -0.2f, z, 1.0f);
        const float gl = clip.z / clip.w * 0.5f + 0.5f;
        EXPECT_NEAR(dsr::depth_from_eye_z(z, 0.5f, 200.0f), gl, 1e-6f) << z;
        EXPECT_NEAR(dsr::depth_from_eye_z(z, 0.5f, 200.0f), (p.x * z + p.y) / -z, 1e-6f) << z;
    }
    EXPECT_THROW(dsr::planes_uniform(1.0f, 1.0f), dsr::Error);
    EXPECT_THROW(dsr::planes_uniform(0.0f, 1.0f), dsr::Error);
    EXPECT_THROW(dsr::depth_from_eye_z(0.0f, 0.1f, 10.0f), dsr::Error);
}

// The error allowed in z after a float depth in between: a few float roundings, magnified by the
// condition number of z(depth), |z|(f-n)/(f n) (docs/depth_precision.md: it grows like far/near near far).
double z_tolerance(double z, double n, double f) {
    return 1.5 * kEps * (1 + std::abs(z) * (f - n) / (f * n));
}

TEST(Reconstruct, DepthAndEyeZAreInverses) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    const double ratios[] = {2, 10, 100, 1e3, 1e4, 1e6};
    for (double ratio : ratios) {
        const float n = (float)std::exp(std::log(0.01) + u(rng) * std::log(100.0));
        const float f = (float)(n * ratio);
        const glm::vec2 planes = dsr::planes_uniform(n, f);
        double worst = 0;
        for (int i = 0; i < 100000; ++i) {
            // Log-uniform z between near and far.
            const float z = (float)-(n * std::exp(u(rng) * std::log((double)f / n)));
            if (!(z <= -n && z >= -f)) continue;
            const float back = dsr::eye_z_from_depth(dsr::depth_from_eye_z(z, n, f), planes);
            const double err = std::abs((double)back - z) / std::abs(z);
            const double tol = z_tolerance(z, n, f);
            worst = std::max(worst, err / tol);
            ASSERT_LE(err, tol) << "z " << z << " near " << n << " far " << f;
        }
        std::printf("[ recon    ] far/near %.0e: z -> depth -> z worst error %.2f of the "
                    "allowance\n", ratio, worst);
    }
}

TEST(Reconstruct, CornerRaysMatchViewRay) {
    const float p00 = 1.7f, p11 = 2.3f;
    const auto c = dsr::corner_rays(p00, p11);
    for (int size : {1, 317, 640}) {
        const int w = size, h = size * 3 / 4 + 1;
        const glm::vec3 at[4] = {dsr::view_ray(0, 0, w, h, p00, p11),
                                 dsr::view_ray((float)w, 0, w, h, p00, p11),
                                 dsr::view_ray((float)w, (float)h, w, h, p00, p11),
                                 dsr::view_ray(0, (float)h, w, h, p00, p11)};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 3; ++j) EXPECT_FLOAT_EQ(at[i][j], c[i][j]) << i << "," << j;
    }
    EXPECT_FLOAT_EQ(c[0].x, -1 / p00);
    EXPECT_FLOAT_EQ(c[0].y, -1 / p11);
    EXPECT_FLOAT_EQ(c[2].x, 1 / p00);
    EXPECT_FLOAT_EQ(c[2].z, -1);
    // Bilinear interpolation of the corner rays (what the rasteriser does across the quad) is
    // the view ray at that window position: the ray is affine in window coordinates.
    const int w = 640, h = 480;
    const float x = 123.5f, y = 401.5f, s = x / w, t = y / h;
    const glm::vec3 lerp = (1 - s) * (1 - t) * c[0] + s * (1 - t) * c[1] + s * t * c[2] +
                           (1 - s) * t * c[3];
    const glm::vec3 v = dsr::view_ray(x, y, w, h, p00, p11);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(lerp[j], v[j], 1e-6f);
}

// Project a random eye-space point with a real GL projection matrix, take its window position
// and depth, and reconstruct it.
TEST(Reconstruct, PositionFromWindowAndDepth) {
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u(0, 1);
    double worst = 0, worst_pix = 0;
    const int sizes[3][2] = {{512, 512}, {640, 480}, {317, 211}};
    for (int t = 0; t < 200; ++t) {
        const int w = sizes[t % 3][0], h = sizes[t % 3][1];
        const float n = (float)(0.01 + u(rng)), f = n * (float)std::exp(u(rng) * std::log(1e3));
        const float fovy = (float)glm::radians(20 + 100 * u(rng)), aspect = (float)w / h;
        const glm::mat4 proj = glm::perspective(fovy, aspect, n, f);
        const float p00 = proj[0][0], p11 = proj[1][1];
        const glm::vec2 planes = dsr::planes_uniform(n, f);
        for (int i = 0; i < 500; ++i) {
            // (a) A random point inside the frustum, projected with proj.
            const double za = n * std::exp(u(rng) * std::log((double)f / n));
            const glm::vec3 p((float)((2 * u(rng) - 1) * za / p00),
                              (float)((2 * u(rng) - 1) * za / p11), (float)-za);
            if (!(p.z < -n && p.z > -f)) continue;
            const glm::vec4 clip = proj * glm::vec4(p, 1);
            const glm::vec3 ndc = glm::vec3(clip) / clip.w;
            const float wx = (ndc.x + 1) * 0.5f * w, wy = (ndc.y + 1) * 0.5f * h;
            const float depth = dsr::depth_from_eye_z(p.z, n, f);
            const glm::vec3 q =
                dsr::reconstruct_position(depth, planes, dsr::view_ray(wx, wy, w, h, p00, p11));
            const double err = glm::length(glm::dvec3(q) - glm::dvec3(p)) / glm::length(glm::dvec3(p));
            worst = std::max(worst, err);
            ASSERT_LT(err, 1e-4) << "far/near " << f / n << " point " << p.x << "," << p.y << ","
                                 << p.z << " got " << q.x << "," << q.y << "," << q.z;

            // (b) A random pixel centre and eye z: the reconstructed point projects back to
            // that pixel centre.
            const float px = (float)(std::floor(u(rng) * w) + 0.5);
            const float py = (float)(std::floor(u(rng) * h) + 0.5);
            const glm::vec3 r = dsr::reconstruct_position(
                depth, planes, dsr::view_ray(px, py, w, h, p00, p11));
            const glm::vec4 rc = proj * glm::vec4(r, 1);
            const double bx = (rc.x / rc.w + 1) * 0.5 * w, by = (rc.y / rc.w + 1) * 0.5 * h;
            worst_pix = std::max({worst_pix, std::abs(bx - px), std::abs(by - py)});
            ASSERT_NEAR(bx, px, 1e-3);
            ASSERT_NEAR(by, py, 1e-3);
            ASSERT_NEAR(r.z, dsr::eye_z_from_depth(depth, planes), 0);
        }
    }
    std::printf("[ recon    ] reconstruct_position: worst relative error %.3g; pixel centres "
                "reproject within %.3g px\n", worst, worst_pix);
}

}  // namespace

// The light quads' depth (sphere_back_depth): every surface GL's GL_GEQUAL test rejects, a depth
// code above the quad's in the 24-bit buffer, is one the light shader's depth test rejects too,
// its eye z reconstructed in float and then moved towards the camera by a half float's rounding
// (the position16 path); and the quad sits within a few codes of the sphere's back, so the test
// still rejects what lies behind it.
TEST(Reconstruct, SphereBackDepthRejectsOnlyWhatTheShaderRejects) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double codes = double((1 << 24) - 1);
    int interior = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const float n = float(0.01 + u(rng)), f = float(n * std::pow(10.0, 1.0 + 4.0 * u(rng)));
        const glm::vec2 planes = dsr::planes_uniform(n, f);
        const float r = float(std::pow(10.0, -2.0 + 3.0 * u(rng)));
        const float cz = -float(u(rng) * 1.3 * f);
        const float back = dsr::sphere_back_depth(cz, r, n, f);
        ASSERT_GE(back, 0.0f);
        ASSERT_LE(back, 1.0f);
        const double quad_code = std::nearbyint(double(back) * codes);  // GL's float -> 24-bit conversion
        // Codes just above the quad's (the worst case) and a spread to the far plane.
        for (double k = quad_code + 1; k <= codes; k += std::max(1.0, std::floor((codes - k) / 64))) {
            const float z = dsr::eye_z_from_depth(float(k / codes), planes);
            const float z_half = z * float(1.0 - std::ldexp(1.0, -11));
            ASSERT_GT(std::abs(z_half - cz), r) << "near " << n << " far " << f << " centre " << cz << " radius " << r
                                                << ": code " << k << " rejected by GL, lit by the shader";
        }
        // Not conservative to the point of rejecting nothing: in window depth, at most the margins
        // (2^-9 of the distance, 2^-20) past the sphere's back.
        const double b = -(double(cz) - r);
        const auto window = [&](double a) { return double(f) * (a - n) / (a * (double(f) - n)); };
        if (b > n && b * (1 + 0x1p-9) < f) {
            ++interior;
            EXPECT_GE(double(back), window(b)) << "the quad in front of the sphere's back";
            EXPECT_LE(double(back), window(b * (1 + 0x1p-9)) + 0x1p-20 + 1e-7) << "the quad far behind the sphere's back";
        }
    }
    EXPECT_GT(interior, 100);  // the tightness check ran
}
