// The entry-point table (entry_points.h), filled through the address function it is handed.
#include "gl/entry_points.h"

#include "dsr_error.h"

namespace dsr {

GLEntryPoints gl_entry;

void load_gl_entry_points(const GLProcAddress& proc_address, const std::string& source) {
    GLEntryPoints t;  // filled aside, so a failure leaves gl_entry as it was
    std::string missing;
#define DSR_GL_LOAD(type, name) t.name = reinterpret_cast<type>(proc_address("gl" #name));
#define DSR_GL_LOAD_REQUIRED(type, name) \
    DSR_GL_LOAD(type, name)              \
    if (!t.name) missing += std::string(missing.empty() ? "" : ", ") + "gl" #name;
    DSR_GL_REQUIRED_ENTRY_POINTS(DSR_GL_LOAD_REQUIRED)
    DSR_GL_OPTIONAL_ENTRY_POINTS(DSR_GL_LOAD)
#undef DSR_GL_LOAD_REQUIRED
#undef DSR_GL_LOAD
    if (!missing.empty())
        throw Error("GL context '" + source + "' lacks required entry point" +
                    (missing.find(',') == std::string::npos ? " " : "s ") + missing);
    gl_entry = t;
}

std::vector<GLEntryPointStatus> gl_entry_point_status() {
    std::vector<GLEntryPointStatus> out;
#define DSR_GL_STATUS_REQUIRED(type, name) out.push_back({"gl" #name, true, gl_entry.name != nullptr});
#define DSR_GL_STATUS_OPTIONAL(type, name) out.push_back({"gl" #name, false, gl_entry.name != nullptr});
    DSR_GL_REQUIRED_ENTRY_POINTS(DSR_GL_STATUS_REQUIRED)
    DSR_GL_OPTIONAL_ENTRY_POINTS(DSR_GL_STATUS_OPTIONAL)
#undef DSR_GL_STATUS_REQUIRED
#undef DSR_GL_STATUS_OPTIONAL
    return out;
}

}  // namespace dsr
