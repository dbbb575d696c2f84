#include <GL/osmesa.h>

#include <vector>

#include "dsr_error.h"
#include "gl/state.h"
#include "platform/context.h"

namespace dsr {

namespace {

class OSMesaGLContext : public GLContext {
public:
    OSMesaGLContext(int w, int h) : w_(w), h_(h), buffer_(size_t(w) * h * 4) {
        // Ask for the oldest profile the tutorial needs: compatibility 2.1. Mesa may give a
        // newer compatibility version, which is a superset (fixed function stays available).
        const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                               OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 2,
                               OSMESA_CONTEXT_MINOR_VERSION, 1, 0};
        ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
        // A GL older than 2.1 (e.g. MESA_GL_VERSION_OVERRIDE=1.5) still gets a context, so the
        // capability probe can say exactly what is missing.
        if (!ctx_) ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
        if (!ctx_) throw Error("OSMesa: cannot create an OpenGL context");
        if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, w, h)) {
            OSMesaDestroyContext(ctx_);
            throw Error("OSMesa: cannot make the context current at " + std::to_string(w) + "x" + std::to_string(h));
        }
        // Row 0 of the buffer is the bottom row, like glReadPixels.
        OSMesaPixelStore(OSMESA_Y_UP, 1);
    }
    ~OSMesaGLContext() override { OSMesaDestroyContext(ctx_); }
    int width() const override { return w_; }
    int height() const override { return h_; }
    std::string backend() const override { return "osmesa"; }
    void* proc_address(const char* name) const override {
        return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
    }
    void make_current() override {
        if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, w_, h_))
            throw Error("OSMesa: cannot make the context current");
        OSMesaPixelStore(OSMESA_Y_UP, 1);
        gl_state().reset();  // the cache described the other context
    }

private:
    int w_, h_;
    std::vector<unsigned char> buffer_;
    OSMesaContext ctx_ = nullptr;
};

}  // namespace

std::unique_ptr<GLContext> create_osmesa_context(int width, int height) {
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
        throw Error("OSMesa: bad main buffer size " + std::to_string(width) + "x" + std::to_string(height));
    return std::make_unique<OSMesaGLContext>(width, height);
}

}  // namespace dsr
