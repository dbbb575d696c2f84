#version 120
// Material pass vertex shader (Listing 10): everything to view space. Meshes are in object
// space; the modelview matrix is view * model, composed in double on the CPU for each object
// (camera-relative: far from the origin it holds small numbers). Tangent and binormal arrive as
// texture coordinates 1 and 2, as in Listing 10's a2v.
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
    // ftransform() is invariant with the fixed-function depth pre-pass (§3.3.1), so GL_LEQUAL
    // passes exactly the fragments the pre-pass kept.
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
