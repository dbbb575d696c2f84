// light_scissor (Listing 16) against brute force: project many points of each light sphere
// (surface, interior, and the disk where it meets the near plane) that can be visible surface
// points (z <= -near), and require every pixel they land on to be inside the rectangle; for
// spheres wholly in front of the near plane and on screen, also require the rectangle to be at
// most 2 pixels larger on each side than the projected points' bounding box.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "analysis/sphere_samples.h"
#include "deferred/scissor.h"
#include "dsr_error.h"

namespace {

using dsr::ScissorRect;

struct Camera {
    float p00, p11, near_plane;
    int w, h;
};

struct Sphere {
    glm::vec3 c;  // eye space
    float r;
};

// Surface, interior and near-plane disk points per sphere (src/analysis/sphere_samples.h).
const dsr::SphereSampleCounts kSamples{1500, 300, 200};

struct Brute {
    double minx = INFINITY, maxx = -INFINITY, miny = INFINITY, maxy = -INFINITY;
    long long points = 0, outside = 0;  // points with z <= -near; of them, pixels not in rect
    std::string first_miss;
};

class Sampler {
public:
    explicit Sampler(unsigned seed) : rng_(seed) {}
    std::mt19937_64& rng() { return rng_; }
    double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
    double log_uni(double a, double b) { return std::exp(uni(std::log(a), std::log(b))); }

    Camera camera() {
        static const int sizes[3][2] = {{512, 512}, {640, 480}, {317, 211}};
        const int* s = sizes[std::uniform_int_distribution<int>(0, 2)(rng_)];
        const double fovy = glm::radians(uni(20, 120)), aspect = uni(0.5, 2.0);
        const double p11 = 1.0 / std::tan(fovy / 2);
        return {(float)(p11 / aspect), (float)p11, (float)log_uni(0.01, 1.0), s[0], s[1]};
    }

    // Projects every sample point of the sphere with z <= -near and checks it against rect.
    Brute run(const Sphere& s, const Camera& cam, const ScissorRect& rect) {
        Brute b;
        const double n = cam.near_plane;
        for (const glm::dvec3& p : dsr::sphere_samples(glm::dvec3(s.c), s.r, n, kSamples, rng_)) {
            if (p.z > -n) continue;
            ++b.points;
            const double wx = (cam.p00 * p.x / -p.z + 1.0) * 0.5 * cam.w;
            const double wy = (cam.p11 * p.y / -p.z + 1.0) * 0.5 * cam.h;
            b.minx = std::min(b.minx, wx), b.maxx = std::max(b.maxx, wx);
            b.miny = std::min(b.miny, wy), b.maxy = std::max(b.maxy, wy);
            const double px = std::floor(wx), py = std::floor(wy);
            // A point projecting outside the viewport covers no pixel.
            if (px < 0 || px >= cam.w || py < 0 || py >= cam.h) continue;
            if (px < rect.x0 || px >= rect.x1 || py < rect.y0 || py >= rect.y1) {
                if (b.outside++ == 0) {
                    char buf[160];
                    std::snprintf(buf, sizeof buf, "point (%.9g,%.9g,%.9g) -> pixel (%g,%g)",
                                  p.x, p.y, p.z, px, py);
                    b.first_miss = buf;
                }
            }
        }
        return b;
    }

private:
    std::mt19937_64 rng_;
};

ScissorRect scissor(const Sphere& s, const Camera& cam) {
    return dsr::light_scissor(s.c, s.r, cam.p00, cam.p11, cam.near_plane, cam.w, cam.h);
}

std::string describe(const Sphere& s, const Camera& cam, const ScissorRect& rc) {
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "light (%.9g,%.9g,%.9g) r=%.9g p00=%.9g p11=%.9g near=%.9g %dx%d -> rect "
                  "[%d,%d)x[%d,%d)",
                  s.c.x, s.c.y, s.c.z, s.r, cam.p00, cam.p11, cam.near_plane, cam.w, cam.h, rc.x0,
                  rc.x1, rc.y0, rc.y1);
    return buf;
}

