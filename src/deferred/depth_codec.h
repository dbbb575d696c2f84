// CPU twins of the packed-depth codec (Listings 11 and 18) and of what an RGB8 render target
// does to a colour, so the packed path's error can be checked without GL.
//
// Listing 11 writes bytes as k/256, but an 8-bit target stores round(c*255) and gives back
// byte/255 (docs/errata.md #11): about half of the first two bytes come back one off, an error up to ~2e-3
// in depth. pack_depth writes byte/255 instead and round-trips every 24-bit code exactly; its
// code k = round(d*(2^24-1)) is the one a 24-bit depth texture holds, and unpack_depth returns
// k/(2^24-1) as GL does for that texture, so the packed and depth-texture paths agree.
//
// Every function below mirrors the GLSL 1.20 twin line for line in float arithmetic (integers
// below 2^24 are exact in float). The GLSL, for glsl120/depth_codec.glsl:
//
//   // Corrected packing: bytes of k = round(d * 16777215) written as byte/255.
//   vec3 pack_depth(float d)
//   {
//       d = clamp(d, 0.0, 1.0);
//       // Not floor(d*16777215.0 + 0.5): above 2^23 the float ulp is 1, so the product is
//       // already rounded and "+ 0.5" ties to even, which is off by one for half the codes.
//       // d*2^24 is exact (power of two) and d*16777215 = floor(m) + (fract(m) - d).
//       float m = d * 16777216.0;
//       float k = floor(m) + floor(fract(m) - d + 0.5);
//       float b0 = floor(k / 65536.0);
//       k -= b0 * 65536.0;
//       float b1 = floor(k / 256.0);
//       float b2 = k - b1 * 256.0;
//       return vec3(b0, b1, b2) / 255.0;
//   }
//
//   float unpack_depth(vec3 c)
//   {
//       vec3 b = floor(c * 255.0 + 0.5);  // back to the stored bytes
//       return (b.x * 65536.0 + b.y * 256.0 + b.z) / 16777215.0;
//   }
//
//   // Listing 11 (float_to_color) as printed.
//   vec3 pack_depth_literal(float f)
//   {
//       vec3 color;
//       f *= 256.0;
//       color.x = floor(f);
//       f = (f - color.x) * 256.0;
//       color.y = floor(f);
//       color.z = f - color.y;
//       color.xy *= 0.00390625;  // *= 1.0/256
//       return color;
//   }
//
//   // Listing 18 (color_to_float) as printed.
//   float unpack_depth_literal(vec3 c)
//   {
//       const vec3 byte_to_float = vec3(1.0, 1.0 / 256.0, 1.0 / (256.0 * 256.0));
//       return dot(c, byte_to_float);
//   }
#pragma once
#include <string>

#include <glm/glm.hpp>

namespace dsr {

// What an RGB8 (unsigned normalised) target keeps of a colour: round(clamp(c,0,1)*255)/255.
glm::vec3 store_unorm8(glm::vec3 c);

// Listing 11 exactly as written (bytes as k/256, third channel the raw remainder in [0,1)).
glm::vec3 pack_depth_literal(float d);
// Listing 18 exactly: dot(c, (1, 1/256, 1/65536)).
float unpack_depth_literal(glm::vec3 c);

// Corrected base-256 packing of k = round(clamp(d,0,1) * 16777215) as (b0, b1, b2)/255; an RGB8
// target keeps it exactly.
glm::vec3 pack_depth(float d);
// Rounds each channel to its byte and returns k / 16777215.
float unpack_depth(glm::vec3 c);

// What the packed target holds (--depth-encoding). literal and corrected pack the window
// depth (Listing 13's d); linear packs (-z-n)/(f-n) and log packs log2(-z/n)/log2(f/n), both with
// the corrected 24-bit packing. CPU twins of glsl120/depth_codec.glsl's packed_encode /
// packed_eye_z, in float like the shader.
enum class DepthEncoding { literal, corrected, linear, log };
const char* encoding_name(DepthEncoding e);
DepthEncoding encoding_from_name(const std::string& name);  // throws dsr::Error listing the names

// z: eye-space z (< 0). Returns the colour written to the RGB8 target (before storage).
glm::vec3 encode_eye_z(DepthEncoding e, float z, float near_plane, float far_plane);
// c: the colour read back from the RGB8 target. Returns eye-space z.
float decode_eye_z(DepthEncoding e, glm::vec3 c, float near_plane, float far_plane);

}  // namespace dsr
