// GL errors become dsr::Error naming the stage (DESIGN: "turned into an exception naming the stage").
#pragma once
#include <string>

#include "gl/gl.h"

namespace dsr {

const char* gl_error_name(GLenum err);
const char* framebuffer_status_name(GLenum status);

// Drains glGetError; throws dsr::Error("GL error in <stage>: GL_INVALID_...") if any was set.
void check_gl(const char* stage);

// Number of GL errors pending (drained); for stress counters that must not throw.
int drain_gl_errors();

}  // namespace dsr
