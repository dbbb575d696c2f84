// The SSAO passes' one position fetch (docs/ssao.md): the eye-space position the G-buffer's depth at
// uv reconstructs to along the view ray (x, y, -1), exactly as light.frag does (Listings 19-20,
// §3.4.3; depth_codec.glsl surface_eye_z, so both --depth texture and --depth packed work).
// A G-buffer that stores eye positions swaps this function alone.
#include "depth_codec.glsl"

uniform sampler2D depth_map;  // the G-buffer's depth texture, or its packed target
uniform vec2 planes;          // §3.4.3: (-f/(f-n), -f*n/(f-n))
uniform vec3 zrange;          // (near, far, log2(far/near)) for the linear and log encodings

vec3 eye_position(vec2 uv, vec3 ray)
{
    float z = surface_eye_z(depth_map, uv, planes, zrange);
    return vec3(ray.xy / ray.z * z, z);
}
