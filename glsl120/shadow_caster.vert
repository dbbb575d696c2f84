#version 120
// The shadow stage's caster pass (shadow_stage.h): each object into one view of a light's map,
// its modelview the light's view x the object's model (camera-relative to the light, in double).
// CUT_OUT (shader_table.h surface_defines): the diffuse map's texture coordinates, and with
// VERTEX_COLOR the vertex colour's alpha, for the fragment stage's coverage.
varying vec3 q;  // the vertex in the light's view space
#ifdef CUT_OUT
varying vec2 texcoord;
#ifdef VERTEX_COLOR
varying float valpha;
#endif
#endif

void main()
{
#ifdef CUT_OUT
    texcoord = gl_MultiTexCoord0.xy;
#ifdef VERTEX_COLOR
    valpha = gl_Color.a;
#endif
#endif
    vec4 v = gl_ModelViewMatrix * gl_Vertex;
    q = v.xyz;
    gl_Position = gl_ProjectionMatrix * v;
}
