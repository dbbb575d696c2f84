// Equations 1-5 in eye space (Listing 2, corrected; docs/errata.md):
//  * v points from p to the viewer (Eq. 5); Listing 2 uses +normalize(p), which points away.
//  * h is built from the unit l (Eq. 5); Listing 2 adds the unnormalised l, so h ~ l.
// brdf() returns I_diff + I_spec for light colour Scolor arriving along l (from p towards the
// light, not normalised, dist = length(l)); the ambient term is the fixed-function pass (Eq. 6).
// v is view_vector(p), taken once per pixel by the caller: a shader that loops over lights
// (forward.frag, light_tiles.frag) would otherwise normalise the same vector for every light
// (llvmpipe does not hoist it; docs/light_loop_cpu.md, "Smaller choices in the shaders").
// VIEW_PER_LIGHT takes it from p per light instead: with v passed in, the NVIDIA compiler runs
// forward single-pass's general-light loop slower (docs/gpu.md, "Other stages on a GPU"), so the
// forward renderer asks for it on GPUs where its lights need the general shader.
#if defined(LIGHT_POINT_ONLY) || defined(LIGHT_POINT_INVERSE)
#define POINT_LIGHTS
#endif

vec3 view_vector(vec3 p)
{
    return -normalize(p);  // Equation 5: from p towards the viewer at the eye-space origin
}

#ifdef METAL_ROUGH
// glTF 2.0's metallic-roughness BRDF (the glTF 2.0 specification, Appendix B, as the Khronos glTF
// Sample Viewer's brdf.glsl writes it; docs/metal_rough.md), for unit l towards the light and
// unit v towards the viewer; returns f * Scolor * NdotL, the caller applies the attenuation:
//   D = a^2 / (pi ((N.H)^2 (a^2 - 1) + 1)^2),  a = roughness^2 (Trowbridge-Reitz / GGX)
//   V = 0.5 / (N.L sqrt((N.V)^2 (1 - a^2) + a^2) + N.V sqrt((N.L)^2 (1 - a^2) + a^2))  (height-correlated Smith)
//   F = F0 + (1 - F0) (1 - V.H)^5,  F0 = mix(0.04, base, metallic)  (Schlick)
//   f = (1 - F) c_diff / pi + F D V,  c_diff = mix(base, 0, metallic)
// Dot products clamped to [0, 1] as the sample viewer clamps them. Beyond the spec: roughness
// below kMinRoughness is raised to it, so a point light's highlight on a smooth surface stays a
// finite peak (a = 0 would make D a delta); analytic_reference.cpp does the same.
const float kPi = 3.14159265358979;
const float kMinRoughness = 0.03;
vec3 brdf_metal_rough(vec3 Scolor, vec3 l, vec3 v, vec3 n, vec3 base, float metallic, float roughness)
{
    vec3 hv = l + v;
    float hl = length(hv);
    vec3 h = hl > 1e-6 ? hv / hl : n;  // l opposite v: no highlight, no NaN (as brdf())
    float NdotL = clamp(dot(n, l), 0.0, 1.0);
    float NdotV = clamp(dot(n, v), 0.0, 1.0);
    float NdotH = clamp(dot(n, h), 0.0, 1.0);
    float VdotH = clamp(dot(v, h), 0.0, 1.0);
    float r = max(roughness, kMinRoughness);
    float a2 = r * r * r * r;  // alpha^2, alpha = roughness^2
    float dd = NdotH * NdotH * (a2 - 1.0) + 1.0;
    float D = a2 / (kPi * dd * dd);
    float ggx = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2) + NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
    float V = ggx > 0.0 ? 0.5 / ggx : 0.0;
    vec3 F0 = mix(vec3(0.04), base, metallic);
    float s = 1.0 - VdotH;
    float s2 = s * s;
    vec3 F = F0 + (1.0 - F0) * (s2 * s2 * s);
    vec3 cdiff = mix(base, vec3(0.0), metallic);
    return ((1.0 - F) * cdiff / kPi + F * (D * V)) * Scolor * NdotL;
}

