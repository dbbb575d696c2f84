// Where a GL context comes from. One small interface; each backend in its own file
// (osmesa_context.cpp now; a GLFW window and an EGL pbuffer later). Knows nothing of
// deferred shading.
#pragma once
#include <memory>
#include <string>

namespace dsr {

class GLContext {
public:
    virtual ~GLContext() = default;
    // Size of the main frame buffer (the tutorial's "main frame buffer", §3.6).
    virtual int width() const = 0;
    virtual int height() const = 0;
    virtual std::string backend() const = 0;
};

// A headless OSMesa compatibility context asking for OpenGL 2.1 (GLSL 1.20), with an
// RGBA8 main buffer of width x height and a 24-bit depth buffer. Made current.
// Throws dsr::Error with one clear line when no context can be had.
std::unique_ptr<GLContext> create_osmesa_context(int width, int height);

}  // namespace dsr
