#version 120
// Anti-alias pass (Listing 21, Equation 7): a blur factor from the squared differences
// between a pixel and its neighbours in the normal target and/or eye depth, then the final
// colour sampled at offsets scaled by that factor (no edge: no offset, no blur).
// Variants: SOURCE_NORMAL, SOURCE_DEPTH (both may be set), LISTING_KERNEL (Listing 21's
// table, which repeats (-1,1) and lacks (-1,-1), and sums 4 neighbours for the factor),
// FACTOR_ONLY (writes the factor as grey: Figure 8), PACKED_DEPTH / ENC_*, POSITION_TARGET.
#include "depth_codec.glsl"

uniform sampler2D normal_map;  // unit 0: G-buffer normal target
uniform sampler2D color_map;   // unit 1: P-buffer 0
uniform sampler2D depth_map;   // unit 2: depth texture, packed depth or position target
uniform vec2 pixel_size;
uniform float weight;
uniform vec2 planes;
uniform vec3 zrange;
uniform float depth_scale;
uniform vec4 uv_clamp;  // content texels' centres: (min, max); keeps taps off power-of-two padding

varying vec2 texcoord;

#ifdef LISTING_KERNEL
#define DELTA_0 vec2(-1.0, 1.0)
const int FACTOR_TAPS = 4;
#else
#define DELTA_0 vec2(-1.0, -1.0)
const int FACTOR_TAPS = 8;  // Equation 7 sums all 8 neighbours
#endif
#ifdef DSR_GLSL_ES
// GLSL ES 1.00 has no array constructors: the same table, filled at the top of main.
vec2 delta[8];
#define DELTA_INIT delta[0] = DELTA_0; delta[1] = vec2(1.0, -1.0); delta[2] = vec2(-1.0, 1.0); \
    delta[3] = vec2(1.0, 1.0); delta[4] = vec2(-1.0, 0.0); delta[5] = vec2(1.0, 0.0); delta[6] = vec2(0.0, -1.0); \
    delta[7] = vec2(0.0, 1.0);
#else
const vec2 delta[8] = vec2[8](DELTA_0, vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0),
                              vec2(-1.0, 0.0), vec2(1.0, 0.0), vec2(0.0, -1.0), vec2(0.0, 1.0));
#define DELTA_INIT
#endif

vec2 tap(vec2 uv)
{
    return clamp(uv, uv_clamp.xy, uv_clamp.zw);
}

float eye_z(vec2 uv)
{
    return surface_eye_z(depth_map, tap(uv), planes, zrange);
}

void main()
{
    DELTA_INIT
    float factor = 0.0;
#ifdef SOURCE_NORMAL
    vec4 tex = texture2D(normal_map, texcoord);
    for (int i = 0; i < FACTOR_TAPS; i++) {
        vec4 t = texture2D(normal_map, tap(texcoord + delta[i] * pixel_size)) - tex;
        factor += dot(t, t);
    }
#endif
#ifdef SOURCE_DEPTH
    // Relative eye-depth steps, so the factor does not depend on the scene's units.
    float zc = eye_z(texcoord);
    for (int i = 0; i < FACTOR_TAPS; i++) {
        float dz = (eye_z(texcoord + delta[i] * pixel_size) - zc) / zc * depth_scale;
        factor += dz * dz;
    }
#endif
#ifdef FACTOR_ONLY
    gl_FragColor = vec4(vec3(min(1.0, factor)), 1.0);
#else
    factor = min(1.0, factor) * weight;
    vec4 color = vec4(0.0);
    for (int i = 0; i < 8; i++)
        color += texture2D(color_map, tap(texcoord + delta[i] * pixel_size * factor));
    color += 2.0 * texture2D(color_map, texcoord);
    gl_FragColor = color / 10.0;
#endif
}
