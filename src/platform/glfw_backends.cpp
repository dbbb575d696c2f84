// create_context for the viewer (dsr_view): the GLFW window only. The headless executables
// link headless_backends.cpp instead; never both (one links libOSMesa, this one libGL).
#include "dsr_error.h"
#include "gl/state.h"
#include "platform/glfw_context.h"

namespace dsr {

std::vector<std::string> context_backends() { return {"glfw"}; }

std::string default_context_backend() { return "glfw"; }

std::unique_ptr<GLContext> create_context(const ContextDesc& d) {
    if (d.backend != "glfw")
        throw Error("unknown GL context backend '" + d.backend + "' (the viewer has: glfw)");
    auto ctx = std::make_unique<GlfwContext>(d.width, d.height, "dsr view");
    load_gl_entry_points(*ctx);
    gl_state().reset();  // a fresh context holds GL's defaults, not the last context's state
    return ctx;
}

}  // namespace dsr
