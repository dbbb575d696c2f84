// libFuzzer target for the command line (`make fuzz`): the input is argv, arguments separated by
// NUL bytes, read as `dsr render` reads its flags: the option table's renderer flags through
// parse_render_flag (app/render_flags.h) and the value helpers of app/args.h. A dsr::Error is a
// correct answer; a crash, sanitizer report, leak or hang is a finding, and so is a parse that
// leaves an option at a value its own table refuses, or an empty value taken.
// Written against those two stable entry points rather than a command's own loop, so it keeps
// compiling while the commands' flag parsing changes shape.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/args.h"
#include "app/render_flags.h"
#include "deferred/option_table.h"
#include "dsr_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> argv;
    std::string cur;
    for (size_t i = 0; i < size && argv.size() < 64; ++i) {
        if (data[i] == 0) {
            argv.push_back(cur);
            cur.clear();
        } else {
            cur += char(data[i]);
        }
    }
    if (!cur.empty() || (size && data[size - 1] == 0 && argv.size() < 64)) argv.push_back(cur);
    dsr::RenderOptions ro;
    try {
        dsr::Args args("render", argv);
        int w = 0, h = 0;
        while (!args.done()) {
            const std::string a = args.next();
            if (dsr::parse_render_flag(args, a, ro)) continue;
            if (a == "--size" || a == "--out-size") {
                args.size_value(a, w, h);
                if (w < 1 || h < 1 || w > 8192 || h > 8192) __builtin_trap();
            } else if (a == "--frames") {
                const int n = args.int_value(a, 1, 100000);
                if (n < 1 || n > 100000) __builtin_trap();
            } else if (a == "--threshold") {
                const float f = args.float_value(a, 0.0f, 255.0f);
                if (!(f >= 0 && f <= 255)) __builtin_trap();
            } else if (a == "--gl-state-cache") {
                args.on_off(a);
            } else if (a == "--tile-plan") {
                const std::string v = args.choice(a, {"lists", "groups"});
                if (v != "lists" && v != "groups") __builtin_trap();
            } else if (a == "-o" || a == "--stats" || a == "--caps" || a == "--context") {
                if (args.value(a).empty()) __builtin_trap();  // an empty value is an error, not "off"
            } else if (!a.empty() && a[0] == '-') {
                args.fail("unknown option '" + a + "'");
            }
        }
    } catch (const dsr::Error&) {
    }
    // Whatever was parsed (and kept when a later flag failed) is a value the table takes.
    for (const dsr::RenderOption& o : dsr::render_options())
        if (!dsr::check_render_option(o, o.get(ro)).empty()) __builtin_trap();
    return 0;
}
