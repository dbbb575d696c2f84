#version 120
// Lighting pass vertex shader: a screen-aligned quad (§3.4.3). Texture coordinate 1 carries
// the eye-space view ray (x, y, -1) of each corner (Listing 19's clean form), interpolated
// linearly across the quad: exact, since the ray is affine in window coordinates.
// VOLUME: the light's volume mesh instead (light geometries volume and stencil); the fragment
// shader takes its texture coordinates and view ray from gl_FragCoord.
varying vec2 texcoord;
varying vec3 vpos;

void main()
{
    gl_Position = ftransform();
#ifdef VOLUME
    texcoord = vec2(0.0);
    vpos = vec3(0.0);
#else
    texcoord = gl_MultiTexCoord0.xy;
    vpos = gl_MultiTexCoord1.xyz;
#endif
}
