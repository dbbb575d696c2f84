#version 120
// The tiles' depth culling, second pass (src/deferred/tile_depth.cpp): fragment (x, y) takes the
// rows y * TILE_SIZE .. of tile column x in tile_depth.frag's target together, so that what is read
// back to the CPU is one texel per tile (at 1920x1080 and 16-pixel tiles 8160 texels, not the row
// target's 129600). Rows at and past `rows` (the frame's height; the target may be padded) are left out.
uniform sampler2D row_spans;  // tile_depth.frag's target, nearest filtering
uniform vec2 texel;           // 1 / the row target's texture size
uniform float rows;

void main()
{
    float x = floor(gl_FragCoord.x) + 0.5;
    float y0 = floor(gl_FragCoord.y) * float(TILE_SIZE);
    float zmin = 1e30;
    float zmax = -1e30;
    for (int i = 0; i < TILE_SIZE; ++i) {
        float y = y0 + float(i);
        if (y < rows) {
            vec2 s = texture2D(row_spans, vec2(x, y + 0.5) * texel).xy;
            zmin = min(zmin, s.x);
            zmax = max(zmax, s.y);
        }
    }
    gl_FragColor = vec4(zmin, zmax, 0.0, 1.0);
}
