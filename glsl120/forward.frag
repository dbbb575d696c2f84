#version 120
// Forward reference renderer, fragment stage (§2.4, Listings 2-4): Equation 1 per pixel from
// the interpolated eye-space position and normal: no G-buffer, no depth reconstruction, the
// material's shininess as given (not the G-buffer's 8-bit code). The accuracy reference the
// deferred renderer is measured against.
//   ambient  Factor_amb of Equation 6 on the pass that lays a surface down, 0 on additive passes
//   nlights  lights in this pass, <= MAX_LIGHTS (Listing 3: many per pass; Listing 4: one)
// Variants: NORMAL_MAP (tangent space, as glsl120/material.frag), LISTING2_LITERAL,
// MAX_LIGHTS n (set by the renderer from GL_MAX_FRAGMENT_UNIFORM_COMPONENTS), OPACITY (docs/forward.md:
// the transparent pass, src/deferred/transparent_pass.cpp, blends with alpha = the material's
// opacity; without it alpha is 1 as before). TWO_SIDED, VERTEX_COLOR, CUT_OUT: as glsl120/material.frag
// (shader_table.h surface_defines), so the references draw a model's surfaces as the G-buffer holds them.
// METAL_ROUGH_FORWARD (with METAL_ROUGH): a glTF metallic-roughness material, shaded by
// lighting.glsl's brdf_metal_rough as the light passes shade it (docs/metal_rough.md): `specular`
// = (metallic, roughness, occlusion strength) and speculartex the metallic-roughness map, as
// material.frag's METAL_ROUGH_MATERIAL reads them; ambient x base x occlusion plus the emissive
// colour (0 on additive passes) on the pass that lays the surface down.
#include "lighting.glsl"
#ifdef SHADOW
// SHADOW: the pass's light (one) scaled by its shadow map's lookup (the shadowed lights of the
// transparent pass and of the forward renderers' passes, docs/shadows.md).
#include "depth_codec.glsl"
#include "shadow.glsl"
#endif

#ifndef MAX_LIGHTS
#define MAX_LIGHTS 1
#endif

uniform sampler2D normaltex;    // unit 0
uniform sampler2D colortex;     // unit 1
uniform sampler2D speculartex;  // unit 2
uniform vec3 diffuse;
uniform vec3 specular;
uniform float shininess;        // M_shi of Equation 4, exactly
uniform float tile;
uniform vec3 ambient;
uniform int nlights;
#ifdef OPACITY
uniform float opacity;          // Material::opacity, in (0, 1)
#endif
#ifdef CUT_OUT
uniform float alpha_cutoff;     // Material::alpha_cutoff
#endif
#ifdef VERTEX_COLOR
varying vec4 vcolor;
#endif
#ifdef METAL_ROUGH_FORWARD
uniform sampler2D occlusiontex;  // unit 5
uniform sampler2D emissivetex;   // unit 6
uniform vec3 emissive;
#endif
// One light as five vec4s (lighting.glsl light_contribution; deferred/light_params.h).
uniform vec4 lightpos[MAX_LIGHTS];    // eye space, w = radius
uniform vec4 lightcolor[MAX_LIGHTS];  // S_diff = S_spec, w = type
uniform vec4 lightdir[MAX_LIGHTS];
uniform vec4 lightspot[MAX_LIGHTS];
uniform vec4 lightatt[MAX_LIGHTS];

varying vec2 texcoord;
varying vec3 vpos;
varying vec3 normal;
varying vec3 tangent;
varying vec3 binormal;

void main()
{
    vec2 txcoord = texcoord * tile;
#if defined(VERTEX_COLOR) || defined(CUT_OUT)
    vec4 colour = texture2D(colortex, txcoord);
#ifdef VERTEX_COLOR
    colour *= vcolor;
#endif
#ifdef CUT_OUT
    if (colour.a < alpha_cutoff) discard;
#endif
#endif
#ifdef NORMAL_MAP
    vec3 n = texture2D(normaltex, txcoord).xyz - 0.5;
    n = normalize(n.x * tangent + n.y * binormal + n.z * normal);
#else
    vec3 n = normalize(normal);
#endif
#ifdef TWO_SIDED
    if (!gl_FrontFacing) n = -n;
#endif
#if defined(VERTEX_COLOR) || defined(CUT_OUT)
    vec3 Mdiff = colour.rgb * diffuse;
#else
    vec3 Mdiff = texture2D(colortex, txcoord).rgb * diffuse;
#endif
#ifdef METAL_ROUGH_FORWARD
    vec4 mr = texture2D(speculartex, txcoord);
    float occlusion = 1.0 + specular.z * (texture2D(occlusiontex, txcoord).r - 1.0);  // glTF's strength mix
    vec3 Mspec = vec3(specular.x * mr.b, specular.y * mr.g, occlusion);
    float Mshi = -1.0;  // brdf()'s flag for glTF's BRDF
    vec3 c = ambient * Mdiff * occlusion + emissive * texture2D(emissivetex, txcoord).rgb;
#else
    vec3 Mspec = texture2D(speculartex, txcoord).rgb * specular;
    float Mshi = shininess;
    vec3 c = ambient * Mdiff;  // Equation 6 (zero on additive passes)
#endif
    vec3 v = view_vector(vpos);
    for (int i = 0; i < MAX_LIGHTS; ++i) {
        if (i >= nlights) break;
#ifdef SHADOW
        vec3 to_light = lightcolor[i].w > 1.5 ? -lightdir[i].xyz : normalize(lightpos[i].xyz - vpos);
        c += shadow_factor(vpos, n, to_light) *
             light_contribution(lightpos[i], lightcolor[i], lightdir[i], lightspot[i], lightatt[i], vpos, v, n, Mdiff,
                                Mspec, Mshi);
#else
        c += light_contribution(lightpos[i], lightcolor[i], lightdir[i], lightspot[i], lightatt[i], vpos, v, n, Mdiff,
                                Mspec, Mshi);
#endif
    }
#ifdef OPACITY
    gl_FragColor = vec4(c, opacity);
#else
    gl_FragColor = vec4(c, 1.0);
#endif
}
