// Light frustum culling (Listing 17). Listing 17 loops over five planes (p < 5) of
// g_render->view.planes, whose order and sign convention the tutorial does not show; dsr tests
// all six, with normalised inward planes, which is what makes "d < -radius" a distance test.
#include "deferred/culling.h"

#include <cmath>
#include <string>

#include "dsr_error.h"

namespace dsr {

std::array<Plane, 6> frustum_planes(const glm::mat4& m) {
    // glm is column-major (m[column][row]); the plane tests are on rows of the clip matrix:
    // a point is inside when -w <= x, y, z <= w, i.e. (row3 +- row_i) . (p, 1) >= 0.
    auto row = [&m](int i) { return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
    const glm::dvec4 r0 = row(0), r1 = row(1), r2 = row(2), r3 = row(3);
    const glm::dvec4 raw[6] = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2};
    static const char* names[6] = {"left", "right", "bottom", "top", "near", "far"};

    std::array<Plane, 6> planes;
    for (int i = 0; i < 6; ++i) {
        // Double so the near/far rows' difference keeps what the float matrix holds.
        const double len = glm::length(glm::dvec3(raw[i]));
        if (!(len > 0) || !std::isfinite(len) || !std::isfinite(raw[i].w))
            throw Error(std::string("frustum_planes: degenerate ") + names[i] +
                        " plane in the view-projection matrix");
        planes[i] = {glm::vec3(glm::dvec3(raw[i]) / len), (float)(raw[i].w / len)};
    }
    return planes;
}

bool sphere_outside(const std::array<Plane, 6>& planes, glm::vec3 center, float radius) {
    return FrustumTest(planes).sphere_outside(center, radius);
}

FrustumTest::FrustumTest(const std::array<Plane, 6>& planes) {
    for (size_t i = 0; i < planes.size(); ++i) planes_[i] = glm::dvec4(glm::dvec3(planes[i].n), double(planes[i].d));
}

}  // namespace dsr
