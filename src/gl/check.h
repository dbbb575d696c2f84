// GL errors become dsr::Error naming the stage.
#pragma once
#include <string>

#include "gl/gl.h"

namespace dsr {

const char* gl_error_name(GLenum err);
const char* framebuffer_status_name(GLenum status);

// Drains glGetError; throws dsr::Error("GL error in <stage>: GL_INVALID_...") if any was set.
void check_gl(const char* stage);

// Per-stage checks, only in debug mode (`--debug-gl`; its default from DSR_DEBUG_GL, read by
// app/environment.h): glGetError can stall a real GPU, so release runs check once a frame (DeferredShader::render) and at set-up.
void set_debug_gl(bool on);
bool debug_gl();
inline void check_gl_stage(const char* stage) {
    if (debug_gl()) check_gl(stage);
}

// Number of GL errors pending (drained); for stress counters that must not throw.
int drain_gl_errors();

}  // namespace dsr
