// Desktop call or ES stand-in (fixed_function.h).
#include "gl/fixed_function.h"

#include "gl/glsl_dialect.h"
#include "gl/state.h"

// gl/gl.h (through state.h) maps these names to the functions below: here they are GL's own.
#undef glColor4f
#undef glClearDepth
#undef glDrawBuffer
#undef glReadBuffer

namespace dsr {

void ff_color4f(GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
    if (gl_state().es()) return gl_entry.VertexAttrib4f(kEsColorLocation, r, g, b, a);
    glColor4f(r, g, b, a);
}

void ff_clear_depth(GLdouble depth) {
    if (gl_state().es()) return gl_entry.ClearDepthf(GLfloat(depth));
    glClearDepth(depth);
}

void ff_draw_buffer(GLenum buffer) {
    if (!gl_state().es()) return glDrawBuffer(buffer);
    if (buffer >= GL_COLOR_ATTACHMENT0_EXT && buffer < GL_COLOR_ATTACHMENT0_EXT + 16 && gl_entry.DrawBuffersARB)
        gl_entry.DrawBuffersARB(1, &buffer);
}

void ff_read_buffer(GLenum buffer) {
    if (!gl_state().es()) glReadBuffer(buffer);
}

}  // namespace dsr
