#version 120
// The depth hand-off (src/deferred/depth_handoff.cpp): the G-buffer's window depth written as
// gl_FragDepth into P-buffer 0's depth buffer. Depth texture: the value itself. Packed: the
// corrected and literal encodings hold the window depth (Listing 11), decoded directly; linear and
// log hold eye z, as the position paths' target does (POSITION_TARGET); mapped back to window
// depth through `planes` (§3.4.3).
// AMBIENT: the pass also writes, blending off, what the clear and Listing 15's ambient pass would
// have left in P-buffer 0 (the ambient pass folded into the hand-off: lighting_stage.cpp), from the
// stored diffuse target as the fixed-function modulate reads it, so the bytes are the pass's.
#include "depth_codec.glsl"

uniform sampler2D depth_map;  // unit 3: depth texture, packed target or position target
uniform vec2 planes;
uniform vec3 zrange;
// G-buffer texture coordinates per window pixel: each pixel reads its own texel from gl_FragCoord,
// as the light shaders do (they found interpolated coordinates a hair off on an NVIDIA GPU).
uniform vec2 uv_scale;
#ifdef AMBIENT
uniform sampler2D normal_map;   // unit 0: the G-buffer's normal target, alpha 1 or 0.5 on a surface, 0 where cleared
uniform sampler2D diffuse_map;  // unit 1: the G-buffer's diffuse target, alpha 1 on a surface
uniform vec3 ambient;           // Listing 15's ambient colour
uniform vec3 background;        // the colour the ambient pass clears P-buffer 0 to
#endif

void main()
{
    vec2 texcoord = gl_FragCoord.xy * uv_scale;
#if !defined(PACKED_DEPTH) && !defined(POSITION_TARGET)
    gl_FragDepth = texture2D(depth_map, texcoord).r;
#elif defined(ENC_LITERAL)
    gl_FragDepth = clamp(unpack_depth_literal(texture2D(depth_map, texcoord).rgb), 0.0, 1.0);
#elif defined(ENC_LINEAR) || defined(ENC_LOG) || defined(POSITION_TARGET)
    float z = surface_eye_z(depth_map, texcoord, planes, zrange);
    gl_FragDepth = clamp((planes.x * z + planes.y) / -z, 0.0, 1.0);
#else
    gl_FragDepth = unpack_depth(texture2D(depth_map, texcoord).rgb);
#endif
#ifdef AMBIENT
    // Listing 15: the modulate where the alpha test (alpha > 0.5) finds a surface, else the clear.
    // The surface is told by the normal target's alpha, where the diffuse target's alpha is 1: the
    // diffuse target's clear may be left out (GbufferClears, render_targets.h).
    vec4 surface = texture2D(diffuse_map, texcoord);
    gl_FragColor = texture2D(normal_map, texcoord).a > 0.25 ? vec4(ambient * surface.rgb, surface.a) : vec4(background, 1.0);
#else
    gl_FragColor = vec4(0.0);
#endif
}