void expect_valid(const ScissorRect& rc, const Camera& cam) {
    if (rc.empty()) {
        EXPECT_EQ(rc.area(), 0);
        return;
    }
    EXPECT_GE(rc.x0, 0);
    EXPECT_GE(rc.y0, 0);
    EXPECT_LE(rc.x1, cam.w);
    EXPECT_LE(rc.y1, cam.h);
}

enum Family { kGeneral, kInFront, kCrossNear, kInside, kBehind, kEyePlane, kTouchEyePlane,
              kAxis, kFamilies };
const char* kFamilyNames[kFamilies] = {"general", "in front", "crossing near",
                                       "eye inside", "behind near", "centre on eye plane",
                                       "touching eye plane", "centre on an axis plane"};

Sphere make_sphere(Sampler& g, Family f, const Camera& cam) {
    const double n = cam.near_plane;
    const double tx = 1.0 / cam.p00, ty = 1.0 / cam.p11;  // half-extents of the view at z = -1
    double r = g.log_uni(0.01, 30.0), b, x, y;
    switch (f) {
    case kGeneral:
        b = g.uni(-60, 100);
        x = g.uni(-2, 2) * tx * (std::abs(b) + r);
        y = g.uni(-2, 2) * ty * (std::abs(b) + r);
        break;
    case kInFront:
        b = n + r + g.log_uni(1e-4, 40) * r;
        x = g.uni(-0.9, 0.9) * tx * b;
        y = g.uni(-0.9, 0.9) * ty * b;
        break;
    case kCrossNear:
        b = n + g.uni(-1, 1) * r;
        x = g.uni(-1.5, 1.5) * tx * (b + r);
        y = g.uni(-1.5, 1.5) * ty * (b + r);
        break;
    case kInside: {
        glm::dvec3 d(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1));
        d *= g.uni(0, 0.99) * r / std::max(1e-9, glm::length(d));
        x = d.x, y = d.y, b = -d.z;
        break;
    }
    case kBehind:
        b = n - r - g.log_uni(1e-5, 50) * (r + n);
        x = g.uni(-2, 2) * (std::abs(b) + r);
        y = g.uni(-2, 2) * (std::abs(b) + r);
        break;
    case kEyePlane:  // Listing 16 divides by l.z
        r = n * g.log_uni(1.01, 1000);
        b = 0;
        x = g.uni(-3, 3) * r;
        y = g.uni(-3, 3) * r;
        break;
    case kTouchEyePlane: {  // |l.z| = r: a tangent plane is the eye plane, Listing 16's nx = 0
        const float rf = (float)r;
        return {glm::vec3((float)(g.uni(-3, 3) * r), (float)(g.uni(-3, 3) * r),
                          g.uni(0, 1) < 0.5 ? -rf : rf),
                rf};
    }
    case kAxis:
    default:
        b = g.uni(-0.5, 1) * 30;
        x = g.uni(-1.5, 1.5) * tx * (std::abs(b) + r);
        y = g.uni(-1.5, 1.5) * ty * (std::abs(b) + r);
        if (g.uni(0, 1) < 0.5) x = 0; else y = 0;
        if (g.uni(0, 1) < 0.25) x = y = 0;
        break;
    }
    return {glm::vec3((float)x, (float)y, (float)-b), (float)r};
}

