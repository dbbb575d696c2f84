// Hostile viewer scripts (`dsr view --script FILE`): read whole and checked before the window
// opens, through the same reader as scene files. The cases that need the window (a screenshot
// path checked against the run's inputs once the scene is loaded) run under an Xvfb of the
// suite's own, and are skipped, saying why, where there is none.
#include <string>
#include <vector>

#include "hostile.h"

namespace dsr::hostile {
namespace {

using D = const std::string&;

// `dsr view a.scene --script s.script`, the script's text `text`.
Case bad_script(const std::string& name, const std::string& text, const std::string& expect) {
    return {name,
            [text](D d) {
                write(d, "a.scene", scene_text());
                write(d, "s.script", text);
            },
            "view a.scene --size 32x32 --script s.script", expect};
}

// A script that runs in a window: screenshots, then quit.
Case window_script(const std::string& name, const std::string& text, std::function<void(D)> more, const std::string& expect) {
    return {name,
            [text, more](D d) {
                write(d, "a.scene", scene_text("", " diffuse_map t.png"));
                image(d, "t.png", 8, 8);
                write(d, "s.script", text);
                if (more) more(d);
            },
            "view a.scene --size 32x32 --script s.script", expect, 1, true};
}

std::vector<Case> cases() {
    std::vector<Case> c;
    const std::string scene = scene_text();
    // ---- not a file
    c.push_back({"fifo", [](D d) { write(d, "a.scene", scene_text()); fifo(d, "s.script"); }, "view a.scene --script s.script",
                 "cannot open viewer script s.script: expected a regular file, got a FIFO"});
    c.push_back({"directory", [](D d) { write(d, "a.scene", scene_text()); folder(d, "s.script"); }, "view a.scene --script s.script",
                 "cannot open viewer script s.script: expected a file, got a directory"});
    c.push_back({"dev_zero", [](D d) { write(d, "a.scene", scene_text()); }, "view a.scene --script /dev/zero",
                 "cannot open viewer script /dev/zero: expected a regular file, got a character device"});
    c.push_back({"missing", [](D d) { write(d, "a.scene", scene_text()); }, "view a.scene --script none.script",
                 "cannot open viewer script none.script: No such file or directory"});
    c.push_back({"oversize", [](D d) { write(d, "a.scene", scene_text()); sparse(d, "s.script", (16ll << 20) + 1); }, "view a.scene --script s.script",
                 "cannot open viewer script s.script: expected at most 16777216 bytes, got 16777217"});
    c.push_back({"symlink_loop", [](D d) { write(d, "a.scene", scene_text()); symlink_to(d, "s.script", "s.script"); }, "view a.scene --script s.script",
                 "cannot open viewer script s.script: Too many levels of symbolic links"});
    c.push_back({"empty_flag", [](D d) { write(d, "a.scene", scene_text()); }, "view a.scene --script ''", "dsr view: --script: expected a value, got ''"});
    // ---- not text
    c.push_back(bad_script("nul", std::string("frames 1\nset scissor o\0ff\n", 26), "s.script:2: expected text, got a NUL byte at column 14"));
    c.push_back(bad_script("escape_byte", "frames 1\x1b\n", "s.script:1: expected text, got the control byte 0x1B at column 9"));
    c.push_back(bad_script("bom_then_bad", "\xEF\xBB\xBF" "frames x\n", "s.script:1: frames: expected an integer in [1, 1000000], got 'x'"));
    c.push_back(bad_script("lone_cr", "frames 1\rfly away\r", "s.script:2: expected size, camera, set, frames, screenshot, quit or wait, got 'fly'"));
    // ---- long tokens and values
    c.push_back(bad_script("long_command", std::string(1 << 20, 'z') + "\n", "s.script:1: expected size, camera, set, frames, screenshot, quit or wait, got 'zzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzz...'"));
    c.push_back(bad_script("long_set_value", "set bloom-strength " + std::string(100000, '9') + "\n", "s.script:1: set bloom-strength: expected a value, got '999999999999999999999999999999999999999999999999999999999999...'"));
    c.push_back(bad_script("long_frames", "frames " + std::string(10000, '1') + "\n", "s.script:1: frames: expected an integer in [1, 1000000], got '111111111111111111111111111111111111111111111111111111111111...'"));
    c.push_back(bad_script("long_line_echo", "size 1 2 " + std::string(5000, '3') + "\n", "s.script:1: expected 'size W H', got 'size 1 2 333333333333333333333333333333333333333333333333333...'"));
    // ---- values
    c.push_back(bad_script("camera_huge", "camera pos 0 0 1e13 target 0 0 0 up 0 1 0\n", "s.script:1: camera pos: expected a finite number, got '1e13'"));
    c.push_back(bad_script("size_huge", "size 100000 10\n", "s.script:1: size: expected W H, each in [1, 8192] (or 0 0 to minimise), got '100000 10'"));
    c.push_back(bad_script("screenshot_extension", "screenshot a.scene\n", "s.script:1: screenshot: expected a file ending .png, .exr, .tif, .jpg or .ppm, got 'a.scene'"));
    // ---- screenshots against the run's inputs and folders (in a window)
    c.push_back(window_script("screenshot_is_texture", "screenshot t.png\nquit\n", nullptr,
                              "s.script:1: screenshot: expected a file that is not an input of this run, got 't.png' (a file the scene reads, t.png)"));
    c.push_back(window_script("screenshot_is_scene_link", "screenshot s.png\nquit\n", [](D d) { symlink_to(d, "s.png", "a.scene"); },
                              "s.script:1: screenshot: expected a file that is not an input of this run, got 's.png' (the scene file a.scene)"));
    c.push_back(window_script("screenshot_is_script_hardlink", "frames 1\nscreenshot h.png\nquit\n", [](D d) { hardlink_to(d, "h.png", "s.script"); },
                              "s.script:2: screenshot: expected a file that is not an input of this run, got 'h.png' (the script s.script)"));
    c.push_back(window_script("screenshot_no_folder", "screenshot a.png\nscreenshot nodir/b.png\nquit\n", nullptr,
                              "s.script:2: screenshot: cannot write nodir/b.png: No such file or directory"));
    c.push_back(window_script("screenshot_is_folder", "screenshot a.png\nscreenshot d.png\nquit\n", [](D d) { folder(d, "d.png"); },
                              "s.script:2: screenshot: expected a file to write, got 'd.png', a folder"));
    // A failure after a screenshot was taken: the first one is not left behind.
    c.push_back(window_script("fails_after_a_screenshot", "screenshot a.png\nframes 1\nsize 0 0\nscreenshot b.png\nquit\n", nullptr,
                              "s.script:4: screenshot: the window is minimised (0x0): nothing to capture"));
    return c;
}

INSTANTIATE_TEST_SUITE_P(Script, Hostile, ::testing::ValuesIn(cases()), CaseName());

}  // namespace
}  // namespace dsr::hostile
