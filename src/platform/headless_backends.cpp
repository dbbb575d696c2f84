// create_context for the headless executables (dsr, dsr_tests): the backends that need no
// window system. The viewer links its own list with the GLFW backend instead.
#include "dsr_error.h"
#include "gl/state.h"
#include "platform/context.h"

namespace dsr {

// gles2: an OpenGL ES 2.0 context (`egl-gles2`) instead of desktop OpenGL.
std::unique_ptr<GLContext> create_egl_context(int width, int height, int device, bool gles2);  // egl_context.cpp
#ifndef DSR_NO_OSMESA
std::unique_ptr<GLContext> create_osmesa_context(int width, int height);  // osmesa_context.cpp
std::vector<std::string> context_backends() { return {"osmesa", "egl", "egl-gles2"}; }
#else
// A build for a machine without Mesa (tests/gpu_bench.sh): EGL only, linked against the
// system's libOpenGL/libEGL (glvnd) instead of libOSMesa.
std::vector<std::string> context_backends() { return {"egl", "egl-gles2"}; }
#endif

std::string default_context_backend() { return context_backends().front(); }

std::unique_ptr<GLContext> create_context(const ContextDesc& d) {
    std::unique_ptr<GLContext> ctx;  // current on return from its backend
#ifndef DSR_NO_OSMESA
    if (d.backend == "osmesa") ctx = create_osmesa_context(d.width, d.height);
#endif
    if (d.backend == "egl" || d.backend == "egl-gles2") {
        ctx = create_egl_context(d.width, d.height, d.egl_device < 0 ? 0 : d.egl_device, d.backend == "egl-gles2");
    }
    if (ctx) {
        // Reloaded with every context: another backend's entry points may differ.
        load_gl_entry_points(*ctx);
        gl_state().reset();  // a fresh context holds GL's defaults, not the last context's state
        return ctx;
    }
    std::string list;
    for (const auto& b : context_backends()) list += (list.empty() ? "" : ", ") + b;
    throw Error("unknown GL context backend '" + d.backend + "' (this build has: " + list + ")");
}

}  // namespace dsr