// The material model of a G-buffer pixel: target 0's alpha is 1 for Phong (as the tutorial's
// material pass writes it) and 0.5 for metallic-roughness (docs/guide.md). A metallic-roughness
// pixel gets Mshi = -1, which brdf() takes as the flag (Phong's decoded shininess is >= 1); its
// Mdiff is the base colour, Mspec (metallic, roughness, occlusion).
float material_model(float normal_alpha, float shininess)
{
    return normal_alpha < 0.75 ? -1.0 : shininess;
}
#endif

vec3 brdf(vec3 Scolor, vec3 l, float dist, vec3 p, vec3 v, vec3 n, vec3 Mdiff, vec3 Mspec, float Mshi)
{
#ifdef METAL_ROUGH
    if (Mshi < 0.0)
        return brdf_metal_rough(Scolor, dist > 0.0 ? l / dist : n, v, n, Mdiff, Mspec.x, Mspec.y);
#endif
#ifdef LISTING2_LITERAL
    v = -v;  // Listing 2's normalize(p), exactly: negation rounds nothing
    vec3 h = normalize(v + l);
    l = l / max(dist, 1e-30);
#else
    l = dist > 0.0 ? l / dist : n;
#ifdef VIEW_PER_LIGHT
    v = -normalize(p);  // here, after l: first in brdf it ran slower (docs/gpu/run10/)
#endif
    vec3 hv = l + v;
    float hl = length(hv);
    vec3 h = hl > 1e-6 ? hv / hl : n;           // l opposite v: no highlight, no NaN
#endif
    vec3 Idiff = max(0.0, dot(l, n)) * Mdiff * Scolor;               // Equation 3
    vec3 Ispec = pow(max(0.0, dot(h, n)), Mshi) * Mspec * Scolor;    // Equation 4
    return Idiff + Ispec;
}

// The tutorial's point light: att * (I_diff + I_spec), Equation 1 with Equation 2's attenuation.
vec3 lighting(vec3 Scolor, vec3 Spos, float Sradius, vec3 p, vec3 v, vec3 n, vec3 Mdiff, vec3 Mspec, float Mshi)
{
    vec3 l = Spos - p;                          // from p towards the light
    float dist = length(l);
    float att = max(0.0, 1.0 - dist / Sradius); // Equation 2
    return att * brdf(Scolor, l, dist, p, v, n, Mdiff, Mspec, Mshi);
}

// One light of any type (point, spot, directional) at eye-space point p, seen along v = view_vector(p);
// scene/light_law.h is its CPU twin and documents the laws. Five vec4s per light, so multi-light shaders can hold them in uniform arrays:
//   Lpos   = (eye-space position, radius)               directional: unused
//   Lcolor = (S_diff = S_spec, type)                    type 0 point, 1 spot, 2 directional
//   Ldir   = (eye-space unit direction the light travels, cos of the half-angle)   spot, directional
//   Lspot  = (cos of the soft edge's inner angle, GL_SPOT_EXPONENT, -, -)          spot
//   Latt   = (KC, KL, KQ, law)   law 0: Equation 2, max(0, 1 - d / radius);
//                                law 1: 1 / (KC + KL d + KQ d^2) for d < radius, else 0
//                                law 2 (physical, KHR_lights_punctual): Latt.x = 1 / range^2
//                                (0: no range), max(min(1 - (d / range)^4, 1), 0) / d^2 for
//                                d < radius, else 0; Lspot = (lightAngleScale, lightAngleOffset)
// Spot: 0 on and outside the cone (GL_SPOT_CUTOFF), inside cos(theta)^E times
// smoothstep(cos half-angle, Lspot.x, cos theta); physical: the extension's
// clamp(cos theta * scale + offset, 0, 1)^2. Directional: l = -dir, no attenuation.
// With LIGHT_POINT_ONLY defined, the shader promises only point lights with Equation 2
// (Lcolor.w = 0, Latt.w = 0) and gets lighting() without the selection; with LIGHT_POINT_INVERSE,
// only point lights with the attenuation law (Lcolor.w = 0, Latt.w = 1), at the same cost.
// POINT_LIGHTS: either promise (the callers' depth and sphere tests need no type test).
// The attenuation law's factor at distance dist inside the radius: 1 / (KC + KL d + KQ d^2), in
// Horner's form (two multiply-adds). The cut-off at the radius is the caller's.
float inverse_law(vec4 Latt, float dist)
{
    return 1.0 / (Latt.x + dist * (Latt.y + Latt.z * dist));
}

