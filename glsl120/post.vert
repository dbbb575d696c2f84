#version 120
// Screen-aligned quad of the post-processing passes (§3.5): texture coordinates only.
varying vec2 texcoord;

void main()
{
    gl_Position = ftransform();
    texcoord = gl_MultiTexCoord0.xy;
}
