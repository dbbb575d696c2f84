// libFuzzer target for the viewer's --script parser (`make fuzz`): the input is a script's text.
// A dsr::Error is a correct answer when it is one line of bounded length (tokens are echoed at
// most 60 characters); a crash, sanitizer report, leak, hang, a long or multi-line message, or a
// parsed command outside its documented range is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "deferred/option_table.h"
#include "dsr_error.h"
#include "scene/image.h"
#include "viewer/script.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const dsr::Script s = dsr::parse_script(text, "fuzz.script");
        int last = 0;
        for (const dsr::ScriptCommand& c : s.commands) {
            if (c.line <= last) __builtin_trap();  // lines in order, from 1
            last = c.line;
            switch (c.kind) {
                case dsr::ScriptCommand::size:
                    if (c.w < 0 || c.h < 0 || c.w > 8192 || c.h > 8192 || (c.w == 0) != (c.h == 0)) __builtin_trap();
                    break;
                case dsr::ScriptCommand::frames:
                    if (c.count < 1 || c.count > 1000000) __builtin_trap();
                    break;
                case dsr::ScriptCommand::set:
                    if (const dsr::RenderOption* o = dsr::find_render_option(c.name))
                        if (!dsr::check_render_option(*o, c.value).empty()) __builtin_trap();
                    break;
                case dsr::ScriptCommand::screenshot:
                    if (dsr::image_extension(c.value).empty()) __builtin_trap();
                    break;
                case dsr::ScriptCommand::camera:
                    for (int i = 0; i < 3; ++i)
                        if (!(c.pos[i] == c.pos[i]) || !(c.target[i] == c.target[i]) || !(c.up[i] == c.up[i])) __builtin_trap();
                    break;
                case dsr::ScriptCommand::quit: break;
                case dsr::ScriptCommand::wait:  // documented as the last command only
                    if (&c != &s.commands.back()) __builtin_trap();
                    break;
            }
        }
    } catch (const dsr::Error& e) {
        const std::string m = e.what();
        if (m.find('\n') != std::string::npos || m.find('\r') != std::string::npos || m.size() > 1024) __builtin_trap();
    }
    return 0;
}
