#version 120
// Lighting pass for one light (Listing 20), of any type (lighting.glsl light_contribution:
// point, spot, directional; Equation 2 or the attenuation law). Variants: LIGHT_POINT_ONLY (the
// tutorial's point lights only, lighting.glsl), LIGHT_POINT_INVERSE (point lights with the
// attenuation law only), PACKED_DEPTH (depth from the
// RGB8 target, Listing 18 / ENC_* encodings), POSITION_TARGET (the stored eye-space position), LISTING2_LITERAL, LIGHT_DEPTH_TEST (reject
// surfaces in front of or behind the light's sphere before shading), LIGHT_SPHERE_TEST (reject
// surface points outside the sphere), OUTPUT_POSITION (write the
// reconstructed eye-space position instead of light: accuracy measurements), BATCH (many lights'
// quads in one draw, each light's parameters from uniform arrays by the quad's slot), AMBIENT_FOLD (a
// full-screen light's pass that also writes the background and Listing 15's ambient term, blending
// off: lighting_stage.cpp; with QUANTIZE_8BIT each term rounded as its own pass would be), SHADOW
// (the light's shadow map scales its term: shadow.glsl).
#include "depth_codec.glsl"
#include "lighting.glsl"
#include "quantize.glsl"
#include "shadow.glsl"

uniform sampler2D normal_map;    // unit 0
uniform sampler2D diffuse_map;   // unit 1
uniform sampler2D specular_map;  // unit 2
uniform sampler2D depth_map;     // unit 3
#ifdef BATCH
// BATCH: many lights in one draw (pseudo-instancing): each light's quad carries its slot in the
// arrays (texture coordinate 2, light.vert), the same five vec4s a light as below.
uniform vec4 batch_pos[BATCH];
uniform vec4 batch_color[BATCH];
uniform vec4 batch_dir[BATCH];
uniform vec4 batch_spot[BATCH];
uniform vec4 batch_att[BATCH];
varying float slot;
#else
uniform vec4 lightpos;           // eye space, w = radius
uniform vec4 lightcolor;         // rgb, w = type (0 point, 1 spot, 2 directional)
uniform vec4 lightdir;           // eye-space unit direction, w = cos(half-angle)
uniform vec4 lightspot;          // (cos of the soft edge's inner angle, exponent, -, -)
uniform vec4 lightatt;           // (KC, KL, KQ, law): lighting.glsl
#endif
uniform vec2 planes;             // §3.4.3: (-f/(f-n), -f*n/(f-n))
uniform vec3 zrange;             // (near, far, log2(far/near)) for the linear and log encodings
uniform vec2 uv_scale;           // VOLUME: G-buffer texture coordinates per window pixel
uniform vec4 ray_map;            // view ray (x, y) = gl_FragCoord.xy * ray_map.xy + ray_map.zw, z = -1
#ifdef AMBIENT_FOLD
uniform vec3 ambient;            // Listing 15's ambient colour
uniform vec3 background;         // the colour P-buffer 0 was cleared to
#endif

#if !defined(VOLUME) && !defined(BATCH)
varying vec2 texcoord;           // the quad's (light.vert)
#endif

