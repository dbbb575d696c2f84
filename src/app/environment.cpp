// The environment variables dsr honours (environment.h).
#include "app/environment.h"

#include <cstdlib>

#include "app/command_table.h"
#include "deferred/light_cost.h"
#include "gl/check.h"
#include "gl/frame_timer.h"
#include "gl/state.h"

namespace dsr {

namespace {
std::string env(const char* name) {
    const char* e = std::getenv(name);
    return e ? e : "";
}
}  // namespace

std::string caps_with_environment(const std::string& flags) { return env("DSR_CAPS") + "," + flags; }

ContextDesc context_desc(const ContextSettings& c, int width, int height) {
    std::string backend = c.backend;
    if (backend.empty()) backend = env("DSR_CONTEXT");
    if (backend.empty()) backend = default_context_backend();
    int device = c.egl_device;
    if (device < 0) {
        const std::string e = env("DSR_EGL_DEVICE");
        device = e.empty() ? 0 : std::atoi(e.c_str());
    }
    return ContextDesc{backend, width, height, device};
}

std::optional<std::array<double, 3>> light_cost_scale_from_environment() {
    const std::string e = env("DSR_LIGHT_COST_SCALE");
    if (e.empty()) return std::nullopt;
    return parse_cost_scale(e);  // its error names the variable
}

void apply_gl_environment() {
    if (env("DSR_GL_STATE_CACHE") == "off") gl_state().set_cache(false);
    const std::string debug = env("DSR_DEBUG_GL");
    if (!debug.empty() && debug != "0") set_debug_gl(true);
    const std::string timing = env("DSR_TIMING");
    if (timing == "wall") set_timing_choice(TimingChoice::wall);
    if (timing == "gpu-timer") set_timing_choice(TimingChoice::gpu_timer);
}

}  // namespace dsr
