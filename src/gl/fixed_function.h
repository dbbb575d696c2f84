// The GL 1.1 calls OpenGL ES 2.0 lacks or names otherwise, each as the desktop call or its ES
// stand-in (docs/gles2.md). gl/gl.h maps the plain names here, so call sites stay plain GL and the
// desktop build makes the same calls as before: glColor4f (ES: the gl_Color attribute's current
// value), glClearDepth (glClearDepthf), glDrawBuffer (a framebuffer object's one target through
// glDrawBuffersEXT/NV; none for the main buffer, which has only its back buffer), glReadBuffer
// (ES reads the one colour buffer there is).
#pragma once
#include "gl/entry_points.h"

namespace dsr {

void ff_color4f(GLfloat r, GLfloat g, GLfloat b, GLfloat a);
void ff_clear_depth(GLdouble depth);
void ff_draw_buffer(GLenum buffer);
void ff_read_buffer(GLenum buffer);

}  // namespace dsr
