// Where a GL context comes from. One small interface; each backend in its own file
// (osmesa_context.cpp now; a GLFW window and an EGL pbuffer later). Knows nothing of
// deferred shading. Backends are linked per executable (not in libdsr_core.a), so no
// executable links libOSMesa and the system libGL both.
#pragma once
#include <memory>
#include <string>
#include <vector>

namespace dsr {

class GLContext {
public:
    virtual ~GLContext() = default;
    // Size of the main frame buffer (the tutorial's "main frame buffer", §3.6).
    virtual int width() const = 0;
    virtual int height() const = 0;
    virtual std::string backend() const = 0;
    // One line for `dsr info`: the backend and what it runs on (EGL version and vendor ...).
    virtual std::string description() const { return backend(); }
    // Address of a GL entry point (core or extension) for this context; null when absent.
    virtual void* proc_address(const char* name) const = 0;
    virtual void make_current() = 0;
    // Presents the main frame buffer: a window's buffer swap; a no-op headless.
    virtual void swap() {}
};

// What to create: the backend by name (`--context`), and the main frame buffer's size.
struct ContextDesc {
    std::string backend = "osmesa";  // osmesa (headless Mesa) | egl (EGL pbuffer: a GPU, or Mesa); later glfw
    int width = 64, height = 64;
    int egl_device = -1;             // egl: which EGL_EXT_platform_device device; -1: 0
};

// Creates the context, makes it current and loads dsr's GL entry-point table through
// proc_address (src/gl/entry_points.h). Throws dsr::Error with one clear line when the
// backend is unknown or not built into this executable, or when no context can be had.
std::unique_ptr<GLContext> create_context(const ContextDesc& desc);

// Loads dsr's GL entry-point table (src/gl/entry_points.h) through ctx.proc_address, for the
// context that is current (create_context calls it; so does whoever makes a context of its own).
// gl/ takes only the address function, so it never includes this layer.
void load_gl_entry_points(const GLContext& ctx);

// The backends linked into this executable ("osmesa", ...), for help and error messages.
std::vector<std::string> context_backends();

// The first of context_backends(): what `--context` defaults to where $DSR_CONTEXT is unset
// (app/environment.h reads it).
std::string default_context_backend();

}  // namespace dsr
