#version 130
// Light geometry `tiles` with --tile-fetch vertex (src/deferred/light_geometry_tiles.cpp): a tile's
// LIGHTS lights, point lights of the linear law (LIGHT_POINT_ONLY) or of one attenuation
// (LIGHT_POINT_INVERSE with ATT_SHARED), come from light_tiles_flat.vert as flat varyings. The
// G-buffer is read once, then each light's term is added as light_tiles.frag adds it
// (tile_light.glsl: the same tests, the same rounding, so the same image), the terms written out
// in a row: a program for each count of lights, since a CPU rasteriser runs an `if` or a loop's
// `break` by masking lanes and would run every term a loop could reach. The sum is blended
// once; a pixel no light reaches is discarded.
#include "depth_codec.glsl"
#include "lighting.glsl"
#include "quantize.glsl"
#include "tile_light.glsl"
#ifndef LIGHTS
#define LIGHTS MAX_LIGHTS  // the table's programs; light_geometry_tiles.cpp builds one per count
#endif

uniform sampler2D normal_map;    // unit 0
uniform sampler2D diffuse_map;   // unit 1
uniform sampler2D specular_map;  // unit 2
uniform sampler2D depth_map;     // unit 3
uniform vec2 planes;
uniform vec3 zrange;
uniform vec2 uv_scale;  // texture coordinates and (light.frag's) view ray from gl_FragCoord
uniform vec4 ray_map;
#ifdef ATT_SHARED
uniform vec3 att_shared;  // the batch's attenuation constants (light_tiles.frag's ATT_SHARED)
#define LIGHT_ATT vec4(att_shared, 1.0)
#else
#define LIGHT_ATT vec4(0.0)  // the linear law reads none
#endif
flat in vec4 tile_lightpos[LIGHTS];
flat in vec4 tile_lightcolor[LIGHTS];

// A light's term at pos, where its tests let it in, added to c (as light_tiles.frag's shade()).
void add_light(vec4 lp, vec4 lc, vec3 pos, vec3 v, vec3 normal, vec3 diffuse, vec3 specular, float shininess,
               inout vec3 c, inout bool any)
{
    vec3 t;
    if (tile_light_term(lp, lc, vec4(0.0), vec4(0.0), LIGHT_ATT, pos, v, normal, diffuse, specular, shininess, t)) {
        c += tile_light_blended(t);
        any = true;
    }
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
    add_light(tile_lightpos[0], tile_lightcolor[0], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#if LIGHTS > 1
    add_light(tile_lightpos[1], tile_lightcolor[1], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
#if LIGHTS > 2
    add_light(tile_lightpos[2], tile_lightcolor[2], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
#if LIGHTS > 3
    add_light(tile_lightpos[3], tile_lightcolor[3], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
#if LIGHTS > 4
    add_light(tile_lightpos[4], tile_lightcolor[4], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
#if LIGHTS > 5
    add_light(tile_lightpos[5], tile_lightcolor[5], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
#if LIGHTS > 6
    add_light(tile_lightpos[6], tile_lightcolor[6], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
#if LIGHTS > 7
    add_light(tile_lightpos[7], tile_lightcolor[7], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
#if LIGHTS > 8
    add_light(tile_lightpos[8], tile_lightcolor[8], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
#if LIGHTS > 9
    add_light(tile_lightpos[9], tile_lightcolor[9], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
#if LIGHTS > 10
    add_light(tile_lightpos[10], tile_lightcolor[10], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
#if LIGHTS > 11
    add_light(tile_lightpos[11], tile_lightcolor[11], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
#if LIGHTS > 12
    add_light(tile_lightpos[12], tile_lightcolor[12], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
#if LIGHTS > 13
    add_light(tile_lightpos[13], tile_lightcolor[13], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
#if LIGHTS > 14
    add_light(tile_lightpos[14], tile_lightcolor[14], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
#if LIGHTS > 15
    add_light(tile_lightpos[15], tile_lightcolor[15], pos, v, normal, diffuse, specular.rgb, shininess, c, any);
#endif
    if (!any)
        discard;
#ifdef QUANTIZE_8BIT
    c /= 255.0;
#endif
    gl_FragColor = vec4(c, 1.0);
}
