#version 120
// Material pass fragment shader (Listings 12-13): fills the G-buffer (Figure 3).
//   target 0: normal  (n*0.5+0.5)
//   target 1: diffuse (map x colour), alpha 1 marks a covered pixel
//   target 2: specular (map x colour), alpha = log2(shininess)/11
//   target 3: depth packed into RGB8 (PACKED_DEPTH only; ENC_* picks the encoding), or the
//             eye-space position xyz, alpha 1 (POSITION_TARGET: an RGBA16F or RGBA32F target)
// Variants: NORMAL_MAP (tangent-space normal map; without it no tangent-space work),
// NO_SPECULAR (material without specular: no specular map read), PACKED_DEPTH, ENC_LITERAL,
// ENC_LINEAR, ENC_LOG, POSITION_TARGET (POSITION16: into half floats), TARGET_n (no MRT: write only target n to gl_FragData[0], §3.2),
// AMBIENT_TARGET n (P-buffer 0 as render target n: what Listing 15's ambient pass would write there).
// What a model brings (shader_table.h surface_defines): TWO_SIDED (a back face's normal, the
// normal map's included, flipped to face the camera), VERTEX_COLOR (the per-vertex colour
// multiplies the diffuse colour and the coverage), CUT_OUT (a fragment whose coverage, the
// diffuse map's alpha times the vertex colour's, is below alpha_cutoff is discarded).
// METAL_ROUGH_MATERIAL: a glTF metallic-roughness material (docs/guide.md, "The G-buffer"):
// target 0's alpha 0.5 marks the model, target 1 holds the base colour (map x factor), target 2
// (metallic, roughness, occlusion, 0) with `specular` = (metallic, roughness, occlusion strength)
// and speculartex the metallic-roughness map (green roughness, blue metallic, as glTF stores
// them); where the ambient term is written here, it is scaled by the occlusion and the emissive
// colour (emissive x emissivetex) is added. EMISSION_PASS (with METAL_ROUGH_MATERIAL; emission_pass.h):
// gl_FragData[0] = (emissive colour, occlusion as target 2 stores it), which P-buffer 0 blends as
// colour + P-buffer 0 x alpha, over what Listing 15's pass left there.
#include "depth_codec.glsl"
#include "quantize.glsl"

uniform sampler2D normaltex;    // unit 0
uniform sampler2D colortex;     // unit 1
uniform sampler2D speculartex;  // unit 2
uniform vec3 diffuse;
uniform vec3 specular;
uniform float shininess_code;
uniform vec2 planes;
uniform vec3 zrange;  // (near, far, log2(far/near))
uniform float tile;
#ifdef AMBIENT_TARGET
uniform vec3 ambient;  // Listing 15's ambient colour
#endif
#ifdef METAL_ROUGH_MATERIAL
uniform sampler2D occlusiontex;  // unit 3
uniform sampler2D emissivetex;   // unit 4
uniform vec3 emissive;
#endif
#ifdef CUT_OUT
uniform float alpha_cutoff;  // Material::alpha_cutoff
#endif
#ifdef VERTEX_COLOR
varying vec4 vcolor;
#endif

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
    n = n.x * tangent + n.y * binormal + n.z * normal;
#else
    vec3 n = normal;
#endif
#ifdef TWO_SIDED
    if (!gl_FrontFacing) n = -n;
#endif
    // normalize(0) is undefined (NaN on llvmpipe, stored as 0, which would decode as a normal):
    // a zero normal is written as the 0.5 grey Listing 20's len > 0.1 branch leaves unlit.
    float nl = length(n);
    n = nl > 0.0 ? n / nl : vec3(0.0);
    vec4 t0 = vec4(n * 0.5 + 0.5, 1.0);
#if defined(VERTEX_COLOR) || defined(CUT_OUT)
    vec4 t1 = vec4(colour.rgb * diffuse, 1.0);
#else
    vec4 t1 = vec4(texture2D(colortex, txcoord).rgb * diffuse, 1.0);
#endif
#if defined(METAL_ROUGH_MATERIAL)
    vec4 mr = texture2D(speculartex, txcoord);
    float occlusion = 1.0 + specular.z * (texture2D(occlusiontex, txcoord).r - 1.0);  // glTF's strength mix
    vec4 t2 = vec4(specular.x * mr.b, specular.y * mr.g, occlusion, 0.0);
    t0.a = 0.5;  // the material model's flag (lighting.glsl material_model)
#elif defined(NO_SPECULAR)
    vec4 t2 = vec4(0.0, 0.0, 0.0, shininess_code);
#else
    vec4 t2 = vec4(texture2D(speculartex, txcoord).rgb * specular, shininess_code);
#endif
#if defined(PACKED_DEPTH)
    vec4 t3 = vec4(packed_encode(vpos.z, planes, zrange), 1.0);  // Listings 11, 13
#elif defined(POSITION_TARGET) && defined(POSITION16)
    // Half floats end at 65504: a coordinate past it would be stored as infinity. Clamped, it
    // stays finite and its error is measured (docs/accuracy.md: fp16 past 6.5e4 eye units).
    vec4 t3 = vec4(clamp(vpos, -65504.0, 65504.0), 1.0);
#elif defined(POSITION_TARGET)
    vec4 t3 = vec4(vpos, 1.0);  // the eye-space position the light pass would rebuild
#endif
#if defined(EMISSION_PASS)
    // The occlusion's nearest 8-bit code, as target 2 holds it and the material pass's ambient target reads it.
    gl_FragData[0] = vec4(emissive * texture2D(emissivetex, txcoord).rgb, floor(clamp(t2.b, 0.0, 1.0) * 255.0 + 0.5) / 255.0);
#elif defined(TARGET_0)
    gl_FragData[0] = t0;
#elif defined(TARGET_1)
    gl_FragData[0] = t1;
#elif defined(TARGET_2)
    gl_FragData[0] = t2;
#elif defined(TARGET_3)
    gl_FragData[0] = t3;
#else
    gl_FragData[0] = t0;
    gl_FragData[1] = t1;
    gl_FragData[2] = t2;
#if defined(PACKED_DEPTH) || defined(POSITION_TARGET)
    gl_FragData[3] = t3;
#endif
#ifdef AMBIENT_TARGET
    // The ambient pass's fixed-function modulate (ambient x the diffuse target, alpha 1 x 1) on the
    // diffuse colour as the pass would read it from the RGBA8 target; P-buffer 0 then rounds the
    // product as it would have rounded the pass's.
    vec3 stored = clamp(t1.rgb, 0.0, 1.0);
#ifdef QUANTIZE_8BIT
    stored = texel8(stored);
#endif
#ifdef METAL_ROUGH_MATERIAL
    // Occlusion scales the ambient (indirect) term only; the emissive colour is added once, here.
    float occ = clamp(t2.b, 0.0, 1.0);
#ifdef QUANTIZE_8BIT
    occ = texel8(vec3(occ)).x;  // as target 2 stores it
#endif
    gl_FragData[AMBIENT_TARGET] = vec4(ambient * stored * occ + emissive * texture2D(emissivetex, txcoord).rgb, 1.0);
#else
    gl_FragData[AMBIENT_TARGET] = vec4(ambient * stored, 1.0);
#endif
#endif
#endif
}
