#version 120
// Light geometry `screen` (src/deferred/light_geometry_screen.cpp): LearnOpenGL's deferred shading
// demo's lighting pass (5.8.1), a full-screen quad that evaluates every light at every pixel. The
// uniform arrays hold a batch of up to BATCH lights, LIGHTS of them set; the G-buffer is read once,
// then Listing 20's light term is summed over all of them with no depth test, no sphere test and
// no discard, and the sum is blended once: one rounding to 8 bits per pixel, as the demo's. The
// demo's pass starts from its ambient term; so does the first batch here (with_ambient, blending
// off: what the clear and Listing 15's ambient pass would have left, as light.frag's AMBIENT_FOLD).
// SHADOW (with SHADOW_SLOTS K): up to K shadowed lights a batch, as light_tiles.frag holds them.
// ATT_SHARED (with LIGHT_POINT_INVERSE): every light has the constants att_shared, read once
// instead of at each light's index in lightatt (the same values, so the same image).
#include "depth_codec.glsl"
#include "lighting.glsl"
#include "shadow.glsl"

uniform sampler2D normal_map;    // unit 0
uniform sampler2D diffuse_map;   // unit 1
uniform sampler2D specular_map;  // unit 2
uniform sampler2D depth_map;     // unit 3
#ifndef LIGHTS
#define LIGHTS BATCH  // the table's programs: a full batch; light_geometry_screen.cpp compiles the others
#endif
uniform vec4 lightpos[BATCH];    // lighting.glsl light_contribution's five vec4s per light
uniform vec4 lightcolor[BATCH];
uniform vec4 lightdir[BATCH];
uniform vec4 lightspot[BATCH];
uniform vec4 lightatt[BATCH];
#ifdef ATT_SHARED
uniform vec3 att_shared;  // every light's attenuation constants (light_tiles.frag's ATT_SHARED)
#define LIGHT_ATT(k) vec4(att_shared, 1.0)
#else
#define LIGHT_ATT(k) lightatt[k]
#endif
uniform vec2 planes;
uniform vec3 zrange;
uniform vec2 uv_scale;           // texture coordinates and (light.frag's) view ray from gl_FragCoord
uniform vec4 ray_map;
uniform float with_ambient;      // 1: the first batch, written over the background and ambient term
uniform vec3 ambient;            // Listing 15's ambient colour
uniform vec3 background;         // the colour P-buffer 0 is cleared to

void main()
{
    vec2 texcoord = gl_FragCoord.xy * uv_scale;
    vec3 pos = surface_eye_pos(depth_map, texcoord, vec3(gl_FragCoord.xy * ray_map.xy + ray_map.zw, -1.0), planes, zrange);
    vec3 normal = texture2D(normal_map, texcoord).xyz - 0.5;
    float len = length(normal);
    normal = len > 0.1 ? normal / len : vec3(0.0);  // background and degenerate normals: unlit (light.frag)
    vec4 surface = texture2D(diffuse_map, texcoord);
    vec3 diffuse = surface.rgb;
    vec4 specular = texture2D(specular_map, texcoord);
    float shininess = GBUFFER_SHININESS(specular.a);
    vec3 v = view_vector(pos);  // once, not per light
    vec3 c = vec3(0.0);
    for (int k = 0; k < LIGHTS; ++k) {  // the demo's loop, to its constant NR_LIGHTS
        vec3 t = light_contribution(lightpos[k], lightcolor[k], lightdir[k], lightspot[k], LIGHT_ATT(k), pos, v, normal,
                                    diffuse, specular.rgb, shininess);
#ifdef SHADOW
        float slot = lightspot[k].z;
        if (slot > -0.5) {
            vec3 to_light = lightcolor[k].w > 1.5 ? -lightdir[k].xyz : normalize(lightpos[k].xyz - pos);
            t *= shadow_factor(int(slot + 0.5), pos, normal, to_light);
        }
#endif
        c += t;
    }
    if (with_ambient > 0.5) {
        // The alpha test of Listing 15 finds a surface where diffuse alpha is set; told here by the
        // normal target's alpha, set on every surface too (light.frag's fold says why).
        bool on_surface = texture2D(normal_map, texcoord).a > 0.25;
        vec3 base = on_surface ? ambient * diffuse : background;
        gl_FragColor = vec4(base + c, (on_surface ? surface.a : 1.0) + 1.0);  // the additive blend's sum
    } else {
        gl_FragColor = vec4(c, 1.0);
    }
}
