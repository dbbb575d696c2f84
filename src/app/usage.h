// Each command's usage, in one table: `dsr COMMAND --help` (or -h) prints the command's entry
// and `dsr --help` the top-level usage built from the same table, both from main.cpp before the
// command runs, so no command file parses --help itself.
#pragma once
#include <string>
#include <vector>

namespace dsr {

struct CommandUsage {
    std::string name;                   // render, figures, ...
    std::vector<std::string> synopsis;  // after "dsr NAME ", wrapped: each line an option group
    std::string summary;                // one line: what the command does
    std::string options;                // one line per option, "  FLAG   what it does\n"
};

// Every command, in the order the top-level usage lists them.
const std::vector<CommandUsage>& command_usages();

// The entry of `name`; null for an unknown command.
const CommandUsage* find_command_usage(const std::string& name);

// `dsr NAME --help`: "usage: dsr NAME ...", the summary and the options.
std::string command_usage_text(const CommandUsage& u);

// `dsr --help`: every command's synopsis and summary.
std::string top_usage_text();

// One line, no newline: "dsr: unknown command 'x' (expected render, ...; dsr --help lists them)".
std::string unknown_command_line(const std::string& name);

// True for "--help" and "-h".
bool is_help_flag(const std::string& arg);

}  // namespace dsr
