// Height maps as normal maps (obj_loader.h): how the OBJ loader reads a greyscale bump map.
#include <cmath>

#include <glm/glm.hpp>

#include "scene/obj_loader.h"

namespace dsr {

bool is_greyscale(const Image& img) {
    const float tol = 2.0f / 255.0f;
    for (size_t i = 0; i + 3 < img.rgba.size(); i += 4) {
        const float r = img.rgba[i], g = img.rgba[i + 1], b = img.rgba[i + 2];
        if (std::fabs(r - g) > tol || std::fabs(g - b) > tol) return false;
    }
    return true;
}

Image height_to_normal(const Image& height, float strength) {
    Image out;
    out.width = height.width;
    out.height = height.height;
    out.rgba.resize(height.rgba.size());
    const int w = height.width, h = height.height;
    auto hgt = [&](int x, int y) { return double(height.at((x + w) % w, (y + h) % h)[0]); };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double dx = (hgt(x + 1, y) - hgt(x - 1, y)) * 0.5, dy = (hgt(x, y + 1) - hgt(x, y - 1)) * 0.5;
            glm::dvec3 n(-double(strength) * dx, -double(strength) * dy, 1.0);
            n /= std::sqrt(glm::dot(n, n));
            float* d = out.at(x, y);
            d[0] = float(n.x * 0.5 + 0.5);
            d[1] = float(n.y * 0.5 + 0.5);
            d[2] = float(n.z * 0.5 + 0.5);
            d[3] = 1.0f;
        }
    return out;
}

}  // namespace dsr