TEST(Scissor, ContainsEveryVisibleSpherePointAndIsTight) {
    Sampler g(20240611u);
    const int counts[kFamilies] = {6000, 4000, 3000, 1000, 1000, 1500, 1500, 2000};
    long long misses_total = 0, cases = 0, points = 0;
    int nonempty = 0, tight_cases = 0, loose_cases = 0;
    double ratio_sum = 0, worst_slack = 0;
    for (int f = 0; f < kFamilies; ++f) {
        int family_misses = 0;
        for (int i = 0; i < counts[f]; ++i) {
            const Camera cam = g.camera();
            const Sphere s = make_sphere(g, (Family)f, cam);
            const ScissorRect rc = scissor(s, cam);
            ++cases;
            expect_valid(rc, cam);
            const Brute b = g.run(s, cam, rc);
            points += b.points;
            if (b.outside) {
                misses_total += b.outside;
                if (family_misses++ < 3)
                    ADD_FAILURE() << kFamilyNames[f] << ": " << b.outside << " of " << b.points
                                  << " visible points fall outside the rectangle, first "
                                  << b.first_miss << "; " << describe(s, cam, rc);
            }
            const double n = cam.near_plane, c = -(double)s.c.z, r = s.r;
            const double d2 = glm::dot(glm::dvec3(s.c), glm::dvec3(s.c));
            if (f == kInside || (f != kBehind && d2 < r * r)) {
                // Eye inside the sphere: full viewport if it reaches past near, else empty.
                const bool reaches = c + r >= n;
                if (reaches)
                    EXPECT_TRUE(rc.x0 == 0 && rc.y0 == 0 && rc.x1 == cam.w && rc.y1 == cam.h)
                        << describe(s, cam, rc);
                else
                    EXPECT_TRUE(rc.empty()) << describe(s, cam, rc);
            }
            if (c + r < n) {
                EXPECT_TRUE(rc.empty()) << "no point at z <= -near: " << describe(s, cam, rc);
                EXPECT_EQ(b.points, 0);
            }
            if (!rc.empty()) ++nonempty;
            // Tightness: wholly in front of near, projected points wholly on screen.
            if (c - r > n && b.points && b.minx >= 1 && b.maxx <= cam.w - 1 && b.miny >= 1 &&
                b.maxy <= cam.h - 1) {
                const double bx0 = std::floor(b.minx), bx1 = std::floor(b.maxx) + 1;
                const double by0 = std::floor(b.miny), by1 = std::floor(b.maxy) + 1;
                const double slack = std::max({bx0 - rc.x0, rc.x1 - bx1, by0 - rc.y0,
                                               rc.y1 - by1});
                worst_slack = std::max(worst_slack, slack);
                if (slack > 2 && loose_cases++ < 3)
                    ADD_FAILURE() << "rectangle " << slack << " px larger than the points' "
                                  << "bounding box [" << bx0 << "," << bx1 << ")x[" << by0
                                  << "," << by1 << "): " << describe(s, cam, rc);
                ratio_sum += (double)rc.area() / ((bx1 - bx0) * (by1 - by0));
                ++tight_cases;
            }
        }
    }
    EXPECT_EQ(misses_total, 0);
    EXPECT_EQ(loose_cases, 0);
    EXPECT_GT(tight_cases, 2000);  // the tightness check really ran
    const double mean_ratio = tight_cases ? ratio_sum / tight_cases : 0;
    std::printf("[ scissor  ] %lld spheres (%d non-empty rects), %lld visible points checked; "
                "tight family: %d spheres, mean area rect/brute-force bbox %.4f, worst side "
                "slack %.0f px\n",
                cases, nonempty, points, tight_cases, mean_ratio, worst_slack);
    RecordProperty("mean_area_ratio", std::to_string(mean_ratio));
    EXPECT_LT(mean_ratio, 1.1);
}

