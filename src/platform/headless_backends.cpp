// create_context for the headless executables (dsr, dsr_tests): the backends that need no
// window system. The viewer links its own list with the GLFW backend instead.
#include <cstdlib>

#include "dsr_error.h"
#include "gl/entry_points.h"
#include "gl/state.h"
#include "platform/context.h"

namespace dsr {

std::unique_ptr<GLContext> create_osmesa_context(int width, int height);  // osmesa_context.cpp

std::vector<std::string> context_backends() { return {"osmesa"}; }

std::string default_context_backend() {
    const char* env = std::getenv("DSR_CONTEXT");
    return env && *env ? env : context_backends().front();
}

std::unique_ptr<GLContext> create_context(const ContextDesc& d) {
    if (d.backend == "osmesa") {
        auto ctx = create_osmesa_context(d.width, d.height);  // current on return
        load_gl_entry_points(*ctx);
        gl_state().reset();  // a fresh context holds GL's defaults, not the last context's state
        return ctx;
    }
    std::string list;
    for (const auto& b : context_backends()) list += (list.empty() ? "" : ", ") + b;
    throw Error("unknown GL context backend '" + d.backend + "' (this build has: " + list + ")");
}

}  // namespace dsr
