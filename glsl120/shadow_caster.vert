#version 120
// The shadow stage's caster pass (shadow_stage.h): each object into one view of a light's map,
// its modelview the light's view x the object's model (camera-relative to the light, in double).
varying vec3 q;  // the vertex in the light's view space

void main()
{
    vec4 v = gl_ModelViewMatrix * gl_Vertex;
    q = v.xyz;
    gl_Position = gl_ProjectionMatrix * v;
}
