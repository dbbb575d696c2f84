// dsr: the tutorial's deferred shading renderer, headless under OSMesa.
#include <cstdio>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/stage.h"
#include "app/usage.h"
#include "dsr_error.h"
#include "scene/user_file.h"

namespace {

struct Command {
    const char* name;
    int (*run)(const std::vector<std::string>&);
};

// Every entry of dsr::command_usages() (usage.cpp) has its function here.
const Command kCommands[] = {
    {"render", dsr::cmd_render}, {"figures", dsr::cmd_figures}, {"bench", dsr::cmd_bench},
    {"stress", dsr::cmd_stress}, {"info", dsr::cmd_info},       {"gen-textures", dsr::cmd_gen_textures},
    {"compare", dsr::cmd_compare},      {"view", dsr::cmd_view},
};

}  // namespace

int main(int argc, char** argv) {
    const std::string first = argc < 2 ? "" : argv[1];
    if (argc < 2 || dsr::is_help_flag(first) || first == "help") {
        // `dsr help COMMAND`: that command's usage.
        const dsr::CommandUsage* u = argc > 2 && first == "help" ? dsr::find_command_usage(argv[2]) : nullptr;
        std::fputs(u ? dsr::command_usage_text(*u).c_str() : dsr::top_usage_text().c_str(), argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    const std::string cmd = first;
    const std::vector<std::string> args(argv + 2, argv + argc);
    const dsr::CommandUsage* usage = dsr::find_command_usage(cmd);
    int (*run)(const std::vector<std::string>&) = nullptr;
    for (const Command& c : kCommands)
        if (cmd == c.name) run = c.run;
    if (!usage || !run) {
        std::fprintf(stderr, "%s\n", dsr::one_line(dsr::unknown_command_line(cmd)).c_str());
        return 2;
    }
    for (const std::string& a : args)
        if (dsr::is_help_flag(a)) {
            std::fputs(dsr::command_usage_text(*usage).c_str(), stdout);
            return 0;
        }
    // Every error is one line (dsr::one_line), with the stage it left when it came from inside
    // the renderer (app/stage.h).
    try {
        return run(args);
    } catch (const dsr::Error& e) {
        // A message that names the command already is the command's own, not the renderer's.
        const std::string stage = dsr::take_failed_stage(), what = e.what();
        const bool own = what.rfind("dsr ", 0) == 0;
        const std::string msg = stage.empty() || own ? what : "dsr " + cmd + ": " + stage + ": " + what;
        std::fprintf(stderr, "%s\n", dsr::one_line(msg).c_str());
        return 1;
    } catch (const std::exception& e) {
        const std::string stage = dsr::take_failed_stage();
        const std::string msg = "dsr " + cmd + ": " + (stage.empty() ? "" : stage + ": ") + e.what();
        std::fprintf(stderr, "%s\n", dsr::one_line(msg).c_str());
        return 1;
    }
}
