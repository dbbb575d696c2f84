// What `dsr --help`, `dsr COMMAND --help` and docs/cli.md say, printed from the command tables
// (command_table.h), the renderer option table (deferred/option_table.h) and the --caps table
// (gl/cap_names.h): nothing here lists a flag by hand.
#pragma once
#include <string>

#include "app/command_line.h"

namespace dsr {

// `dsr NAME --help`: "usage: dsr NAME ...", the summary, the options (the renderer's too where the
// command takes them) and the command's notes.
std::string command_help(const Command& c);

// `dsr --help`: every command's synopsis and summary.
std::string top_help();

// docs/cli.md: every command, its flags, values, defaults and help; the renderer options; the
// --caps names. `dsr help --markdown` prints it; `make docs-cli` writes it.
std::string cli_markdown();

// One line, no newline: "dsr: unknown command 'x' (expected render, ...; dsr --help lists them)".
std::string unknown_command_line(const std::string& name);

// True for "--help" and "-h".
bool is_help_flag(const std::string& arg);

}  // namespace dsr
