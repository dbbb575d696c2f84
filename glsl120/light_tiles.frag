#version 120
// Light geometry `tiles` (src/deferred/light_geometry_tiles.cpp): up to MAX_LIGHTS lights of any type
// per pass (§3.4.3's "multiple lights per pass"). The uniform arrays hold a batch of BATCH lights;
// the quad's vertices carry which of them shade this tile (`ids`: two slot indices a float, hi*256 +
// lo, 255 for none). The G-buffer is read once, then Listing 20's light loop runs over the tile's
// lights, with light.frag's per-light tests (LIGHT_DEPTH_TEST, LIGHT_SPHERE_TEST) as early returns
// from shade(); the sum is blended once. A pixel no light reaches is discarded (nothing to add; light_fragments
// counts the rest). SHADOW (with SHADOW_SLOTS K): up to K of the batch's lights are shadowed, each
// light's slot among the batch's maps in lightspot.z (-1: none), its term scaled by shadow.glsl's
// lookup as light.frag's SHADOW form scales it (SHADOW_ATLAS: the batch's maps in one atlas).
// ATT_SHARED (with LIGHT_POINT_INVERSE): every light of the batch has the attenuation constants
// att_shared, read once instead of lane by lane from lightatt (the same values, so the same image).
#include "depth_codec.glsl"
#include "lighting.glsl"
#include "quantize.glsl"
#include "shadow.glsl"
#include "tile_light.glsl"

uniform sampler2D normal_map;    // unit 0
uniform sampler2D diffuse_map;   // unit 1
uniform sampler2D specular_map;  // unit 2
uniform sampler2D depth_map;     // unit 3
uniform vec4 lightpos[BATCH];    // lighting.glsl light_contribution's five vec4s per light
uniform vec4 lightcolor[BATCH];
uniform vec4 lightdir[BATCH];
uniform vec4 lightspot[BATCH];
uniform vec4 lightatt[BATCH];
#ifdef ATT_SHARED
uniform vec3 att_shared;
#define LIGHT_ATT(i) vec4(att_shared, 1.0)
#else
#define LIGHT_ATT(i) lightatt[i]
#endif
uniform vec2 planes;
uniform vec3 zrange;
uniform vec2 uv_scale;  // texture coordinates and (light.frag's) view ray from gl_FragCoord
uniform vec4 ray_map;
#ifdef ID_VECS
varying vec4 ids[ID_VECS];  // --tile-plan lists: this quad's light slots
#else
uniform int light_count;    // --tile-plan groups: the draw's group, slots 0 .. light_count-1
#endif

// Light slot i of the batch at surface point pos: its term (tile_light.glsl), as its own pass
// would blend it, added to c.
void shade(int i, vec3 pos, vec3 v, vec3 normal, vec3 diffuse, vec4 specular, float shininess, inout vec3 c, inout bool any)
{
    vec3 t;
    if (!tile_light_term(lightpos[i], lightcolor[i], lightdir[i], lightspot[i], LIGHT_ATT(i), pos, v, normal, diffuse,
                         specular.rgb, shininess, t))
        return;
#ifdef SHADOW
    float slot = lightspot[i].z;
    if (slot > -0.5) {
        vec3 to_light = lightcolor[i].w > 1.5 ? -lightdir[i].xyz : normalize(lightpos[i].xyz - pos);  // light.frag's
        t *= shadow_factor(int(slot + 0.5), pos, normal, to_light);
    }
#endif
    c += tile_light_blended(t);
    any = true;
}

void main()
{
    vec2 texcoord = gl_FragCoord.xy * uv_scale;
    vec3 pos = surface_eye_pos(depth_map, texcoord, vec3(gl_FragCoord.xy * ray_map.xy + ray_map.zw, -1.0), planes, zrange);
    vec3 normal = texture2D(normal_map, texcoord).xyz - 0.5;
    float len = length(normal);
    if (len <= 0.1)
        discard;  // background and degenerate normals: unlit
    normal /= len;
    vec3 diffuse = texture2D(diffuse_map, texcoord).rgb;
    vec4 specular = texture2D(specular_map, texcoord);
    float shininess = GBUFFER_SHININESS(specular.a);
    vec3 v = view_vector(pos);  // once, not per light
    vec3 c = vec3(0.0);
    bool any = false;
#ifdef ID_VECS
    // Two slots a float, decoded once per pair: one iteration per light (decoding each slot in its
    // own iteration) is far slower on llvmpipe. The pairs pass through q0..q3, shifted one float an
    // iteration, so each is read from q0.x: indexing the varying array with the loop counter
    // (ids[k / 4][k % 4]) costs llvmpipe an indexed load per iteration (docs/light_loop_cpu.md,
    // "Smaller choices in the shaders"). 65535 is an empty pair (hi = 255).
    vec4 q0 = ids[0];
#if ID_VECS > 1
    vec4 q1 = ids[1];
#else
    vec4 q1 = vec4(65535.0);
#endif
#if ID_VECS > 2
    vec4 q2 = ids[2];
#else
    vec4 q2 = vec4(65535.0);
#endif
#if ID_VECS > 3
    vec4 q3 = ids[3];
#else
    vec4 q3 = vec4(65535.0);
#endif
    // A discarded lane (the background) leaves the loop at once: llvmpipe (Mesa 22.3) runs a lane
    // group on past a discard, so the loop would go on until its last slot for groups no pixel of
    // which is lit (docs/light_loop_cpu.md, "How llvmpipe runs a fragment shader").
    // The loop is a do-while whose test, at the end of an iteration, looks at the next pair: a CPU
    // rasteriser runs an `if` or a `break` by masking lanes, not by jumping, and leaves a loop only
    // at the end of an iteration, so a for loop's iteration that finds the empty pair still ran
    // both shade() calls with no lane on (every list of an even length paid two wasted terms);
    // docs/light_loop_cpu.md, "How llvmpipe runs a fragment shader".
    float pair = len <= 0.1 ? 65535.0 : floor(q0.x + 0.5);
    int k = 0;
    do {
        q0 = vec4(q0.yzw, q1.x);
        q1 = vec4(q1.yzw, q2.x);
        q2 = vec4(q2.yzw, q3.x);
        q3 = vec4(q3.yzw, 65535.0);
        float hi = floor(pair / 256.0);
        if (hi > 254.5)
            break;  // an empty list: a lane of the background
        shade(int(hi), pos, v, normal, diffuse, specular, shininess, c, any);
        float lo = pair - 256.0 * hi;
        if (lo > 254.5)
            break;  // an odd list's end: its lo term runs masked, once
        shade(int(lo), pos, v, normal, diffuse, specular, shininess, c, any);
        pair = floor(q0.x + 0.5);
        ++k;
    } while (k < (MAX_LIGHTS + 1) / 2 && pair < 65279.5);
#else
    int count = len <= 0.1 ? 0 : light_count;  // a discarded lane leaves the loop at once (above)
    for (int k = 0; k < MAX_LIGHTS; ++k) {
        if (k >= count)
            break;
        shade(k, pos, v, normal, diffuse, specular, shininess, c, any);
    }
#endif
    if (!any)
        discard;
#ifdef QUANTIZE_8BIT
    c /= 255.0;
#endif
    gl_FragColor = vec4(c, 1.0);
}
