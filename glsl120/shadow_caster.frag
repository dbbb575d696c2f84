#version 120
// What a shadow map stores (shadow_math.h ShadowLayout): depth from the light as a fraction of the
// map's depth range, the distance over the radius (spot, point) or the depth across the
// orthographic box (directional), linear in both, so the bias means the same everywhere in the
// map. The depth-texture path writes it as the fragment's depth; SHADOW_PACKED packs it into
// RGB8 with the packed G-buffer's codec (depth_codec.glsl pack_depth, Listing 11 corrected).
#include "depth_codec.glsl"

uniform vec3 shadow_depth;  // stored depth = x |q| + y (-q.z) + z
varying vec3 q;

void main()
{
    float d = clamp(shadow_depth.x * length(q) + shadow_depth.y * -q.z + shadow_depth.z, 0.0, 1.0);
    gl_FragDepth = d;
#ifdef SHADOW_PACKED
    gl_FragColor = vec4(pack_depth(d), 1.0);
#endif
}