void main()
{
#ifdef BATCH
    int i = int(slot + 0.5);  // constant over the light's quad; rounded against interpolation's last bit
    vec4 lightpos = batch_pos[i];
    vec4 lightcolor = batch_color[i];
    vec4 lightdir = batch_dir[i];
    vec4 lightspot = batch_spot[i];
    vec4 lightatt = batch_att[i];
#endif
    // The pixel centre's view ray (Listing 19's corner rays, which are affine in window
    // coordinates, as a map of gl_FragCoord): what interpolating them across the drawn primitive
    // gives in exact arithmetic, but the same float result whatever draws the pixel. Interpolated
    // across each light's rectangle, tile or mesh, the reconstructed points differ in their last
    // bits between light geometries, and a GPU's 8-bit rounding of many lights a pixel turns that
    // into LSB between the geometries' images (docs/gpu.md, "Images on a GPU"). The texture
    // coordinates may be interpolated: at a pixel centre they pick the same nearest texel either
    // way, and computing them too costs llvmpipe (docs/light_loop_cpu.md).
#if defined(VOLUME) || defined(BATCH)
    vec2 texcoord = gl_FragCoord.xy * uv_scale;
#endif
    vec3 vpos = vec3(gl_FragCoord.xy * ray_map.xy + ray_map.zw, -1.0);
    // pos.z = -planes.y/(planes.x+depth), pos.xy along the view ray; or the stored position.
    vec3 pos = surface_eye_pos(depth_map, texcoord, vpos, planes, zrange);
#ifdef AMBIENT_FOLD
    // What the clear and the ambient pass leave (Listing 15: ambient x diffuse where the alpha test
    // finds a surface, else the background), and the light added to it in this one pass. A
    // rejected pixel is not discarded: it keeps that, as it would without the light.
    // A surface is told by the normal target's alpha (1 or 0.5 where written, 0 where cleared) as
    // the diffuse target's alpha 1 tells it, whose clear may be left out (render_targets.h GbufferClears).
    vec4 surface = texture2D(diffuse_map, texcoord);
    bool on_surface = texture2D(normal_map, texcoord).a > 0.25;
    vec3 base = on_surface ? ambient * surface.rgb : background;
#ifdef QUANTIZE_8BIT
    base = quantize8(base);  // as the clear and the ambient pass wrote it into RGBA8
#endif
    float base_alpha = on_surface ? surface.a : 1.0;
#define REJECT { gl_FragColor = vec4(base, base_alpha); return; }
#else
#define REJECT discard
#endif
#ifdef LIGHT_DEPTH_TEST
    // Beyond the tutorial: a surface outside the sphere's depth span [z-r, z+r] (background
    // included: it sits at the far plane) cannot be lit; reject it before any other work.
    // A spot's cone lies in the sphere about its apex; a directional light has no span.
#ifdef POINT_LIGHTS
    if (abs(pos.z - lightpos.z) > lightpos.w)
#else
    if (lightcolor.w < 1.5 && abs(pos.z - lightpos.z) > lightpos.w)
#endif
        REJECT;
#endif
#ifdef LIGHT_SPHERE_TEST
    // A point outside the sphere gets att = 0 (Equation 2): nothing to add, so no G-buffer reads.
    // A spot adds nothing on or outside its cone either (GL_SPOT_CUTOFF).
    // l as light_contribution takes it (light_tiles.frag says why).
    vec3 l = lightpos.xyz - pos;
#ifdef POINT_LIGHTS
    if (dot(l, l) >= lightpos.w * lightpos.w)
        REJECT;
#else
    if (lightcolor.w < 1.5 && dot(l, l) >= lightpos.w * lightpos.w)
        REJECT;
    if (lightcolor.w > 0.5 && lightcolor.w < 1.5 && -dot(l, lightdir.xyz) <= length(l) * lightdir.w)
        REJECT;
#endif
#endif

    vec3 normal = texture2D(normal_map, texcoord).xyz - 0.5;
    float len = length(normal);
    normal = len > 0.1 ? normal / len : vec3(0.0);  // background and degenerate normals: unlit

#ifdef OUTPUT_POSITION
    gl_FragColor = vec4(pos, len > 0.1 ? 1.0 : 0.0);
    return;
#endif
    vec3 diffuse = texture2D(diffuse_map, texcoord).rgb;
    vec4 specular = texture2D(specular_map, texcoord);
    vec3 c = light_contribution(lightpos, lightcolor, lightdir, lightspot, lightatt, pos, view_vector(pos), normal, diffuse,
                                specular.rgb, GBUFFER_SHININESS(specular.a));
#ifdef SHADOW
    vec3 to_light = lightcolor.w > 1.5 ? -lightdir.xyz : normalize(lightpos.xyz - pos);
    c *= shadow_factor(pos, normal, to_light);
#endif
#ifdef AMBIENT_FOLD
#ifdef QUANTIZE_8BIT
    c = quantize8(c);  // as the light's own additive pass would have been rounded
#endif
    gl_FragColor = vec4(base + c, base_alpha + 1.0);  // the additive blend's sum
#else
    gl_FragColor = vec4(c, 1.0);
#endif
}
