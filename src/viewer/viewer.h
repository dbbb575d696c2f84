// `dsr view`: the same renderer in a GLFW window, with a Dear ImGui panel (viewer_app.cpp,
// viewer_panel.cpp). app/viewer_main.cpp parses the command line into a ViewerConfig by
// the view command's table (app/command_table.h).
#pragma once
#include <optional>
#include <string>

#include "analysis/bench_scenes.h"
#include "deferred/option_table.h"
#include "scene/scene.h"

namespace dsr {

struct ViewerConfig {
    std::string scene_path;  // empty: data/default.scene
    int width = 1280, height = 720;  // the window's framebuffer at start; the deferred buffers follow it
    RenderOptions options;          // the option table's flags
    std::string caps_list;          // $DSR_CAPS and --caps (the app joins them: app/environment.h)
    std::string script_path;        // --script FILE; empty: a person drives it
    std::optional<LightSpec> lights;  // --lights: the bench's generated lights instead of the scene's
    LoadOptions load;                 // --strict, --from, --camera, --ambient
};

// Opens the window and runs until it is closed, Esc, or the script's end (unless its last line
// is `wait`: script.h). Returns the exit status; throws dsr::Error (one line, FILE:LINE for the
// script) on bad input or a failure.
int run_viewer(const ViewerConfig& config);

}  // namespace dsr
