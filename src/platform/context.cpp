// What every backend shares (context.h): handing the entry-point loader its address function.
#include "platform/context.h"

#include "gl/entry_points.h"

namespace dsr {

void load_gl_entry_points(const GLContext& ctx) {
    load_gl_entry_points([&ctx](const char* name) { return ctx.proc_address(name); }, ctx.backend());
}

}  // namespace dsr