// make_frame computes its spheres' rectangles two at a time (light_scissors, one light a SIMD
// lane). The test above checks a lone light, lane 0; here every sphere of every family, in a batch
// and shifted by one so that it is drawn in each lane, must get the lone light's rectangle.
TEST(Scissor, EachLaneOfABatchIsTheLoneLightsRectangle) {
    Sampler g(20261206u);
    int compared = 0, nonempty = 0;
    for (int round = 0; round < 400; ++round) {
        const Camera cam = g.camera();
        std::vector<dsr::EyeSphere> batch;
        for (int i = 0; i < 37; ++i) {  // odd: the last light of a batch is a lane alone
            const Sphere s = make_sphere(g, Family(std::uniform_int_distribution<int>(0, kFamilies - 1)(g.rng())), cam);
            batch.push_back({s.c, s.r});
        }
        for (size_t shift = 0; shift < 2; ++shift) {
            std::vector<ScissorRect> rects(batch.size() - shift, ScissorRect{-7, -7, -7, -7});
            dsr::light_scissors(batch.data() + shift, rects.size(), cam.p00, cam.p11, cam.near_plane, cam.w, cam.h,
                                rects.data());
            for (size_t i = 0; i < rects.size(); ++i) {
                const dsr::EyeSphere& e = batch[i + shift];
                const ScissorRect lone = scissor({e.centre, e.radius}, cam);
                const ScissorRect& r = rects[i];
                ASSERT_TRUE(r.x0 == lone.x0 && r.y0 == lone.y0 && r.x1 == lone.x1 && r.y1 == lone.y1)
                    << "lane " << (i % 2) << ": [" << r.x0 << "," << r.x1 << ")x[" << r.y0 << "," << r.y1
                    << ") against " << describe({e.centre, e.radius}, cam, lone);
                ++compared;
                nonempty += !lone.empty();
            }
        }
    }
    EXPECT_GT(nonempty, compared / 4);  // the batches held lights that reach the screen
    // A bad sphere anywhere in the batch: the error, and no rectangle written.
    std::vector<dsr::EyeSphere> bad = {{{0, 0, -5}, 1}, {{0, 0, -5}, 1}, {{0, NAN, -5}, 1}};
    std::vector<ScissorRect> rects(3, ScissorRect{-7, -7, -7, -7});
    EXPECT_THROW(dsr::light_scissors(bad.data(), 3, 1, 1, 0.1f, 64, 64, rects.data()), dsr::Error);
    for (const ScissorRect& r : rects) EXPECT_EQ(r.x0, -7);
}

TEST(Scissor, ExplicitCases) {
    const float p = 1.0f / std::tan(glm::radians(30.0f));  // 60 degree square frustum
    // Centred sphere well in front: symmetric rect around the middle.
    ScissorRect rc = dsr::light_scissor({0, 0, -10}, 1, p, p, 0.1f, 512, 512);
    EXPECT_EQ(rc.x0 + rc.x1, 512);
    EXPECT_EQ(rc.y0 + rc.y1, 512);
    // Half-angle asin(1/10): ndc extent p*tan(asin(0.1)).
    const double e = p * std::tan(std::asin(0.1)) * 256;
    EXPECT_NEAR(rc.x1 - 256, e, 1.0);
    // Eye inside, sphere reaching past near: whole viewport.
    rc = dsr::light_scissor({0.3f, -0.2f, 0.5f}, 2, p, p, 0.1f, 640, 480);
    EXPECT_TRUE(rc.x0 == 0 && rc.y0 == 0 && rc.x1 == 640 && rc.y1 == 480);
    // Wholly behind the eye and behind near.
    EXPECT_TRUE(dsr::light_scissor({0, 0, 5}, 1, p, p, 0.1f, 640, 480).empty());
    EXPECT_TRUE(dsr::light_scissor({0, 0, -0.5f}, 0.3f, p, p, 0.9f, 640, 480).empty());
    // Off screen to the left: empty, not a column at the edge.
    EXPECT_TRUE(dsr::light_scissor({-100, 0, -10}, 1, p, p, 0.1f, 640, 480).empty());
    // Centre on the eye plane, reaching past near: bounded by the near-plane disk, finite.
    rc = dsr::light_scissor({5, 0, 0}, 1, p, p, 0.1f, 640, 480);
    EXPECT_TRUE(rc.empty());  // x/(-z) >= (5-1)/0.1 * p: far right, off screen
    rc = dsr::light_scissor({0.01f, 0, 0}, 1, p, p, 0.1f, 640, 480);
    EXPECT_EQ(rc.area(), 640 * 480);  // eye inside
    // The extreme lands exactly on a pixel boundary: (0,0,-1) is on the sphere, at z = -near,
    // and its tangent line x = 0 passes through the eye, so the rightmost visible point has
    // window x = 32 exactly and lies in pixel 32 (ceil(32) = 32 would drop it).
    // The other extremes are the near-plane disk's rim: x/(-z) = -1, y/(-z) = +-0.5.
    rc = dsr::light_scissor({-0.5f, 0, -1}, 0.5f, 0.5f, 1, 1, 64, 64);
    EXPECT_EQ(rc.x1, 33);
    EXPECT_TRUE(rc.x0 == 15 || rc.x0 == 16) << rc.x0;  // window x = 16 exactly
    EXPECT_TRUE(rc.y0 == 15 || rc.y0 == 16) << rc.y0;
    EXPECT_EQ(rc.y1, 49);
    // Zero-sized viewport and degenerate input.
    EXPECT_TRUE(dsr::light_scissor({0, 0, -10}, 1, p, p, 0.1f, 0, 480).empty());
    EXPECT_THROW(dsr::light_scissor({0, 0, NAN}, 1, p, p, 0.1f, 64, 64), dsr::Error);
    EXPECT_THROW(dsr::light_scissor({0, 0, -1}, INFINITY, p, p, 0.1f, 64, 64), dsr::Error);
    EXPECT_THROW(dsr::light_scissor({0, 0, -1}, -1, p, p, 0.1f, 64, 64), dsr::Error);
    EXPECT_THROW(dsr::light_scissor({0, 0, -1}, 1, p, p, 0.0f, 64, 64), dsr::Error);
}

