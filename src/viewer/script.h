// The viewer's `--script FILE`: one command per line, so it runs without a person (the tests
// drive it this way under Xvfb). Parsed whole before the window opens, so a bad line is one
// error naming FILE:LINE and nothing runs. Pure: no GL, no window.
//
//   size W H                                  resize the window (0 0: minimise)
//   camera pos X Y Z target X Y Z up X Y Z    place the camera (fov, near, far stay the scene's)
//   set NAME VALUE                            a renderer option by its `render` flag name, or
//                                             panel|overlay|animate on|off (the viewer's own)
//   frames N                                  render N frames
//   screenshot FILE                           the deferred image (no panel), written with the image seam
//   screenshot FILE panel                     the window as shown: the image with the panel and
//                                             overlay drawn over it (where they are on)
//   quit                                      close the viewer
//   wait                                      (last line only) leave the window open for a person
// A script ends when it ends: after its last line the viewer closes, as if `quit` followed,
// unless that line is `wait`. `#` starts a comment; blank lines are skipped.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace dsr {

struct ScriptCommand {
    enum Kind { size, camera, set, frames, screenshot, quit, wait } kind;
    int line = 0;                        // 1-based, for FILE:LINE in errors while it runs
    int w = 0, h = 0;                    // size
    glm::vec3 pos{0}, target{0}, up{0};  // camera
    std::string name, value;             // set (checked against the option table); screenshot: value = FILE
    bool with_panel = false;             // screenshot: FILE panel
    int count = 0;                       // frames
};

struct Script {
    std::string path;
    std::vector<ScriptCommand> commands;
    // "FILE:LINE: " for error messages.
    std::string where(const ScriptCommand& c) const { return path + ":" + std::to_string(c.line) + ": "; }
    // Whether the viewer stays open after the last command (it ends with `wait`); otherwise the
    // script's end closes it.
    bool waits() const { return !commands.empty() && commands.back().kind == ScriptCommand::wait; }
};

// The viewer's own settings `set` takes beside the option table's (each on|off).
const std::vector<std::string>& viewer_settings();

// Throws dsr::Error "FILE:LINE: expected ..., got '...'" on the first bad line, or when the file
// cannot be read. The file goes through the user-file reader (scene/user_file.h): regular files
// of at most kMaxScriptBytes, a byte-order mark skipped, control bytes refused.
Script parse_script(std::string text, const std::string& path);
Script load_script(const std::string& path);

}  // namespace dsr
