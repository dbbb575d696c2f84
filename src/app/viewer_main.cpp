// dsr_view: `dsr view`'s executable (it links the system libGL through GLFW, so it cannot be
// `dsr` itself, which links libOSMesa; `dsr view` runs this file beside it). Parses the
// command line by the view command's table (app/command_table.h); the viewer is in src/viewer/.
#include <cstdio>
#include <string>
#include <vector>

#include "app/command_table.h"
#include "app/help_text.h"
#include "analysis/terminal_text.h"
#include "dsr_error.h"
#include "scene/scene.h"
#include "scene/user_file.h"
#include "gl/check.h"
#include "gl/state.h"
#include "viewer/viewer.h"

namespace dsr {

int cmd_view(const std::vector<std::string>& argv) {
    ViewerConfig cfg;
    apply_gl_environment();  // the GL switches' defaults, before the flags
    cfg.options.shader.light_cost_scale = light_cost_scale_from_environment();  // --light-cost-scale's default
    parse_command_line(view_command(cfg), argv);
    cfg.caps_list = caps_with_environment(cfg.caps_list);
    return run_viewer(cfg);
}

}  // namespace dsr

int main(int argc, char** argv) {
    // A model's warnings name its path: fitted to the terminal like the rest of the output.
    dsr::set_warning_printer(dsr::print_wrapped_warning);
    const std::vector<std::string> args(argv + 1, argv + argc);
    for (const std::string& a : args)
        if (dsr::is_help_flag(a)) {
            std::fputs(dsr::command_help(*dsr::find_command("view")).c_str(), stdout);
            return 0;
        }
    try {
        return dsr::cmd_view(args);
    } catch (const dsr::Error& e) {
        std::fprintf(stderr, "%s\n", dsr::one_line(e.what()).c_str());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", dsr::one_line(std::string("dsr view: ") + e.what()).c_str());
        return 1;
    }
}
