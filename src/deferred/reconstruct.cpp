// Eye-space position from depth (§3.4.3, Listings 19 and 20).
#include "deferred/reconstruct.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "dsr_error.h"

namespace dsr {

namespace {
void check_planes(float n, float f, const char* who) {
    if (!std::isfinite(n) || !std::isfinite(f) || !(n > 0) || !(f > n))
        throw Error(std::string(who) + ": need 0 < near < far, got near " + std::to_string(n) +
                    ", far " + std::to_string(f));
}
}  // namespace

glm::vec2 planes_uniform(float near_plane, float far_plane) {
    check_planes(near_plane, far_plane, "planes_uniform");
    const double n = near_plane, f = far_plane;
    return {(float)(-f / (f - n)), (float)(-f * n / (f - n))};
}

float eye_z_from_depth(float depth, glm::vec2 planes) {
    // planes.x + depth <= -n/(f-n) < 0 for depth in [0,1]: no division by zero in range.
    return (float)(-(double)planes.y / ((double)planes.x + depth));
}

float depth_from_eye_z(float z, float near_plane, float far_plane) {
    check_planes(near_plane, far_plane, "depth_from_eye_z");
    if (!(z < 0)) throw Error("depth_from_eye_z: eye z must be < 0, got " + std::to_string(z));
    // (planes.x*z + planes.y)/(-z) rearranged to f*(a - n)/(a*(f - n)) with a = -z, which has no
    // cancellation between planes.x*z and planes.y.
    const double n = near_plane, f = far_plane, a = -(double)z;
    return (float)(f * (a - n) / (a * (f - n)));
}

float sphere_back_depth(float centre_z, float radius, float near_plane, float far_plane) {
    check_planes(near_plane, far_plane, "sphere_back_depth");
    const double back = -(double(centre_z) - double(radius));  // its distance along -z
    const double a = back + std::abs(back) * 0x1p-9;
    if (!(a > near_plane)) return 0.0f;  // the whole span in front of the near plane
    if (!(a < far_plane)) return 1.0f;
    const double n = near_plane, f = far_plane;
    return (float)std::min(1.0, f * (a - n) / (a * (f - n)) + 0x1p-20);
}

glm::vec3 view_ray(float win_x, float win_y, int width, int height, float p00, float p11) {
    // Window -> NDC (x_ndc = 2*win_x/width - 1), then NDC -> eye direction at z = -1, since
    // ndc_x = p00*x/(-z).
    const double nx = 2.0 * win_x / width - 1.0, ny = 2.0 * win_y / height - 1.0;
    return {(float)(nx / p00), (float)(ny / p11), -1.0f};
}

std::array<glm::vec3, 4> corner_rays(float p00, float p11) {
    const float x = (float)(1.0 / p00), y = (float)(1.0 / p11);
    return {glm::vec3(-x, -y, -1.0f), glm::vec3(x, -y, -1.0f), glm::vec3(x, y, -1.0f),
            glm::vec3(-x, y, -1.0f)};
}

glm::vec3 reconstruct_position(float depth, glm::vec2 planes, glm::vec3 ray) {
    const double z = -(double)planes.y / ((double)planes.x + depth);
    return {(float)(ray.x / (double)ray.z * z), (float)(ray.y / (double)ray.z * z), (float)z};
}

}  // namespace dsr
