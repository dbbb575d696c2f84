#version 120
// Screen-space ambient occlusion (docs/ssao.md; Vasilovici §5, after Crytek's depth comparison):
// SAMPLES points of a hemisphere about the surface normal (ssao_kernel.h), in eye space around the
// reconstructed position, each projected back to the screen and compared with the depth there.
// The kernel turns about the normal by one of a 4x4 tile of rotations (gl_FragCoord mod 4):
// banding traded for noise that ssao_blur.frag's 4x4 blur removes. Drawn with light.vert over
// a screen quad carrying the G-buffer texture coordinates and the view rays (Listing 19).
// Writes ao in [0, 1] (1: open) in rgb; the ambient pass multiplies Eq. 6's term by it.
#include "ssao_position.glsl"

uniform sampler2D normal_map;     // G-buffer normal target (unit 0); depth_map on unit 1
uniform vec3 kernel[SAMPLES];     // tangent space, z along the normal, |k| <= 1
uniform vec3 rotations[16];       // unit vectors in the tangent plane, row-major 4x4
uniform vec2 proj;                // the projection's (P[0][0], P[1][1]): eye to NDC
uniform vec2 gtex_scale;          // the G-buffer's content extent in texture coordinates
uniform vec2 gsize;               // the G-buffer's content size in pixels
uniform float radius;             // hemisphere radius, eye units
uniform float strength;
uniform float bias;               // eye units: depth differences below it do not occlude (no acne)

varying vec2 texcoord;
varying vec3 vpos;

void main()
{
    vec3 n = texture2D(normal_map, texcoord).xyz - 0.5;
    float len = length(n);
    if (len < 0.1) {  // background: nothing to occlude
        gl_FragColor = vec4(1.0);
        return;
    }
    n /= len;
    vec3 p = eye_position(texcoord, vpos);
    // Gram-Schmidt: the tile's rotation vector made tangent to n (Crytek / LearnOpenGL's TBN).
    vec2 cell = mod(floor(gl_FragCoord.xy), 4.0);
    vec3 r = rotations[int(cell.y * 4.0 + cell.x)];
    vec3 t = r - n * dot(r, n);
    if (dot(t, t) < 1e-4) t = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) - n * n.x : vec3(0.0, 1.0, 0.0) - n * n.y;
    t = normalize(t);
    mat3 tbn = mat3(t, cross(n, t), n);
    float occluded = 0.0;
    for (int i = 0; i < SAMPLES; ++i) {
        vec3 s = p + tbn * kernel[i] * radius;
        vec2 uv = vec2(proj.x * s.x, proj.y * s.y) / -s.z * 0.5 + 0.5;  // the sample's screen point
        if (s.z >= 0.0 || uv.x < 0.0 || uv.y < 0.0 || uv.x > 1.0 || uv.y > 1.0) continue;
        // The surface point q at the centre of the G-buffer pixel the sample falls in, along that
        // pixel's own view ray: at grazing angles a pixel spans a long stretch of depth, and the
        // sample's depth against its pixel's centre would make a flat floor occlude itself.
        uv = (floor(uv * gsize) + 0.5) / gsize;
        vec2 ndc = uv * 2.0 - 1.0;
        vec3 q = eye_position(uv * gtex_scale, vec3(ndc.x / proj.x, ndc.y / proj.y, -1.0));
        // Crytek's test (Vasilovici §5): the sample lies behind the surface seen there, and q
        // rises above p's tangent plane (points of p's own plane never occlude it). Range check:
        // a surface far in front of p (another object) does not darken it.
        float range = smoothstep(0.0, 1.0, radius / abs(p.z - q.z));
        occluded += (q.z >= s.z + bias && dot(q - p, n) > bias ? 1.0 : 0.0) * range;
    }
    float ao = clamp(1.0 - strength * occluded / float(SAMPLES), 0.0, 1.0);
    gl_FragColor = vec4(vec3(ao), 1.0);
}
