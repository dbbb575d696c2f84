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
// SHADOW_SLOTS K: the batched light passes (light_tiles.frag, light_screen.frag), which shade up to
// K shadowed lights a draw: their maps on units 4 .. 4+K-1 (shadow_maps), the per-map uniforms as
// arrays indexed by the light's shadow slot, shadow_factor(slot, ...). GLSL 1.20 indexes a sampler
// array only with a constant, so shadow_compare(slot, ...) picks the sampler by an if-chain; the
// lookup itself (shadow_lookup) is one function for both forms, its map a sampler or a slot.
// SHADOW_ATLAS (with SHADOW_SLOTS): the batch's maps copied into one atlas (shadow_atlas.h) on unit 4,
// slot s's map at shadow_region[s]: one sampler, no chain (a CPU rasteriser runs every branch of
// it). Its regions lie at whole texels of a power-of-two atlas; the lookup finds the texels and
// weights in the map as the single-map lookup does and only then moves the texels to the region,
// (corner + texel + 0.5) / atlas exactly, so the result is the same to the bit on both paths.
#ifdef SHADOW
#ifndef SHADOW_TAPS
#define SHADOW_TAPS 1
#endif
#ifdef SHADOW_PACKED
#define SHADOW_SAMPLER sampler2D        // depth packed into RGB8
#else
#define SHADOW_SAMPLER sampler2DShadow  // depth texture, GL_COMPARE_R_TO_TEXTURE, GL_LEQUAL
#endif
#ifdef SHADOW_SLOTS
#ifdef SHADOW_ATLAS
uniform SHADOW_SAMPLER shadow_atlas;               // unit 4
uniform vec4 shadow_region[SHADOW_SLOTS];          // (corner x, y; atlas width, height) in texels
#else
uniform SHADOW_SAMPLER shadow_maps[SHADOW_SLOTS];  // units 4 .. 4+K-1
#endif
uniform vec4 shadow_view[4 * SHADOW_SLOTS];        // as below, slot s at [4s, 4s+3]
uniform vec4 shadow_proj[4 * SHADOW_SLOTS];
uniform vec3 shadow_depth[SHADOW_SLOTS];
uniform vec4 shadow_params[SHADOW_SLOTS];
uniform vec4 shadow_size[SHADOW_SLOTS];
#define SHADOW_MAP int  // shadow_lookup's map: a slot
#else
uniform SHADOW_SAMPLER shadow_map;  // unit 4
uniform vec4 shadow_view[4];  // eye space -> light space, by columns
uniform vec4 shadow_proj[4];  // light space -> the map's clip space (perspective, orthographic)
uniform vec3 shadow_depth;
uniform vec4 shadow_params;   // (bias, slope, texel.x, texel.y): scene.h LightShadow, shadow_math.h
uniform vec4 shadow_size;     // (kind: 0 perspective, 1 orthographic, 2 six faces; face texels; width; height)
#define SHADOW_MAP SHADOW_SAMPLER  // shadow_lookup's map: the sampler
#endif

#ifdef SHADOW_PACKED
// 1 where depth d is at most the texel's at texture coordinates uv (a texel centre).
float shadow_texel(sampler2D m, vec2 uv, float d)
{
    return d <= unpack_depth(texture2D(m, uv).rgb) ? 1.0 : 0.0;
}
#endif

// One comparison at texture coordinates uv of map m (size: its texels): the nearest texel, or its
// 2x2 weighted bilinearly.
float shadow_compare(SHADOW_SAMPLER m, vec2 size, vec2 uv, float d)
{
#ifdef SHADOW_PACKED
#ifdef SHADOW_HARD
    return shadow_texel(m, (floor(uv * size) + 0.5) / size, d);
#else
    vec2 t = uv * size - 0.5;
    vec2 i = floor(t);
    vec2 w = t - i;
    vec2 a = (i + 0.5) / size, b = (i + 1.5) / size;
    return mix(mix(shadow_texel(m, a, d), shadow_texel(m, vec2(b.x, a.y), d), w.x),
               mix(shadow_texel(m, vec2(a.x, b.y), d), shadow_texel(m, b, d), w.x), w.y);
#endif
#else
    return shadow2D(m, vec3(uv, d)).r;
#endif
}

