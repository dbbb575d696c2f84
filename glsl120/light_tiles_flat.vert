#version 130
// Light geometry `tiles` with --tile-fetch vertex (src/deferred/light_geometry_tiles.cpp; GLSL 1.30
// for flat varyings, where the GL has it; every other shader here is 1.20): a whole tile's point,
// or a partial edge tile's quad, carries the slots of its LIGHTS lights in the batch's uniform
// arrays (texture coordinates 2.., one slot a float). Their position and colour are read here,
// once for the tile, and handed to light_tiles_flat.frag as flat varyings, which a CPU rasteriser
// gives every pixel of the primitive without interpolating; read in the fragment shader at a slot
// taken from a varying, as light_tiles.frag reads them, each element is read lane by lane.
#ifndef LIGHTS
#define LIGHTS MAX_LIGHTS  // the table's programs; light_geometry_tiles.cpp builds one per count
#endif
uniform vec4 lightpos[BATCH];
uniform vec4 lightcolor[BATCH];
flat out vec4 tile_lightpos[LIGHTS];
flat out vec4 tile_lightcolor[LIGHTS];

void main()
{
    gl_Position = ftransform();
    vec4 slots[4] = vec4[4](gl_MultiTexCoord2, gl_MultiTexCoord3, gl_MultiTexCoord4, gl_MultiTexCoord5);
    for (int k = 0; k < LIGHTS; ++k) {
        int s = int(slots[k / 4][k % 4] + 0.5);
        tile_lightpos[k] = lightpos[s];
        tile_lightcolor[k] = lightcolor[s];
    }
}
