#version 120
// Lighting pass vertex shader: a screen-aligned quad (§3.4.3). Texture coordinate 1 carries
// the eye-space view ray (x, y, -1) of each corner (Listing 19's clean form), interpolated
// linearly across the quad: exact, since the ray is affine in window coordinates.
// The light shaders (light.frag, light_tiles.frag) take the ray from gl_FragCoord instead, so that
// every light geometry reconstructs the same point; light.frag reads the texture coordinates, and
// ssao.frag both.
// VOLUME: the light's volume mesh instead (light geometries volume and stencil).
// ID_VECS (light_tiles.frag): texture coordinates 2.. carry the quad's light slots, two a float.
// BATCH (light.frag): texture coordinate 2 carries the quad's light slot.
// VOLUME_BATCH (with BATCH and VOLUME): many lights' volume meshes in one draw, each copy of the unit
// sphere's mesh (gl_Vertex) carrying its light's slot; the vertex is the light's eye-space centre
// plus its radius times the unit vertex (batch_pos: eye-space centre, radius), drawn with the
// frame's projection and an identity modelview, as the mesh of one light is drawn scaled and moved.
varying vec2 texcoord;
varying vec3 vpos;
#ifdef ID_VECS
varying vec4 ids[ID_VECS];
#endif
#ifdef BATCH
varying float slot;  // the light's slot in light.frag's arrays, from texture coordinate 2
#endif
#ifdef VOLUME_BATCH
uniform vec4 batch_pos[BATCH];
#endif

void main()
{
#ifdef VOLUME_BATCH
    vec4 lp = batch_pos[int(gl_MultiTexCoord2.x + 0.5)];
    gl_Position = gl_ModelViewProjectionMatrix * vec4(lp.xyz + lp.w * gl_Vertex.xyz, 1.0);
#else
    gl_Position = ftransform();
#endif
#ifdef VOLUME
    texcoord = vec2(0.0);
    vpos = vec3(0.0);
#else
    texcoord = gl_MultiTexCoord0.xy;
    vpos = gl_MultiTexCoord1.xyz;
#endif
#ifdef BATCH
    slot = gl_MultiTexCoord2.x;
#endif
#ifdef ID_VECS
    ids[0] = gl_MultiTexCoord2;
#if ID_VECS > 1
    ids[1] = gl_MultiTexCoord3;
#endif
#if ID_VECS > 2
    ids[2] = gl_MultiTexCoord4;
#endif
#if ID_VECS > 3
    ids[3] = gl_MultiTexCoord5;
#endif
#endif
}
