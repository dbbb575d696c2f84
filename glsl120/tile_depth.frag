#version 120
// The tiles light geometry's depth culling (src/deferred/tile_depth.cpp): fragment (x, y) writes the
// least and greatest eye z over the TILE_SIZE pixels of window row y in tile column x, of the
// surfaces the light shader can light (light_tiles.frag discards a normal shorter than 0.1:
// background), with the same surface_eye_z the light shader uses; the CPU takes each tile's rows
// together. One fragment per row rather than per tile: the target spans the frame's height, so
// llvmpipe spreads it over its threads. None of those surfaces: (1e30, -1e30).
#include "depth_codec.glsl"

uniform sampler2D normal_map;  // unit 0
uniform sampler2D depth_map;   // unit 3
uniform vec2 planes;
uniform vec3 zrange;
uniform vec2 texel;  // G-buffer texture coordinates per window pixel (padded textures included)
uniform vec2 size;   // the frame in pixels: the last column of tiles may be partial

void main()
{
    vec2 origin = vec2(floor(gl_FragCoord.x) * float(TILE_SIZE), floor(gl_FragCoord.y));
    float zmin = 1e30;
    float zmax = -1e30;
    for (int i = 0; i < TILE_SIZE; ++i) {
        vec2 p = origin + vec2(float(i), 0.0) + 0.5;  // the pixel centre, as the tiles' quads sample
        vec2 uv = p * texel;
        vec3 n = texture2D(normal_map, uv).xyz - 0.5;
        if (p.x < size.x && length(n) > 0.1) {
            float z = surface_eye_z(depth_map, uv, planes, zrange);
            zmin = min(zmin, z);
            zmax = max(zmax, z);
        }
    }
    gl_FragColor = vec4(zmin, zmax, 0.0, 1.0);
}
