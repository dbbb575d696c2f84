// An EGL context: a desktop OpenGL compatibility context asking for 2.1 (`egl`), or an OpenGL ES
// 2.0 context (`egl-gles2`, docs/gles2.md), with a pbuffer surface as the main frame buffer, on
// the EGL device platform (EGL_EXT_platform_device: the first device, or --egl-device N), else
// Mesa's surfaceless platform, else the default display. On an NVIDIA GPU desktop GL gives GL 4.6
// compatibility; on Mesa here, llvmpipe (so CI tests both).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string>
#include <vector>

#include "dsr_error.h"
#include "gl/state.h"
#include "gl/surfaces.h"
#include "platform/context.h"

namespace dsr {

namespace {

const char* egl_error_name(EGLint e) {
    switch (e) {
        case EGL_SUCCESS: return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
        case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
        case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
        default: return "unknown EGL error";
    }
}

[[noreturn]] void fail(const std::string& what) {
    throw Error("EGL: " + what + " (" + egl_error_name(eglGetError()) + ")");
}

bool has_token(const char* list, const std::string& name) {
    if (!list) return false;
    const std::string s = std::string(" ") + list + " ";
    return s.find(" " + name + " ") != std::string::npos;
}

// The display: device platform, then surfaceless, then the default display.
EGLDisplay open_display(int device, std::string& platform) {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (get_platform_display && query_devices && has_token(client, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[16];
        EGLint n = 0;
        if (query_devices(16, devices, &n) && n > 0) {
            if (device < 0 || device >= n)
                throw Error("EGL: --egl-device " + std::to_string(device) + " asked for, " + std::to_string(n) +
                            " device(s) found (0.." + std::to_string(n - 1) + ")");
            EGLDisplay d = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[device], nullptr);
            if (d != EGL_NO_DISPLAY) {
                platform = "device " + std::to_string(device) + " of " + std::to_string(n);
                return d;
            }
        }
    }
    if (device != 0) throw Error("EGL: --egl-device needs EGL_EXT_platform_device, which this EGL lacks");
    if (get_platform_display && has_token(client, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY) {
            platform = "surfaceless (Mesa)";
            return d;
        }
    }
    platform = "default display";
    return eglGetDisplay(EGL_DEFAULT_DISPLAY);
}

// The main buffer and every P-buffer of `--render-target pbuffer` (gl/surfaces.h) are pbuffer
// surfaces of one config, made current with the one context.
class EGLGLContext : public GLContext, public OffscreenSurfaces {
public:
    // gles2: an OpenGL ES 2.0 context instead of desktop OpenGL.
    EGLGLContext(int w, int h, int device, bool gles2) : w_(w), h_(h), gles2_(gles2) {
        dpy_ = open_display(device, platform_);
        if (dpy_ == EGL_NO_DISPLAY) fail("no display");
        EGLint major = 0, minor = 0;
        if (!eglInitialize(dpy_, &major, &minor)) fail("cannot initialise the display (" + platform_ + ")");
        version_ = std::to_string(major) + "." + std::to_string(minor);
        const char* api = gles2 ? "OpenGL ES 2.0" : "desktop OpenGL";
        if (!eglBindAPI(gles2 ? EGL_OPENGL_ES_API : EGL_OPENGL_API))
            fail(std::string(api) + " is not offered (eglBindAPI)");
        // RGBA8 with a 24-bit depth and 8-bit stencil main buffer, as the OSMesa context has.
        const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                         gles2 ? EGL_OPENGL_ES2_BIT : EGL_OPENGL_BIT,
                                         EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                                         EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8, EGL_NONE};
        EGLConfig& config = config_;
        EGLint n = 0;
        if (!eglChooseConfig(dpy_, config_attribs, &config, 1, &n) || n < 1)
            fail(std::string("no RGBA8 pbuffer config with 24-bit depth and 8-bit stencil for ") + api);
        const EGLint surface_attribs[] = {EGL_WIDTH, w, EGL_HEIGHT, h, EGL_NONE};
        surface_ = eglCreatePbufferSurface(dpy_, config, surface_attribs);
        if (surface_ == EGL_NO_SURFACE) fail("cannot create a " + std::to_string(w) + "x" + std::to_string(h) + " pbuffer");
        if (gles2) {
            // ES 2.0 asked for; Mesa gives its newest ES (a superset), and dsr reads only ES 2.0 and
            // its extensions from it (gl/caps.h).
            const EGLint es_attribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
            ctx_ = eglCreateContext(dpy_, config, EGL_NO_CONTEXT, es_attribs);
        } else {
            // The oldest profile the tutorial needs: compatibility 2.1 (a newer compatibility
            // version is a superset and fine).
            const EGLint ctx_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 2, EGL_CONTEXT_MINOR_VERSION, 1,
                                          EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                                          EGL_NONE};
            ctx_ = eglCreateContext(dpy_, config, EGL_NO_CONTEXT, ctx_attribs);
            if (ctx_ == EGL_NO_CONTEXT) ctx_ = eglCreateContext(dpy_, config, EGL_NO_CONTEXT, nullptr);
        }
        if (ctx_ == EGL_NO_CONTEXT) fail(std::string("cannot create an ") + api + " context");
        make_current();
        const char* vendor = eglQueryString(dpy_, EGL_VENDOR);
        vendor_ = vendor ? vendor : "";
        // An ES context offers no P-buffer surfaces: --render-target pbuffer is a desktop path.
        if (gles2) return;
        // Render-to-texture pbuffers (eglBindTexImage): configs that offer them for desktop GL.
        const EGLint rtt_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                      EGL_BIND_TO_TEXTURE_RGBA, EGL_TRUE, EGL_NONE};
        EGLint rtt = 0;
        if (!eglChooseConfig(dpy_, rtt_attribs, nullptr, 0, &rtt)) rtt = 0;
        bind_tex_note_ = std::to_string(rtt) + " pbuffer config(s) with EGL_BIND_TO_TEXTURE_RGBA for desktop GL; "
                         "not used: P-buffers reach their textures by glCopyTexSubImage2D (Mesa accepted "
                         "eglBindTexImage with the texture left empty, docs/gpu.md)";
        set_offscreen_surfaces(this);
    }
    ~EGLGLContext() override {
        if (offscreen_surfaces() == this) set_offscreen_surfaces(nullptr);
        eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (ctx_ != EGL_NO_CONTEXT) eglDestroyContext(dpy_, ctx_);
        if (surface_ != EGL_NO_SURFACE) eglDestroySurface(dpy_, surface_);
        // The display stays initialised: EGL displays are per process and other contexts of
        // this process may still use it.
    }
    int width() const override { return w_; }
    int height() const override { return h_; }
    std::string backend() const override { return gles2_ ? "egl-gles2" : "egl"; }
    std::string description() const override {
        return "EGL " + version_ + " (" + vendor_ + "), " + (gles2_ ? "OpenGL ES 2.0 context, " : "") + platform_ + ", pbuffer " + std::to_string(w_) + "x" +
               std::to_string(h_);
    }
    void* proc_address(const char* name) const override { return reinterpret_cast<void*>(eglGetProcAddress(name)); }
    void make_current() override {
        if (!eglMakeCurrent(dpy_, surface_, surface_, ctx_)) fail("cannot make the context current");
        gl_state().reset();  // the cache described the other context
    }

    void* create_surface(int width, int height) override {
        const EGLint attribs[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
        EGLSurface s = eglCreatePbufferSurface(dpy_, config_, attribs);
        if (s == EGL_NO_SURFACE)
            fail("cannot create a " + std::to_string(width) + "x" + std::to_string(height) + " pbuffer for a P-buffer");
        return s;
    }
    void destroy_surface(void* surface) override { eglDestroySurface(dpy_, static_cast<EGLSurface>(surface)); }
    void make_surface_current(void* surface) override {
        // The same context: every object and all state stay, so GlState's cache stays true.
        EGLSurface s = surface ? static_cast<EGLSurface>(surface) : surface_;
        if (!eglMakeCurrent(dpy_, s, s, ctx_)) fail("cannot make a pbuffer surface current");
    }
    std::string bind_tex_image_note() const override { return bind_tex_note_; }

private:
    int w_, h_;
    bool gles2_;
    EGLConfig config_ = nullptr;
    std::string bind_tex_note_;
    EGLDisplay dpy_ = EGL_NO_DISPLAY;
    EGLSurface surface_ = EGL_NO_SURFACE;
    EGLContext ctx_ = EGL_NO_CONTEXT;
    std::string version_, vendor_, platform_;
};

}  // namespace

std::unique_ptr<GLContext> create_egl_context(int width, int height, int device, bool gles2) {
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
        throw Error("EGL: bad main buffer size " + std::to_string(width) + "x" + std::to_string(height));
    return std::make_unique<EGLGLContext>(width, height, device, gles2);
}

}  // namespace dsr