// Listing 16 as printed: agrees with the exact rectangle to within its truncation only when the
// projection happens to be its fixed e1 = 1.2 and the sphere is in front of the eye.
TEST(Scissor, Listing16Defects) {
    Sampler g(7u);
    const int w = 640, h = 480;
    const float aspect = (float)w / h;
    int fixed_fov_cases = 0, fixed_fov_miss = 0, max_dev = 0;
    int other_fov_cases = 0, other_fov_miss = 0;
    for (int i = 0; i < 4000; ++i) {
        const bool fixed = i % 2 == 0;
        Camera cam = g.camera();
        cam.w = w, cam.h = h;
        if (fixed) cam.p00 = 1.2f, cam.p11 = 1.2f * aspect;
        const Sphere s = make_sphere(g, kInFront, cam);
        const ScissorRect lit = dsr::light_scissor_listing16(s.c, s.r, aspect, w, h);
        const Brute b = g.run(s, cam, lit);
        if (fixed) {
            ++fixed_fov_cases;
            fixed_fov_miss += b.outside > 0;
            const ScissorRect ex = scissor(s, cam);
            if (!lit.empty() && !ex.empty())
                max_dev = std::max({max_dev, std::abs(lit.x0 - ex.x0), std::abs(lit.x1 - ex.x1),
                                    std::abs(lit.y0 - ex.y0), std::abs(lit.y1 - ex.y1)});
        } else {
            ++other_fov_cases;
            other_fov_miss += b.outside > 0;
        }
    }
    std::printf("[ scissor  ] Listing 16 literal: e1 = 1.2 projection: %d/%d rects miss visible "
                "pixels (truncation), max deviation from exact %d px; random fov: %d/%d miss\n",
                fixed_fov_miss, fixed_fov_cases, max_dev, other_fov_miss, other_fov_cases);
    EXPECT_LE(max_dev, 1);                          // same tangent planes, (int) truncation only
    EXPECT_GT(other_fov_miss, other_fov_cases / 10);  // the fixed field of view is wrong in general

    const float p00 = 1.2f, p11 = 1.2f * aspect;
    // Wholly behind the eye: the listing keeps the full-screen rectangle (no tangent point in
    // front), dsr gives nothing.
    const ScissorRect behind = dsr::light_scissor_listing16({0, 0, 10}, 1, aspect, w, h);
    EXPECT_EQ(behind.area(), (long long)w * h);
    EXPECT_TRUE(dsr::light_scissor({0, 0, 10}, 1, p00, p11, 0.1f, w, h).empty());
    // Centre on the eye plane: division by l.z = 0; non-finite -> full viewport, no UB.
    EXPECT_EQ(dsr::light_scissor_listing16({2, 1, 0}, 1, aspect, w, h).area(), (long long)w * h);
}

}  // namespace
