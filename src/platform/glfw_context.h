// The viewer's GL context: a GLFW window with an OpenGL 2.1 compatibility context on the system
// libGL (never linked with libOSMesa: see the Makefile). Beside GLContext it hands out the
// window, for input and resizing.
#pragma once
#include <memory>
#include <string>

#include "platform/context.h"

struct GLFWwindow;

namespace dsr {

class GlfwContext : public GLContext {
public:
    // Opens a visible window of width x height and makes its context current. Throws dsr::Error
    // with GLFW's own description when there is no display or no GL 2.1 context.
    GlfwContext(int width, int height, const std::string& title);
    ~GlfwContext() override;
    // The framebuffer's size now (0 x 0 while minimised).
    int width() const override;
    int height() const override;
    std::string backend() const override { return "glfw"; }
    std::string description() const override;
    void* proc_address(const char* name) const override;
    void make_current() override;
    void swap() override;
    GLFWwindow* window() const { return window_; }

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace dsr
