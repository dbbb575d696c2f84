#version 120
// The invocation-counter probe (src/gl/invocation_probe.cpp): any shader of more than one
// instruction (llvmpipe counts nothing for a shader of one); its colour is never written, since
// every fragment fails the stencil test.
varying vec2 texcoord;

void main()
{
    gl_FragColor = vec4(fract(gl_FragCoord.xy * 0.01), texcoord);
}
