#version 120
// What a shadow map stores (shadow_math.h ShadowLayout): depth from the light as a fraction of the
// map's depth range, the distance over the radius (spot, point) or the depth across the
// orthographic box (directional), linear in both, so the bias means the same everywhere in the
// map. The depth-texture path writes it as the fragment's depth; SHADOW_PACKED packs it into
// RGB8 with the packed G-buffer's codec (depth_codec.glsl pack_depth, Listing 11 corrected).
// CUT_OUT: a cut-out surface casts only where it is drawn: a fragment whose coverage (the
// diffuse map's alpha, times the vertex colour's alpha with VERTEX_COLOR) is below alpha_cutoff
// is discarded, as the material pass discards it.
#include "depth_codec.glsl"

uniform vec3 shadow_depth;  // stored depth = x |q| + y (-q.z) + z
varying vec3 q;
#ifdef CUT_OUT
uniform sampler2D colortex;  // the material's diffuse map
uniform float tile;
uniform float alpha_cutoff;
varying vec2 texcoord;
#ifdef VERTEX_COLOR
varying float valpha;
#endif
#endif

void main()
{
#ifdef CUT_OUT
    float coverage = texture2D(colortex, texcoord * tile).a;
#ifdef VERTEX_COLOR
    coverage *= valpha;
#endif
    if (coverage < alpha_cutoff) discard;
#endif
    float d = clamp(shadow_depth.x * length(q) + shadow_depth.y * -q.z + shadow_depth.z, 0.0, 1.0);
    gl_FragDepth = d;
#ifdef SHADOW_PACKED
    gl_FragColor = vec4(pack_depth(d), 1.0);
#endif
}
