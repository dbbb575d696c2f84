// Offscreen surfaces of the current context: the 2005 pbuffer (WGL_ARB_pbuffer then, EGL pbuffer
// surfaces now): a drawable of its own, with its own colour, depth and stencil, made current with
// the one context (so every GL object and state is shared) to render into it. PBuffer's `pbuffer`
// implementation (pbuffer.h) renders through this; a context backend that has such surfaces (EGL)
// registers itself while it lives. No render-to-texture: the drivers at hand offer none for
// desktop GL (docs/gpu.md), so a surface reaches a texture by glCopyTexSubImage2D.
#pragma once
#include <string>

namespace dsr {

class OffscreenSurfaces {
public:
    virtual ~OffscreenSurfaces() = default;
    // A width x height RGBA8 surface with 24-bit depth and 8-bit stencil; throws dsr::Error.
    virtual void* create_surface(int width, int height) = 0;
    virtual void destroy_surface(void* surface) = 0;
    // Draw and read `surface` with the current context; null: the context's main frame buffer.
    virtual void make_surface_current(void* surface) = 0;
    // What the backend found about binding a surface as a texture (eglBindTexImage), for `info`.
    virtual std::string bind_tex_image_note() const = 0;
};

// The current context's offscreen surfaces, or null where it has none (OSMesa, GLFW).
OffscreenSurfaces* offscreen_surfaces();
void set_offscreen_surfaces(OffscreenSurfaces* s);  // the backend, on creation (null on destruction)

}  // namespace dsr
