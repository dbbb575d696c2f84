// The entry-point table (entry_points.h), filled through the address function it is handed.
#include "gl/entry_points.h"

#include <cstring>
#include <map>

#include "dsr_error.h"

namespace dsr {

GLEntryPoints gl_entry;

namespace {

bool current_extension(const char* name) {
    const char* ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
    if (!ext) return false;
    const size_t n = std::strlen(name);
    for (const char* p = ext; (p = std::strstr(p, name)); p += n)
        if ((p == ext || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

// Under OpenGL ES 2.0 (docs/gles2.md) a slot whose desktop name ES lacks is filled from the
// first name here whose extension the context offers ("" = core in ES 2.0); a slot with no name
// that applies stays null and is not required. Slots not listed keep their name (GL 2.0 core
// that ES 2.0 shares: shaders, uniforms, buffers, glActiveTexture, two-sided stencil). Names are
// read from the extension list, not from the address function: EGL answers every name it knows,
// whatever the context offers.
struct EsName {
    const char* name;
    const char* extension;
};
const std::map<std::string, std::vector<EsName>>& es_names() {
    static const std::map<std::string, std::vector<EsName>> t = {
        {"glClientActiveTexture", {}},  // no fixed-function arrays in ES 2.0
        {"glMultiTexCoord2f", {}},
        {"glMultiTexCoord3f", {}},
        {"glGenQueries", {}},  // EXT_occlusion_query_boolean answers yes/no, not a sample count
        {"glDeleteQueries", {}},
        {"glBeginQuery", {}},
        {"glEndQuery", {}},
        {"glGetQueryObjectuiv", {}},
        {"glQueryCounter", {}},
        {"glGetQueryObjectui64v", {}},
        {"glActiveStencilFaceEXT", {}},
        {"glDepthBoundsEXT", {}},
        {"glDrawBuffersARB", {{"glDrawBuffersEXT", "GL_EXT_draw_buffers"}, {"glDrawBuffersNV", "GL_NV_draw_buffers"}}},
        {"glGenFramebuffersEXT", {{"glGenFramebuffers", ""}}},
        {"glBindFramebufferEXT", {{"glBindFramebuffer", ""}}},
        {"glDeleteFramebuffersEXT", {{"glDeleteFramebuffers", ""}}},
        {"glFramebufferTexture2DEXT", {{"glFramebufferTexture2D", ""}}},
        {"glFramebufferRenderbufferEXT", {{"glFramebufferRenderbuffer", ""}}},
        {"glCheckFramebufferStatusEXT", {{"glCheckFramebufferStatus", ""}}},
        {"glGenRenderbuffersEXT", {{"glGenRenderbuffers", ""}}},
        {"glBindRenderbufferEXT", {{"glBindRenderbuffer", ""}}},
        {"glDeleteRenderbuffersEXT", {{"glDeleteRenderbuffers", ""}}},
        {"glRenderbufferStorageEXT", {{"glRenderbufferStorage", ""}}},
        {"glBlitFramebufferEXT",
         {{"glBlitFramebufferNV", "GL_NV_framebuffer_blit"}, {"glBlitFramebufferANGLE", "GL_ANGLE_framebuffer_blit"}}},
    };
    return t;
}

// The name to load `desktop` by on this context, or nullptr where it has none; `required` is
// cleared where ES 2.0 may lack it.
const char* context_name(const char* desktop, bool es, bool& required) {
    if (!es) return desktop;
    auto it = es_names().find(desktop);
    if (it == es_names().end()) return desktop;
    required = false;
    for (const EsName& e : it->second)
        if (!*e.extension || current_extension(e.extension)) {
            // Core in ES 2.0 (framebuffer objects): as required as on the desktop.
            if (!*e.extension) required = true;
            return e.name;
        }
    return nullptr;
}

// The fixed-function texture-coordinate calls on OpenGL ES 2.0, which has none: a path that still
// draws through them refuses in one line instead of calling a null pointer.
[[noreturn]] void no_fixed_texcoords() {
    throw Error("this pass draws with fixed-function texture coordinates (glClientActiveTexture, glMultiTexCoord), "
                "which OpenGL ES 2.0 lacks; on --context egl-gles2 use --light-geometry quad (docs/gles2.md)");
}
void APIENTRY es_client_active_texture(GLenum) { no_fixed_texcoords(); }
void APIENTRY es_multi_tex_coord2f(GLenum, GLfloat, GLfloat) { no_fixed_texcoords(); }
void APIENTRY es_multi_tex_coord3f(GLenum, GLfloat, GLfloat, GLfloat) { no_fixed_texcoords(); }

}  // namespace

bool current_gl_is_es() {
    const char* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return v && std::strncmp(v, "OpenGL ES", 9) == 0;
}

void load_gl_entry_points(const GLProcAddress& proc_address, const std::string& source) {
    GLEntryPoints t;  // filled aside, so a failure leaves gl_entry as it was
    std::string missing;
    const bool es = current_gl_is_es();
    auto load = [&](const char* desktop, bool required) -> void* {
        const char* n = context_name(desktop, es, required);
        void* p = n ? proc_address(n) : nullptr;
        if (!p && required) missing += std::string(missing.empty() ? "" : ", ") + (n ? n : desktop);
        return p;
    };
#define DSR_GL_LOAD(type, name) t.name = reinterpret_cast<type>(load("gl" #name, false));
#define DSR_GL_LOAD_REQUIRED(type, name) t.name = reinterpret_cast<type>(load("gl" #name, true));
    DSR_GL_REQUIRED_ENTRY_POINTS(DSR_GL_LOAD_REQUIRED)
    DSR_GL_OPTIONAL_ENTRY_POINTS(DSR_GL_LOAD)
#undef DSR_GL_LOAD_REQUIRED
#undef DSR_GL_LOAD
    if (es) {
        t.ClientActiveTexture = es_client_active_texture;
        t.MultiTexCoord2f = es_multi_tex_coord2f;
        t.MultiTexCoord3f = es_multi_tex_coord3f;
    }
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
