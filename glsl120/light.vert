#version 120
// Lighting pass vertex shader: a screen-aligned quad (§3.4.3). Texture coordinate 1 carries
// the eye-space view ray (x, y, -1) of each corner (Listing 19's clean form), interpolated
// linearly across the quad: exact, since the ray is affine in window coordinates.
varying vec2 texcoord;
varying vec3 vpos;

void main()
{
    gl_Position = ftransform();
    texcoord = gl_MultiTexCoord0.xy;
    vpos = gl_MultiTexCoord1.xyz;
}
