// The shadow lookup every shadowed light pass makes (compiled in with SHADOW only, so programs
// without shadows are unchanged). One light's map (shadow_stage.h), its layout and formulas as in
// src/deferred/shadow_math.h, which is the CPU twin the tests check:
//   q = shadow_view * p           the eye-space point in the light's space
//   stored depth = shadow_depth.x |q| + shadow_depth.y (-q.z) + shadow_depth.z
//   lit where that, less the bias, is at most the map's depth (ARB_shadow's GL_LEQUAL)
// The depth-texture path compares in the texture unit (shadow2D; GL_LINEAR filters the 2x2
// comparisons bilinearly where the GL does); SHADOW_PACKED reads the RGB8 map through
// depth_codec.glsl's unpack_depth and compares here, the same four texels with the same weights.
// SHADOW_HARD: the nearest texel alone. SHADOW_TAPS N: N x N of those lookups a texel apart, averaged.
#ifdef SHADOW
#ifndef SHADOW_TAPS
#define SHADOW_TAPS 1
#endif
#ifdef SHADOW_PACKED
uniform sampler2D shadow_map;        // unit 4: depth packed into RGB8
#else
uniform sampler2DShadow shadow_map;  // unit 4: depth texture, GL_COMPARE_R_TO_TEXTURE, GL_LEQUAL
#endif
uniform vec4 shadow_view[4];  // eye space -> light space, by columns
uniform vec4 shadow_proj[4];  // light space -> the map's clip space (perspective, orthographic)
uniform vec3 shadow_depth;
uniform vec4 shadow_params;   // (bias, slope, texel.x, texel.y): scene.h LightShadow, shadow_math.h
uniform vec4 shadow_size;     // (kind: 0 perspective, 1 orthographic, 2 six faces; face texels; width; height)

#ifdef SHADOW_PACKED
// 1 where depth d is at most the texel's at texture coordinates uv (a texel centre).
float shadow_texel(vec2 uv, float d)
{
    return d <= unpack_depth(texture2D(shadow_map, uv).rgb) ? 1.0 : 0.0;
}
#endif

// One comparison at texture coordinates uv: the nearest texel, or its 2x2 weighted bilinearly.
float shadow_compare(vec2 uv, float d)
{
#ifdef SHADOW_PACKED
    vec2 size = shadow_size.zw;
#ifdef SHADOW_HARD
    return shadow_texel((floor(uv * size) + 0.5) / size, d);
#else
    vec2 t = uv * size - 0.5;
    vec2 i = floor(t);
    vec2 w = t - i;
    vec2 a = (i + 0.5) / size, b = (i + 1.5) / size;
    return mix(mix(shadow_texel(a, d), shadow_texel(vec2(b.x, a.y), d), w.x),
               mix(shadow_texel(vec2(a.x, b.y), d), shadow_texel(b, d), w.x), w.y);
#endif
#else
    return shadow2D(shadow_map, vec3(uv, d)).r;
#endif
}

// The fraction of the light reaching eye-space point p (unit normal n, unit l towards the light).
float shadow_factor(vec3 p, vec3 n, vec3 l)
{
    vec3 q = (mat4(shadow_view[0], shadow_view[1], shadow_view[2], shadow_view[3]) * vec4(p, 1.0)).xyz;
    vec3 a = abs(q);
    bool cube = shadow_size.x > 1.5;
    float axis = cube ? max(a.x, max(a.y, a.z)) : -q.z;
    float c = clamp(dot(n, l), 1e-6, 1.0);
    float tangent = min(sqrt(1.0 - c * c) / c, 8.0);  // shadow_math.h kMaxShadowTangent
    float texel = shadow_params.z + shadow_params.w * axis;
    float d = shadow_depth.x * length(q) + shadow_depth.y * -q.z + shadow_depth.z - shadow_params.x -
              shadow_params.y * texel * tangent * (shadow_depth.x + shadow_depth.y);
    vec2 uv;        // on the view's own map, [0, 1]
    vec2 tile = vec2(0.0), tiles = vec2(1.0);  // a cube's face: its place among the 3 x 2
    if (cube) {
        // shadow_math.cpp cube_face / cube_face_uv: the face of the largest |q_i|, ties to the lower.
        vec3 f, up = vec3(0.0, 1.0, 0.0);
        float face;
        if (a.x >= a.y && a.x >= a.z) {
            face = q.x >= 0.0 ? 0.0 : 1.0;
            f = vec3(q.x >= 0.0 ? 1.0 : -1.0, 0.0, 0.0);
        } else if (a.y >= a.z) {
            face = q.y >= 0.0 ? 2.0 : 3.0;
            f = vec3(0.0, q.y >= 0.0 ? 1.0 : -1.0, 0.0);
            up = vec3(0.0, 0.0, 1.0);
        } else {
            face = q.z >= 0.0 ? 4.0 : 5.0;
            f = vec3(0.0, 0.0, q.z >= 0.0 ? 1.0 : -1.0);
        }
        vec3 s = normalize(cross(f, up));
        vec3 u = cross(s, f);
        uv = vec2(dot(q, s), dot(q, u)) / dot(q, f) * 0.5 + 0.5;
        tile = vec2(mod(face, 3.0), floor(face / 3.0));
        tiles = vec2(3.0, 2.0);
    } else {
        vec4 cl = mat4(shadow_proj[0], shadow_proj[1], shadow_proj[2], shadow_proj[3]) * vec4(q, 1.0);
        uv = cl.xy / cl.w * 0.5 + 0.5;
        if (cl.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))))
            return 1.0;  // off the map: nothing there casts
    }
    // Taps stay on their own view's texels (a face's neighbour in the texture is another face).
    float face_texel = 1.0 / shadow_size.y;
    float lit = 0.0;
    for (int j = 0; j < SHADOW_TAPS; ++j)
        for (int i = 0; i < SHADOW_TAPS; ++i) {
            vec2 o = vec2(float(i), float(j)) - float(SHADOW_TAPS - 1) * 0.5;
            vec2 t = clamp(uv + o * face_texel, 0.5 * face_texel, 1.0 - 0.5 * face_texel);
            lit += shadow_compare((tile + t) / tiles, d);
        }
    return lit / float(SHADOW_TAPS * SHADOW_TAPS);
}
#endif  // SHADOW
