// Packed depth codec, CPU twin of glsl120/depth_codec.glsl (Listings 11 and 18). Each line
// mirrors the GLSL in depth_codec.h in float arithmetic; only store_unorm8, which models the
// hardware's float -> unorm8 conversion, is computed exactly (in double).
#include "deferred/depth_codec.h"

#include "dsr_error.h"

#include <algorithm>
#include <cmath>

namespace dsr {

namespace {
float store_channel(float c) {
    const double b = std::floor(std::clamp((double)c, 0.0, 1.0) * 255.0 + 0.5);
    return (float)(b / 255.0);
}
}  // namespace

glm::vec3 store_unorm8(glm::vec3 c) {
    return {store_channel(c.x), store_channel(c.y), store_channel(c.z)};
}

glm::vec3 pack_depth_literal(float f) {
    glm::vec3 color;
    f *= 256.0f;
    color.x = std::floor(f);
    f = (f - color.x) * 256.0f;
    color.y = std::floor(f);
    color.z = f - color.y;
    color.x *= 0.00390625f;  // Listing 11 line 08: color.xy *= 1.0/256
    color.y *= 0.00390625f;
    return color;
}

float unpack_depth_literal(glm::vec3 c) {
    const glm::vec3 byte_to_float(1.0f, 1.0f / 256.0f, 1.0f / (256.0f * 256.0f));
    return glm::dot(c, byte_to_float);
}

glm::vec3 pack_depth(float d) {
    d = std::clamp(d, 0.0f, 1.0f);
    // round(d*16777215) without forming d*16777215 in float (see the GLSL note in the header).
    const float m = d * 16777216.0f;
    const float fl = std::floor(m);
    float k = fl + std::floor((m - fl) - d + 0.5f);  // m - fl is GLSL's fract(m), exact
    const float b0 = std::floor(k / 65536.0f);
    k -= b0 * 65536.0f;
    const float b1 = std::floor(k / 256.0f);
    const float b2 = k - b1 * 256.0f;
    return glm::vec3(b0, b1, b2) / 255.0f;
}

float unpack_depth(glm::vec3 c) {
    const glm::vec3 b = glm::floor(c * 255.0f + 0.5f);
    return (b.x * 65536.0f + b.y * 256.0f + b.z) / 16777215.0f;
}

const char* encoding_name(DepthEncoding e) {
    switch (e) {
        case DepthEncoding::literal: return "literal";
        case DepthEncoding::corrected: return "corrected";
        case DepthEncoding::linear: return "linear";
        case DepthEncoding::log: return "log";
    }
    return "?";
}

DepthEncoding encoding_from_name(const std::string& name) {
    for (DepthEncoding e : {DepthEncoding::literal, DepthEncoding::corrected, DepthEncoding::linear, DepthEncoding::log})
        if (name == encoding_name(e)) return e;
    throw Error("expected a depth encoding (literal|corrected|linear|log), got '" + name + "'");
}

// Mirrors packed_encode in glsl120/depth_codec.glsl, operation for operation in float.
glm::vec3 encode_eye_z(DepthEncoding e, float z, float n, float f) {
    const float px = -f / (f - n), py = -f * n / (f - n);  // planes (§3.4.3)
    switch (e) {
        case DepthEncoding::literal: return pack_depth_literal((px * z + py) / -z);  // Listing 13 line 27
        case DepthEncoding::corrected: return pack_depth((px * z + py) / -z);
        case DepthEncoding::linear: return pack_depth((-z - n) / (f - n));
        case DepthEncoding::log: return pack_depth(std::log2(-z / n) / std::log2(f / n));
    }
    return glm::vec3(0);
}

// Mirrors packed_eye_z in glsl120/depth_codec.glsl.
float decode_eye_z(DepthEncoding e, glm::vec3 c, float n, float f) {
    const float px = -f / (f - n), py = -f * n / (f - n);
    switch (e) {
        case DepthEncoding::literal: return -py / std::min(px + unpack_depth_literal(c), py / f);
        case DepthEncoding::corrected: return -py / std::min(px + unpack_depth(c), py / f);
        case DepthEncoding::linear: return -(n + unpack_depth(c) * (f - n));
        case DepthEncoding::log: return -n * std::exp2(unpack_depth(c) * std::log2(f / n));
    }
    return 0;
}

}  // namespace dsr
