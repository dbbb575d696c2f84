// Fixed-function arrays or ES 2.0 attributes (vertex_arrays.h).
#include "gl/vertex_arrays.h"

#include "gl/glsl_dialect.h"
#include "gl/state.h"

namespace dsr {

namespace {
bool es() { return gl_state().es(); }
void attribute(int location, int size, GLsizei stride, const void* p) {
    glEnableVertexAttribArray(GLuint(location));
    glVertexAttribPointer(GLuint(location), size, GL_FLOAT, GL_FALSE, stride, p);
}
}  // namespace

void vertex_array(int size, GLsizei stride, const void* p) {
    if (es()) return attribute(kEsVertexLocation, size, stride, p);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(size, GL_FLOAT, stride, p);
}

void normal_array(GLsizei stride, const void* p) {
    if (es()) return attribute(kEsNormalLocation, 3, stride, p);
    glEnableClientState(GL_NORMAL_ARRAY);
    glNormalPointer(GL_FLOAT, stride, p);
}

void texcoord_array(int unit, int size, GLsizei stride, const void* p) {
    if (es()) return attribute(es_texcoord_location(unit), size, stride, p);
    glClientActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(size, GL_FLOAT, stride, p);
    glClientActiveTexture(GL_TEXTURE0);
}

void color_array(GLsizei stride, const void* p) {
    if (es()) return attribute(kEsColorLocation, 4, stride, p);
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(4, GL_FLOAT, stride, p);
}

void disable_vertex_array() {
    if (es()) return glDisableVertexAttribArray(kEsVertexLocation);
    glDisableClientState(GL_VERTEX_ARRAY);
}

void disable_normal_array() {
    if (es()) return glDisableVertexAttribArray(kEsNormalLocation);
    glDisableClientState(GL_NORMAL_ARRAY);
}

void disable_texcoord_array(int unit) {
    if (es()) return glDisableVertexAttribArray(GLuint(es_texcoord_location(unit)));
    glClientActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glClientActiveTexture(GL_TEXTURE0);
}

void disable_color_array() {
    if (es()) {
        glDisableVertexAttribArray(kEsColorLocation);
        glVertexAttrib4f(kEsColorLocation, 1, 1, 1, 1);
        return;
    }
    glDisableClientState(GL_COLOR_ARRAY);
    glColor4f(1, 1, 1, 1);  // the current colour is undefined after drawing with the array
}

}  // namespace dsr
