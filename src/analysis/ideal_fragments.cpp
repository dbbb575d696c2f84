// The ideal fragment count (ideal_fragments.h): surface points from each source, and the one
// tiled count over the lights' eye-space volumes that every form calls.
#include "analysis/ideal_fragments.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "deferred/reconstruct.h"

namespace dsr {

Image positions_from_depth(const Image& depth, glm::vec2 planes, float p00, float p11) {
    Image out;
    out.width = depth.width;
    out.height = depth.height;
    out.rgba.assign(depth.rgba.size(), 0.0f);
    for (int y = 0; y < depth.height; ++y)
        for (int x = 0; x < depth.width; ++x) {
            const float d = depth.at(x, y)[0];
            if (!(d < 1.0f)) continue;  // the clear value: no surface
            const glm::vec3 ray = view_ray(float(x) + 0.5f, float(y) + 0.5f, depth.width, depth.height, p00, p11);
            const glm::vec3 p = reconstruct_position(d, planes, ray);
            float* q = out.at(x, y);
            q[0] = p.x, q[1] = p.y, q[2] = p.z, q[3] = 1.0f;
        }
    return out;
}

namespace {

std::vector<EyeVolume> spheres(const std::vector<glm::dvec4>& lights) {
    std::vector<EyeVolume> out;
    for (const glm::dvec4& l : lights) {
        EyeVolume v;
        v.pos = glm::dvec3(l);
        v.radius = l.w;
        out.push_back(v);
    }
    return out;
}

std::vector<glm::dvec4> to_double(const std::vector<glm::vec4>& lights) {
    return std::vector<glm::dvec4>(lights.begin(), lights.end());
}

}  // namespace

long long ideal_fragments(const Image& positions, const std::vector<glm::vec4>& lights) {
    return ideal_fragments(surface_from_positions(positions), spheres(to_double(lights)));
}

long long ideal_fragments_brute(const Image& positions, const std::vector<glm::vec4>& lights) {
    return ideal_fragments_brute(surface_from_positions(positions), spheres(to_double(lights)));
}

glm::dvec2 projection_scale(const Camera& camera, int width, int height) {
    const double t = std::tan(double(camera.fov_deg) * M_PI / 360.0);
    const double aspect = double(width) / double(height);
    return {1.0 / (aspect * t), 1.0 / t};
}

namespace {

SurfacePoints empty_points(int w, int h) {
    SurfacePoints s;
    s.width = w, s.height = h;
    s.p.assign(size_t(w) * h, glm::dvec3(0));
    s.surface.assign(size_t(w) * h, 0);
    return s;
}

// The pixel-centre ray scaled to eye depth `depth` (> 0).
glm::dvec3 point_at_depth(int x, int y, int w, int h, glm::dvec2 p, double depth) {
    const double xn = 2.0 * (x + 0.5) / w - 1.0, yn = 2.0 * (y + 0.5) / h - 1.0;
    return {xn * depth / p.x, yn * depth / p.y, -depth};
}

}  // namespace

SurfacePoints surface_from_eye_depth(const std::vector<double>& eye_depth, int w, int h, glm::dvec2 p) {
    SurfacePoints s = empty_points(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            const double d = i < eye_depth.size() ? eye_depth[i] : 0.0;
            if (!(d > 0)) continue;
            s.p[i] = point_at_depth(x, y, w, h, p, d);
            s.surface[i] = 1;
        }
    return s;
}

SurfacePoints surface_from_depth_codes(const std::vector<uint32_t>& codes, int w, int h, double n, double f,
                                       glm::dvec2 p) {
    SurfacePoints s = empty_points(w, h);
    const double p22 = -(f + n) / (f - n), p32 = -2.0 * f * n / (f - n);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            const uint32_t code = (i < codes.size() ? codes[i] : 0xffffffffu) >> 8;
            if (code >= 0xffffffu) continue;  // the clear value 1: background
            const double d = double(code) / 16777215.0;
            const double z = -p32 / (2.0 * d - 1.0 + p22);
            s.p[i] = point_at_depth(x, y, w, h, p, -z);
            s.surface[i] = 1;
        }
    return s;
}

SurfacePoints surface_from_positions(const Image& positions) {
    SurfacePoints s = empty_points(positions.width, positions.height);
    for (int y = 0; y < positions.height; ++y)
        for (int x = 0; x < positions.width; ++x) {
            const float* q = positions.at(x, y);
            if (!(q[3] > 0.5f)) continue;
            const size_t i = size_t(y) * positions.width + x;
            s.p[i] = glm::dvec3(q[0], q[1], q[2]);
            s.surface[i] = 1;
        }
    return s;
}

