#version 120
// Lighting pass for one point light (Listing 20). Variants: PACKED_DEPTH (depth from the
// RGB8 target, Listing 18 / corrected codec), PACKED_LITERAL, LISTING2_LITERAL.
#include "depth_codec.glsl"
#include "lighting.glsl"

uniform sampler2D normal_map;    // unit 0
uniform sampler2D diffuse_map;   // unit 1
uniform sampler2D specular_map;  // unit 2
uniform sampler2D depth_map;     // unit 3
uniform vec4 lightpos;           // eye space, w = radius
uniform vec3 lightcolor;
uniform vec2 planes;             // §3.4.3: (-f/(f-n), -f*n/(f-n))

varying vec2 texcoord;
varying vec3 vpos;

void main()
{
#ifdef PACKED_DEPTH
#ifdef PACKED_LITERAL
    float depth = unpack_depth_literal(texture2D(depth_map, texcoord).rgb);
#else
    float depth = unpack_depth(texture2D(depth_map, texcoord).rgb);
#endif
#else
    float depth = texture2D(depth_map, texcoord).r;
#endif
    vec3 pos;
    pos.z = -planes.y / (planes.x + depth);
    pos.xy = vpos.xy / vpos.z * pos.z;

    vec3 normal = texture2D(normal_map, texcoord).xyz - 0.5;
    float len = length(normal);
    normal = len > 0.1 ? normal / len : vec3(0.0);  // background and degenerate normals: unlit

    vec3 diffuse = texture2D(diffuse_map, texcoord).rgb;
    vec4 specular = texture2D(specular_map, texcoord);
    vec3 c = lighting(lightcolor, lightpos.xyz, lightpos.w, pos, normal, diffuse, specular.rgb,
                      decode_shininess(specular.a));
    gl_FragColor = vec4(c, 1.0);
}