vec3 light_contribution(vec4 Lpos, vec4 Lcolor, vec4 Ldir, vec4 Lspot, vec4 Latt,
                        vec3 p, vec3 v, vec3 n, vec3 Mdiff, vec3 Mspec, float Mshi)
{
#ifdef LIGHT_POINT_ONLY
    // Every light of the program is the tutorial's: Equation 2 alone, at the tutorial's cost.
    return lighting(Lcolor.rgb, Lpos.xyz, Lpos.w, p, v, n, Mdiff, Mspec, Mshi);
#elif defined(LIGHT_POINT_INVERSE)
    // Every light is a point light with the attenuation law: the general form's arithmetic for
    // that case alone (the same float operations, so the same image), without the selection.
    // With LIGHT_SPHERE_TEST the caller has left out every point with dot(l, l) >= radius^2
    // (light.frag, tile_light.glsl): the law's cut-off at the radius but for the square root's
    // last bit, so the cut-off's comparison and select go too. Without them, and with the
    // polynomial in Horner's form (inverse_law, the general form's too), the law costs little
    // more than the linear law's division, subtraction and max (docs/light_loop_cpu.md, "Smaller
    // choices in the shaders").
    vec3 l = Lpos.xyz - p;
    float dist = length(l);
    float f = inverse_law(Latt, dist);
#ifndef LIGHT_SPHERE_TEST
    f = dist < Lpos.w ? f : 0.0;  // the cut-off at the radius
#endif
    return f * brdf(Lcolor.rgb, l, dist, p, v, n, Mdiff, Mspec, Mshi);
#else
    // Selects, not branches: the type and law are uniform, but a software rasteriser pays for
    // control flow; every factor is computed and the light's own one chosen
    // (docs/light_loop_cpu.md, "Smaller choices in the shaders").
    bool directional = Lcolor.w > 1.5;
    vec3 l = directional ? -Ldir.xyz : Lpos.xyz - p;   // from p towards the light
    float dist = length(l);                            // 1 for a directional light
    float linear = max(0.0, 1.0 - dist / Lpos.w);      // Equation 2
    float inverse = dist < Lpos.w ? inverse_law(Latt, dist) : 0.0;
    float f = Latt.w > 0.5 ? inverse : linear;
    // Physical (law 2): (d / range)^4 as (d^2 / range^2)^2, so no range (Latt.x = 0) gives 0,
    // not infinity times 0, however far the pixel.
    float q = dist * dist * Latt.x;
    float window = clamp(1.0 - q * q, 0.0, 1.0);
    float physical = dist < Lpos.w ? window / max(dist * dist, 1e-30) : 0.0;
    f = Latt.w > 1.5 ? physical : f;
    // Spot: cos theta from the axis; GL_SPOT_CUTOFF, the soft edge, GL_SPOT_EXPONENT.
    float c = dot(-l, Ldir.xyz) / max(dist, 1e-30);
    float edge = c > Ldir.w ? smoothstep(Ldir.w, Lspot.x, c) : 0.0;
    float spot = edge * (Lspot.y > 0.0 ? pow(max(c, 1e-30), Lspot.y) : 1.0);
    float cone = clamp(c * Lspot.x + Lspot.y, 0.0, 1.0);
    spot = Latt.w > 1.5 ? cone * cone : spot;
    f = directional ? 1.0 : (Lcolor.w > 0.5 ? f * spot : f);
    return f * brdf(Lcolor.rgb, l, dist, p, v, n, Mdiff, Mspec, Mshi);
#endif
}

// Shininess in the specular target's 8-bit alpha (Listing 20 reads specular.w): stored as
// log2(M_shi)/11, so the alpha spans M_shi in [1, 2048] with ~3% steps (docs/errata.md).
float decode_shininess(float a)
{
    return exp2(a * 11.0);
}

// What the deferred light shaders pass as Mshi for the pixel at texcoord, from the specular
// target's alpha a: the decoded shininess, or with METAL_ROUGH the material model's flag
// (material_model above) from the normal target's alpha (normal_map, texcoord: the shader's).
#ifdef METAL_ROUGH
#define GBUFFER_SHININESS(code) material_model(texture2D(normal_map, texcoord).a, decode_shininess(code))
#else
#define GBUFFER_SHININESS(code) decode_shininess(code)
#endif
