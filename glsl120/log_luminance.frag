#version 120
// P-buffer 0 reduced for --exposure auto (docs/hdr.md): each texel of a small float target the
// mean of log2(delta + L) over TAPS x TAPS samples of its block of P-buffer 0 (Reinhard et al.
// 2002, Eq. 1: the log-average luminance, whose mean the CPU takes over the reduced copy; no
// full read-back). Also in green: the block's largest L, for the viewer's histogram range.
#ifndef TAPS
#define TAPS 4
#endif
#include "luminance.glsl"

uniform sampler2D source;
uniform vec2 block;      // a destination texel's extent in source texture coordinates
uniform vec4 uv_clamp;   // content texels' centres: (min, max)

varying vec2 texcoord;   // the block's centre

void main()
{
    float sum = 0.0, top = 0.0;
    for (int j = 0; j < TAPS; ++j)
        for (int i = 0; i < TAPS; ++i) {
            vec2 uv = clamp(texcoord + block * ((vec2(float(i), float(j)) + 0.5) / float(TAPS) - 0.5), uv_clamp.xy, uv_clamp.zw);
            float l = max(luminance(texture2D(source, uv).rgb), 0.0);
            sum += log2(1e-4 + l);
            top = max(top, l);
        }
    gl_FragColor = vec4(sum / float(TAPS * TAPS), top, 0.0, 1.0);
}
