// dsr: the tutorial's deferred shading renderer, headless under OSMesa.
#include <cstdio>
#include <string>
#include <vector>

#include "app/command_table.h"
#include "app/commands.h"
#include "app/help_text.h"
#include "app/stage.h"
#include "analysis/terminal_text.h"
#include "dsr_error.h"
#include "scene/scene.h"
#include "scene/user_file.h"

namespace {

struct Run {
    const char* name;
    int (*run)(const std::vector<std::string>&);
};

// Every entry of dsr::command_table() (command_table.cpp) has its function here.
const Run kRuns[] = {
    {"render", dsr::cmd_render}, {"figures", dsr::cmd_figures}, {"bench", dsr::cmd_bench},
    {"stress", dsr::cmd_stress}, {"info", dsr::cmd_info},       {"gen-textures", dsr::cmd_gen_textures},
    {"compare", dsr::cmd_compare},      {"view", dsr::cmd_view},
    {"gen-model", dsr::cmd_gen_model},  {"hdr", dsr::cmd_hdr},
};

}  // namespace

int main(int argc, char** argv) {
    // A model's warnings name its path: fitted to the terminal like the rest of the output.
    dsr::set_warning_printer(dsr::print_wrapped_warning);
    const std::string first = argc < 2 ? "" : argv[1];
    if (argc < 2 || dsr::is_help_flag(first) || first == "help") {
        // `dsr help COMMAND`: that command's usage; `dsr help --markdown`: docs/cli.md.
        const std::string topic = argc > 2 && first == "help" ? argv[2] : "";
        if (topic == "--markdown") {
            std::fputs(dsr::cli_markdown().c_str(), stdout);
            return 0;
        }
        const dsr::Command* c = topic.empty() ? nullptr : dsr::find_command(topic);
        if (!topic.empty() && !c) {
            std::fprintf(stderr, "%s\n", dsr::unknown_command_line(topic).c_str());
            return 2;
        }
        std::fputs(c ? dsr::command_help(*c).c_str() : dsr::top_help().c_str(), argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    const std::string cmd = first;
    const std::vector<std::string> args(argv + 2, argv + argc);
    const dsr::Command* command = dsr::find_command(cmd);
    int (*run)(const std::vector<std::string>&) = nullptr;
    for (const Run& r : kRuns)
        if (cmd == r.name) run = r.run;
    if (!command || !run) {
        std::fprintf(stderr, "%s\n", dsr::one_line(dsr::unknown_command_line(cmd)).c_str());
        return 2;
    }
    for (const std::string& a : args)
        if (dsr::is_help_flag(a)) {
            std::fputs(dsr::command_help(*command).c_str(), stdout);
            return 0;
        }
    // Every error is one line (dsr::one_line), with the stage it left when it came from inside
    // the renderer (app/stage.h).
    try {
        dsr::apply_gl_environment();  // the GL switches' defaults (app/environment.h), before the flags
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
