#version 120
// The final stage with high dynamic range (docs/hdr.md): P-buffer 0's linear colour scaled by
// the exposure, mapped by the operator into [0, 1], encoded for the output. Without any of them
// the final pass is the tutorial's fixed-function copy (§3.6), not this program.
//  TONEMAP_REINHARD  Reinhard et al. 2002, Eq. 3: L_d = L / (1 + L) on the luminance L, the
//                    colour scaled by L_d / L (hue and saturation kept)
//  TONEMAP_ACES      Narkowicz 2016's fit of the ACES filmic curve (RRT + ODT), per channel:
//                    x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14)
//  neither           the exposed colour clamped to [0, 1]
//  OUTPUT_SRGB       IEC 61966-2-1's encoding: 12.92 c below 0.0031308, else 1.055 c^(1/2.4) - 0.055
uniform sampler2D source;
uniform float exposure_scale;  // 2^E, or auto's 0.18 / the frame's geometric mean luminance

varying vec2 texcoord;

#include "luminance.glsl"

void main()
{
    vec3 c = max(texture2D(source, texcoord).rgb, vec3(0.0)) * exposure_scale;
#if defined(TONEMAP_REINHARD)
    float l = luminance(c);
    c = l > 0.0 ? c * (1.0 / (1.0 + l)) : vec3(0.0);
#elif defined(TONEMAP_ACES)
    c = (c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14);
#endif
    c = clamp(c, 0.0, 1.0);
#ifdef OUTPUT_SRGB
    vec3 lo = c * 12.92;
    vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    c = mix(hi, lo, vec3(lessThanEqual(c, vec3(0.0031308))));
#endif
    gl_FragColor = vec4(c, 1.0);
}