#if defined(SHADOW_SLOTS) && defined(SHADOW_ATLAS)
// 1 where depth d is at most the atlas texel's at texture coordinates uv (a texel centre).
float shadow_atlas_texel(vec2 uv, float d)
{
#ifdef SHADOW_PACKED
    return shadow_texel(shadow_atlas, uv, d);
#else
    return shadow2D(shadow_atlas, vec3(uv, d)).r;  // GL_NEAREST: that texel's comparison
#endif
}
// The same through slot s's region of the atlas: the texels and weights found in the map (texel
// indices clamped to its edge, as GL_CLAMP_TO_EDGE does for a map of its own), then moved to the
// region. The depth texture's 2x2 too: in atlas coordinates the GL's own filter would see
// corner + uv * size rounded to fewer bits than uv * size, and weigh the texels differently.
float shadow_compare(int s, vec2 size, vec2 uv, float d)
{
    vec4 r = shadow_region[s];
#ifdef SHADOW_HARD
    return shadow_atlas_texel((r.xy + clamp(floor(uv * size), vec2(0.0), size - 1.0) + 0.5) / r.zw, d);
#else
    vec2 t = uv * size - 0.5;
    vec2 i = floor(t);
    vec2 w = t - i;
    vec2 a = (r.xy + clamp(i, vec2(0.0), size - 1.0) + 0.5) / r.zw;
    vec2 b = (r.xy + clamp(i + 1.0, vec2(0.0), size - 1.0) + 0.5) / r.zw;
    return mix(mix(shadow_atlas_texel(a, d), shadow_atlas_texel(vec2(b.x, a.y), d), w.x),
               mix(shadow_atlas_texel(vec2(a.x, b.y), d), shadow_atlas_texel(b, d), w.x), w.y);
#endif
}
#elif defined(SHADOW_SLOTS)
// The same through slot s's map.
#define SHADOW_CASE(k) if (s == k) return shadow_compare(shadow_maps[k], size, uv, d);
float shadow_compare(int s, vec2 size, vec2 uv, float d)
{
    SHADOW_CASE(0)
#if SHADOW_SLOTS > 1
    SHADOW_CASE(1)
#endif
#if SHADOW_SLOTS > 2
    SHADOW_CASE(2)
#endif
#if SHADOW_SLOTS > 3
    SHADOW_CASE(3)
#endif
#if SHADOW_SLOTS > 4
    SHADOW_CASE(4)
#endif
#if SHADOW_SLOTS > 5
    SHADOW_CASE(5)
#endif
#if SHADOW_SLOTS > 6
    SHADOW_CASE(6)
#endif
#if SHADOW_SLOTS > 7
    SHADOW_CASE(7)
#endif
    return 1.0;
}
#endif

// The fraction of the light reaching eye-space point p (unit normal n, unit l towards the light)
// through map m and its uniforms (view: eye -> light space; proj; depth; params; size, as above).
float shadow_lookup(SHADOW_MAP m, mat4 view, mat4 proj, vec3 depth, vec4 params, vec4 size, vec3 p, vec3 n, vec3 l)
{
    vec3 q = (view * vec4(p, 1.0)).xyz;
    vec3 a = abs(q);
    bool cube = size.x > 1.5;
    float axis = cube ? max(a.x, max(a.y, a.z)) : -q.z;
    float c = clamp(dot(n, l), 1e-6, 1.0);
    float tangent = min(sqrt(1.0 - c * c) / c, 8.0);  // shadow_math.h kMaxShadowTangent
    float texel = params.z + params.w * axis;
    float d = depth.x * length(q) + depth.y * -q.z + depth.z - params.x -
              params.y * texel * tangent * (depth.x + depth.y);
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
        vec4 cl = proj * vec4(q, 1.0);
        uv = cl.xy / cl.w * 0.5 + 0.5;
        if (cl.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))))
            return 1.0;  // off the map: nothing there casts
    }
    // Taps stay on their own view's texels (a face's neighbour in the texture is another face).
    float face_texel = 1.0 / size.y;
    float lit = 0.0;
    for (int j = 0; j < SHADOW_TAPS; ++j)
        for (int i = 0; i < SHADOW_TAPS; ++i) {
            vec2 o = vec2(float(i), float(j)) - float(SHADOW_TAPS - 1) * 0.5;
            vec2 t = clamp(uv + o * face_texel, 0.5 * face_texel, 1.0 - 0.5 * face_texel);
            lit += shadow_compare(m, size.zw, (tile + t) / tiles, d);
        }
    return lit / float(SHADOW_TAPS * SHADOW_TAPS);
}

#ifdef SHADOW_SLOTS
// Slot s's map: a batched pass's shadowed light.
float shadow_factor(int s, vec3 p, vec3 n, vec3 l)
{
    int v = 4 * s;
    return shadow_lookup(s, mat4(shadow_view[v], shadow_view[v + 1], shadow_view[v + 2], shadow_view[v + 3]),
                         mat4(shadow_proj[v], shadow_proj[v + 1], shadow_proj[v + 2], shadow_proj[v + 3]),
                         shadow_depth[s], shadow_params[s], shadow_size[s], p, n, l);
}
#else
// The one light's map (light.frag, forward.frag).
float shadow_factor(vec3 p, vec3 n, vec3 l)
{
    return shadow_lookup(shadow_map, mat4(shadow_view[0], shadow_view[1], shadow_view[2], shadow_view[3]),
                         mat4(shadow_proj[0], shadow_proj[1], shadow_proj[2], shadow_proj[3]), shadow_depth,
                         shadow_params, shadow_size, p, n, l);
}
#endif
#endif  // SHADOW
