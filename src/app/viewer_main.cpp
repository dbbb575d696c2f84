// dsr_view: `dsr view`'s executable (it links the system libGL through GLFW, so it cannot be
// `dsr` itself, which links libOSMesa; `dsr view` runs this file beside it). Parses the
// command line and prints; the viewer is in src/viewer/.
#include <cstdio>
#include <string>
#include <vector>

#include "app/args.h"
#include "app/render_flags.h"
#include "app/usage.h"
#include "dsr_error.h"
#include "scene/user_file.h"
#include "gl/check.h"
#include "gl/state.h"
#include "viewer/viewer.h"

namespace dsr {

int cmd_view(const std::vector<std::string>& argv) {
    Args args("view", argv);
    ViewerConfig cfg;
    while (!args.done()) {
        std::string a = args.next();
        if (a == "--size") args.size_value(a, cfg.width, cfg.height);
        else if (parse_render_flag(args, a, cfg.options)) continue;
        else if (a == "--caps") cfg.caps_list += "," + args.value(a);
        else if (a == "--script") cfg.script_path = args.value(a);
        else if (a == "--gl-state-cache") gl_state().set_cache(args.on_off(a));
        else if (a == "--debug-gl") set_debug_gl(true);
        else if (!a.empty() && a[0] == '-') args.fail("unknown option '" + a + "'");
        else if (cfg.scene_path.empty()) cfg.scene_path = a;
        else args.fail("expected one scene file, got also '" + a + "'");
    }
    return run_viewer(cfg);
}

}  // namespace dsr

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    for (const std::string& a : args)
        if (dsr::is_help_flag(a)) {
            std::fputs(dsr::command_usage_text(*dsr::find_command_usage("view")).c_str(), stdout);
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
