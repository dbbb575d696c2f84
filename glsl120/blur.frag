#version 120
// Bloom blur (Listing 22): NUMPOINTS taps along one axis; the offsets carry the direction,
// so the same shader serves the horizontal and the vertical pass (§3.5.2).
// Listing 22 sums dot(t,t): grey, and after two passes a 4th power of the colour. dsr keeps
// colour: the first pass (SELECT) weights each tap by its mean squared intensity dot(t,t)/3,
// which selects "regions with intense colors" (a contrast stretch), and the second pass is a
// plain average. LISTING reproduces the listing in both passes (docs/errata.md).
// SELECT_THRESHOLD (float accumulation, docs/hdr.md): the first pass keeps the part of each tap
// whose luminance lies above `threshold`, t x max(L - T, 0) / L: light beyond the display's range,
// not the clipped colour.
#ifndef NUMPOINTS
#define NUMPOINTS 7
#endif
uniform sampler2D source;
uniform vec2 offset[NUMPOINTS];
uniform vec4 uv_clamp;  // content texels' centres: (min, max); keeps taps off power-of-two padding

varying vec2 texcoord;
#ifdef SELECT_THRESHOLD
#include "luminance.glsl"
uniform float threshold;
#endif

void main()
{
    vec3 sum = vec3(0.0);
    for (int i = 0; i < NUMPOINTS; i++) {
        vec3 t = texture2D(source, clamp(texcoord + offset[i], uv_clamp.xy, uv_clamp.zw)).rgb;
#if defined(LISTING)
        sum += vec3(dot(t, t));
#elif defined(SELECT_THRESHOLD)
        float l = luminance(t);
        sum += l > threshold ? t * ((l - threshold) / l) : vec3(0.0);
#elif defined(SELECT)
        sum += t * (dot(t, t) / 3.0);
#else
        sum += t;
#endif
    }
    gl_FragColor = vec4(sum / float(NUMPOINTS), 1.0);
}
