#include "platform/glfw_context.h"

#include <GLFW/glfw3.h>

#include "dsr_error.h"
#include "gl/state.h"

namespace dsr {

namespace {

std::string last_glfw_error() {
    const char* what = nullptr;
    const int code = glfwGetError(&what);
    return code == GLFW_NO_ERROR ? "no GLFW error reported" : what ? what : "GLFW error " + std::to_string(code);
}

}  // namespace

GlfwContext::GlfwContext(int width, int height, const std::string& title) {
    if (!glfwInit()) throw Error("GLFW: cannot start (" + last_glfw_error() + "); is DISPLAY set to a running X server?");
    // The tutorial's GL: a 2.1 context. GLFW gives a compatibility context for any version
    // before 3.2, so fixed function stays available; a newer compatible version is a superset.
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    glfwWindowHint(GLFW_STENCIL_BITS, 8);
    glfwWindowHint(GLFW_ALPHA_BITS, 8);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string why = last_glfw_error();
        glfwTerminate();
        throw Error("GLFW: cannot open a " + std::to_string(width) + "x" + std::to_string(height) +
                    " window with an OpenGL 2.1 context (" + why + ")");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(0);  // frame times are the renderer's, not the display's refresh
}

GlfwContext::~GlfwContext() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

int GlfwContext::width() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return w;
}

int GlfwContext::height() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return h;
}

std::string GlfwContext::description() const { return std::string("glfw ") + glfwGetVersionString(); }

void* GlfwContext::proc_address(const char* name) const { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

void GlfwContext::make_current() {
    glfwMakeContextCurrent(window_);
    gl_state().reset();  // the cache described the other context
}

void GlfwContext::swap() { glfwSwapBuffers(window_); }

}  // namespace dsr