namespace {

struct DTile {
    int x0, y0, x1, y1;
    glm::dvec3 lo, hi;
};

std::vector<DTile> surface_tiles(const SurfacePoints& s) {
    constexpr int kTile = 16;
    std::vector<DTile> tiles;
    const double inf = std::numeric_limits<double>::infinity();
    for (int ty = 0; ty < s.height; ty += kTile)
        for (int tx = 0; tx < s.width; tx += kTile) {
            DTile t{tx, ty, std::min(tx + kTile, s.width), std::min(ty + kTile, s.height), glm::dvec3(inf),
                    glm::dvec3(-inf)};
            for (int y = t.y0; y < t.y1; ++y)
                for (int x = t.x0; x < t.x1; ++x) {
                    const size_t i = size_t(y) * s.width + x;
                    if (!s.surface[i]) continue;
                    t.lo = glm::min(t.lo, s.p[i]);
                    t.hi = glm::max(t.hi, s.p[i]);
                }
            if (t.lo.x <= t.hi.x) tiles.push_back(t);
        }
    return tiles;
}

}  // namespace

std::vector<EyeVolume> eye_volumes(const std::vector<Light>& lights, const glm::dmat4& view) {
    std::vector<EyeVolume> out;
    for (const Light& l : lights) {
        if (l.color == glm::vec3(0.0f)) continue;
        const LightVolume w = light_volume(l);
        EyeVolume e;
        e.kind = w.kind;
        e.pos = glm::dvec3(view * glm::dvec4(glm::dvec3(w.pos), 1.0));
        e.axis = glm::normalize(glm::dmat3(view) * glm::dvec3(w.axis));
        e.radius = w.radius;
        e.cos_angle = std::cos(glm::radians(double(l.angle_deg)));
        out.push_back(e);
    }
    return out;
}

std::vector<EyeVolume> eye_volumes(const Scene& scene) { return eye_volumes(scene.lights, scene.camera.view_d()); }

bool inside(const EyeVolume& v, const glm::dvec3& p) {
    if (v.kind == LightVolume::Kind::full_screen) return true;
    if (!(v.radius > 0)) return false;  // no volume: the tiled count skips it too
    const glm::dvec3 d = p - v.pos;
    const double d2 = glm::dot(d, d);
    if (!(d2 < v.radius * v.radius)) return false;
    return v.kind == LightVolume::Kind::sphere || glm::dot(d, v.axis) > std::sqrt(d2) * v.cos_angle;
}

long long ideal_fragments(const SurfacePoints& s, const std::vector<EyeVolume>& lights) {
    const std::vector<DTile> tiles = surface_tiles(s);
    long long n = 0;
    for (const EyeVolume& l : lights) {
        const bool all = l.kind == LightVolume::Kind::full_screen;
        if (!all && !(l.radius > 0)) continue;
        for (const DTile& t : tiles) {
            if (!all) {  // the ball about the centre or apex holds the whole volume
                const glm::dvec3 d = glm::max(glm::max(t.lo - l.pos, l.pos - t.hi), glm::dvec3(0.0));
                if (glm::dot(d, d) > l.radius * l.radius) continue;
            }
            for (int y = t.y0; y < t.y1; ++y)
                for (int x = t.x0; x < t.x1; ++x) {
                    const size_t i = size_t(y) * s.width + x;
                    n += s.surface[i] && inside(l, s.p[i]);
                }
        }
    }
    return n;
}

long long ideal_fragments_brute(const SurfacePoints& s, const std::vector<EyeVolume>& lights) {
    long long n = 0;
    for (const EyeVolume& l : lights)
        for (size_t i = 0; i < s.p.size(); ++i) n += s.surface[i] && inside(l, s.p[i]);
    return n;
}

long long ideal_count(const SurfacePoints& s, const std::vector<Light>& lights, const glm::dmat4& view) {
    return ideal_fragments(s, eye_volumes(lights, view));
}

long long ideal_count_from_depth_codes(const std::vector<uint32_t>& codes, int width, int height,
                                       const Camera& camera, const std::vector<Light>& lights) {
    const SurfacePoints s = surface_from_depth_codes(codes, width, height, camera.near_plane, camera.far_plane,
                                                     projection_scale(camera, width, height));
    return ideal_count(s, lights, camera.view_d());
}

std::vector<glm::dvec4> eye_lights(const Scene& scene) {
    std::vector<glm::dvec4> out;
    for (const EyeVolume& v : eye_volumes(scene)) out.emplace_back(v.pos, v.radius);
    return out;
}

long long ideal_fragments(const SurfacePoints& s, const std::vector<glm::dvec4>& lights) {
    return ideal_fragments(s, spheres(lights));
}

long long ideal_fragments_brute(const SurfacePoints& s, const std::vector<glm::dvec4>& lights) {
    return ideal_fragments_brute(s, spheres(lights));
}

}  // namespace dsr
