// The fixed-function vertex arrays (glVertexPointer, glNormalPointer, glTexCoordPointer,
// glColorPointer) and their OpenGL ES 2.0 stand-ins: generic attributes at the locations the GLSL
// ES prelude binds (gl/glsl_dialect.h, es_attributes). On desktop GL each call is the fixed-function
// one, as before; on ES the attribute. Pointers are offsets into the bound GL_ARRAY_BUFFER, or
// client memory where none is bound.
#pragma once
#include "gl/gl.h"

namespace dsr {

void vertex_array(int size, GLsizei stride, const void* p);               // gl_Vertex
void normal_array(GLsizei stride, const void* p);                         // gl_Normal (3 floats)
void texcoord_array(int unit, int size, GLsizei stride, const void* p);   // gl_MultiTexCoord<unit>
void color_array(GLsizei stride, const void* p);                          // gl_Color (4 floats)
void disable_vertex_array();
void disable_normal_array();
void disable_texcoord_array(int unit);
// Without its array gl_Color reads the current colour (white after the arrays are drawn).
void disable_color_array();

}  // namespace dsr
