#include "gl/check.h"

#include <cstdlib>
#include <string>

#include "dsr_error.h"

namespace dsr {

const char* gl_error_name(GLenum err) {
    switch (err) {
        case GL_NO_ERROR: return "GL_NO_ERROR";
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
        case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        case GL_INVALID_FRAMEBUFFER_OPERATION_EXT: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        default: return "unknown GL error";
    }
}

const char* framebuffer_status_name(GLenum status) {
    switch (status) {
        case GL_FRAMEBUFFER_COMPLETE_EXT: return "complete";
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_EXT: return "incomplete attachment";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_EXT: return "missing attachment";
        case GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_EXT: return "attachments differ in size";
        case GL_FRAMEBUFFER_INCOMPLETE_FORMATS_EXT: return "attachments differ in format";
        case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER_EXT: return "draw buffer has no attachment";
        case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER_EXT: return "read buffer has no attachment";
        case GL_FRAMEBUFFER_UNSUPPORTED_EXT: return "format combination unsupported";
        default: return "unknown framebuffer status";
    }
}

namespace {
bool& debug_flag() {
    static bool on = false;  // `--debug-gl` (its default from $DSR_DEBUG_GL, app/environment.h)
    return on;
}
}  // namespace

void set_debug_gl(bool on) { debug_flag() = on; }
bool debug_gl() { return debug_flag(); }

int drain_gl_errors() {
    int n = 0;
    while (glGetError() != GL_NO_ERROR && n < 64) ++n;
    return n;
}

void check_gl(const char* stage) {
    GLenum err = glGetError();
    if (err == GL_NO_ERROR) return;
    std::string msg = std::string("GL error in ") + stage + ": " + gl_error_name(err);
    drain_gl_errors();
    throw Error(msg);
}

}  // namespace dsr
