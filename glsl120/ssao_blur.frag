#version 120
// Depth-aware blur of the SSAO buffer (docs/ssao.md): the 4x4 texels that cover one tile of
// ssao.frag's rotation pattern, each weighted by how close its surface's eye depth is to this
// pixel's, so occlusion does not bleed across silhouettes. Drawn with post.vert over the screen
// quad of the light passes: texcoord is the G-buffer's, to_ao maps it to the AO buffer's (their
// padding to powers of two may differ).
#include "ssao_position.glsl"

uniform sampler2D ao_map;      // unit 0 (the G-buffer depth on unit 1)
uniform vec2 texel;            // one AO texel in texture coordinates
uniform vec4 uv_clamp;         // the AO buffer's first and last texel centres
uniform vec2 to_ao;            // AO texture coordinates per G-buffer texture coordinate
uniform float depth_tolerance; // relative eye-depth difference at which a tap's weight reaches 0

varying vec2 texcoord;

void main()
{
    float zc = eye_position(texcoord, vec3(0.0, 0.0, -1.0)).z;
    vec2 centre = texcoord * to_ao;
    float sum = 0.0, weight = 0.0;
    for (int j = -2; j < 2; ++j)
        for (int i = -2; i < 2; ++i) {
            vec2 uv = clamp(centre + vec2(float(i), float(j)) * texel, uv_clamp.xy, uv_clamp.zw);
            float z = eye_position(uv / to_ao, vec3(0.0, 0.0, -1.0)).z;
            float w = max(0.0, 1.0 - abs(z - zc) / (depth_tolerance * -zc));
            sum += texture2D(ao_map, uv).r * w;
            weight += w;
        }
    float ao = weight > 0.0 ? sum / weight : texture2D(ao_map, centre).r;
    gl_FragColor = vec4(vec3(ao), 1.0);
}
