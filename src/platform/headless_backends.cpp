// create_context for the headless executables (dsr, dsr_tests): the backends that need no
// window system. The viewer links its own list with the GLFW backend instead.
#include "dsr_error.h"
#include "platform/context.h"

namespace dsr {

std::unique_ptr<GLContext> create_osmesa_context(int width, int height);  // osmesa_context.cpp

std::vector<std::string> context_backends() { return {"osmesa"}; }

std::unique_ptr<GLContext> create_context(const ContextDesc& d) {
    if (d.backend == "osmesa") return create_osmesa_context(d.width, d.height);
    std::string list;
    for (const auto& b : context_backends()) list += (list.empty() ? "" : ", ") + b;
    throw Error("unknown GL context backend '" + d.backend + "' (this build has: " + list + ")");
}

}  // namespace dsr
