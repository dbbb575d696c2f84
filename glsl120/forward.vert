#version 120
// Forward reference renderer, vertex stage (§2.4.1, Listings 3-4): the same view-space
// varyings as the material pass (Listing 10), so the forward and deferred paths light the
// same interpolated position and tangent frame. Meshes are in object space: modelview =
// view * model, composed in double on the CPU per object.
// The depth pre-pass of the multi-pass form (Listing 4) draws with this program too, and the
// later passes may use the other variant (normal map or not): `invariant` makes gl_Position the
// same bits in every program built from this code, so GL_EQUAL passes exactly the pre-pass's
// fragments (ftransform() alone promises invariance only with the fixed-function pipeline).
invariant gl_Position;
varying vec2 texcoord;
varying vec3 vpos;
varying vec3 normal;
varying vec3 tangent;
varying vec3 binormal;
#ifdef VERTEX_COLOR
varying vec4 vcolor;  // the mesh's per-vertex colour (Mesh::colors)
#endif

void main()
{
    gl_Position = ftransform();
    texcoord = gl_MultiTexCoord0.xy;
    vpos = (gl_ModelViewMatrix * gl_Vertex).xyz;
    mat3 modelviewrot = mat3(gl_ModelViewMatrix);
    normal = modelviewrot * gl_Normal;
    tangent = modelviewrot * gl_MultiTexCoord1.xyz;
    binormal = modelviewrot * gl_MultiTexCoord2.xyz;
#ifdef VERTEX_COLOR
    vcolor = gl_Color;
#endif
}
