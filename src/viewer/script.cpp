#include "viewer/script.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "deferred/option_table.h"
#include "dsr_error.h"
#include "scene/image.h"
#include "scene/user_file.h"

namespace dsr {

namespace {

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
    throw Error(path + ":" + std::to_string(line) + ": " + what);
}

bool to_float(const std::string& s, float& out) {
    if (s.size() > 64) return false;  // not a number, and strtod's time grows with the digits
    char* end = nullptr;
    errno = 0;
    const double d = s.empty() ? 0 : std::strtod(s.c_str(), &end);
    if (s.empty() || errno != 0 || *end != '\0' || !std::isfinite(d) || std::fabs(d) > 1e12) return false;
    out = float(d);
    return true;
}

bool to_int(const std::string& s, long lo, long hi, int& out) {
    if (s.size() > 64) return false;
    char* end = nullptr;
    errno = 0;
    const long n = s.empty() ? 0 : std::strtol(s.c_str(), &end, 10);
    if (s.empty() || errno != 0 || *end != '\0' || n < lo || n > hi) return false;
    out = int(n);
    return true;
}

const char* kCommands = "size, camera, set, frames, screenshot, quit or wait";

}  // namespace

const std::vector<std::string>& viewer_settings() {
    static const std::vector<std::string> s = {"panel", "overlay", "animate"};
    return s;
}

Script parse_script(std::string text, const std::string& path) {
    Script script;
    script.path = path;
    check_user_text(path, text);  // a byte-order mark dropped, control bytes refused
    TextLines lines(text);
    for (std::string_view raw; lines.next(raw);) {
        const int n = lines.number();
        const std::vector<std::string_view> views = split_tokens(raw);
        if (views.empty()) continue;
        const std::vector<std::string> w(views.begin(), views.end());
        // The line as written, for "expected 'size W H', got 'size 640'": its tokens from the first.
        const std::string_view line = raw.substr(size_t(views.front().data() - raw.data()),
                                                 size_t(views.back().data() + views.back().size() - views.front().data()));
        ScriptCommand c{};
        c.line = n;
        const std::string& cmd = w[0];
        auto want_words = [&](size_t count, const char* form) {
            if (w.size() != count) fail(path, n, std::string("expected '") + form + "', got " + quote(line));
        };
        if (cmd == "size") {
            want_words(3, "size W H");
            if (!to_int(w[1], 0, 8192, c.w) || !to_int(w[2], 0, 8192, c.h) || ((c.w == 0) != (c.h == 0)))
                fail(path, n, "size: expected W H, each in [1, 8192] (or 0 0 to minimise), got " + quote(w[1] + " " + w[2]));
            c.kind = ScriptCommand::size;
        } else if (cmd == "camera") {
            want_words(13, "camera pos X Y Z target X Y Z up X Y Z");
            const char* keys[3] = {"pos", "target", "up"};
            glm::vec3* dst[3] = {&c.pos, &c.target, &c.up};
            for (int k = 0; k < 3; ++k) {
                if (w[1 + 4 * k] != keys[k])
                    fail(path, n, std::string("camera: expected '") + keys[k] + "', got " + quote(w[1 + 4 * k]));
                for (int i = 0; i < 3; ++i)
                    if (!to_float(w[2 + 4 * k + i], (*dst[k])[i]))
                        fail(path, n, std::string("camera ") + keys[k] + ": expected a finite number, got " +
                                          quote(w[2 + 4 * k + i]));
            }
            if (glm::length(c.target - c.pos) <= 0 || glm::length(glm::cross(c.target - c.pos, c.up)) <= 0)
                fail(path, n, "camera: expected target apart from pos and up not along the view direction");
            c.kind = ScriptCommand::camera;
        } else if (cmd == "set") {
            want_words(3, "set NAME VALUE");
            const RenderOption* o = find_render_option(w[1]);
            bool own = false;
            for (const std::string& v : viewer_settings()) own |= w[1] == v;
            if (!o && !own) {
                std::string names;
                for (const RenderOption& r : render_options()) names += (names.empty() ? "" : ", ") + r.name;
                for (const std::string& v : viewer_settings()) names += ", " + v;
                fail(path, n, "set: expected an option name (" + names + "), got " + quote(w[1]));
            }
            // The option table echoes a bad value whole: a long one is refused here, cut.
            if (w[2].size() > 64) fail(path, n, "set " + w[1] + ": expected a value, got " + quote(w[2]));
            const std::string err = o ? check_render_option(*o, w[2])
                                      : w[2] == "on" || w[2] == "off" ? "" : "expected on|off, got " + quote(w[2]);
            if (!err.empty()) fail(path, n, "set " + w[1] + ": " + one_line(err));
            c.name = w[1];
            c.value = w[2];
            c.kind = ScriptCommand::set;
        } else if (cmd == "frames") {
            want_words(2, "frames N");
            if (!to_int(w[1], 1, 1000000, c.count))
                fail(path, n, "frames: expected an integer in [1, 1000000], got " + quote(w[1]));
            c.kind = ScriptCommand::frames;
        } else if (cmd == "screenshot") {
            if (w.size() != 3) want_words(2, "screenshot FILE [panel]");
            if (w.size() == 3 && w[2] != "panel")
                fail(path, n, "screenshot: expected 'panel' or nothing after FILE, got " + quote(w[2]));
            c.with_panel = w.size() == 3;
            const std::string ext = image_extension(w[1]);
            if (ext != ".png" && ext != ".exr" && ext != ".tif" && ext != ".tiff" && ext != ".jpg" && ext != ".ppm")
                fail(path, n, "screenshot: expected a file ending .png, .exr, .tif, .jpg or .ppm, got " + quote(w[1]));
            c.value = w[1];
            c.kind = ScriptCommand::screenshot;
        } else if (cmd == "quit") {
            want_words(1, "quit");
            c.kind = ScriptCommand::quit;
        } else if (cmd == "wait") {
            want_words(1, "wait");
            c.kind = ScriptCommand::wait;
        } else {
            fail(path, n, std::string("expected ") + kCommands + ", got " + quote(cmd));
        }
        // `wait` keeps the window open after the script: anything after it would never run.
        if (!script.commands.empty() && script.commands.back().kind == ScriptCommand::wait)
            fail(path, script.commands.back().line, "wait: expected as the script's last command, got " +
                                                        quote(cmd) + " on line " + std::to_string(n) + " after it");
        script.commands.push_back(c);
    }
    return script;
}

Script load_script(const std::string& path) { return parse_script(read_user_text(path, "viewer script", kMaxScriptBytes), path); }

}  // namespace dsr
