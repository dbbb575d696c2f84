// A command's flags as data. Each Flag says how it is written, what it takes, its default and
// its help, and parses its own value; parse_command_line reads a command line by the table, and
// help_text.h prints `--help` and docs/cli.md from the same table, so the three cannot drift.
// Every bad flag or value is one dsr::Error line naming the flag and what was expected.
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "app/args.h"
#include "deferred/option_table.h"

namespace dsr {

struct Flag {
    std::vector<std::string> names;  // {"-o", "--output"}; help writes them in this order
    std::string arg;                 // what follows: "FILE", "WxH", "on|off"; "" for a switch
    std::string range;               // the values where `arg` does not say them: "1..1000"
    std::string def;                 // the default as help says it; "" when there is none
    std::string help;                // what it does
    std::vector<std::pair<std::string, std::string>> items;  // values explained one a line (--caps)
    std::function<void(Args&, const std::string& flag)> parse;  // reads its value and stores it
};

// A word of the command line that is not a flag: SCENE, DIR, A B.
struct Operand {
    std::string name;  // "SCENE"
    std::string help;
    bool optional = false;  // written [SCENE] in the synopsis
};

struct Command {
    std::string name;     // render, figures, ...
    std::string summary;  // one line: what the command does
    std::vector<Operand> operands;
    std::function<void(Args&, const std::string& word)> operand;  // null: the command takes none
    std::vector<Flag> flags;
    RenderOptions* renderer = nullptr;  // render, view: the option table's flags too, into *renderer
    std::string notes;                  // after the options in --help and docs/cli.md (view's keys)
};

// Reads `argv` into the settings the command's flags write: each flag by its parse, the option
// table's when the command takes them, operands by `operand`. Throws dsr::Error ("dsr NAME: ...").
void parse_command_line(const Command& c, const std::vector<std::string>& argv);

// Flags for the common kinds. Each reads its default from the field it writes (the settings are
// fresh when a table is made), unless `def` says otherwise.
Flag text_flag(std::vector<std::string> names, std::string arg, std::string& field, std::string help, std::string def = "");
Flag switch_flag(std::string name, bool& field, std::string help);  // present: true
Flag int_flag(std::string name, std::string arg, int lo, int hi, int& field, std::string help, std::string def = "");
Flag float_flag(std::string name, std::string arg, float lo, float hi, double& field, std::string help, std::string def = "");
Flag size_flag(std::string name, int& w, int& h, std::string help, std::string def = "");  // WxH
Flag choice_flag(std::string name, const std::vector<std::string>& values, std::string& field, std::string help,
                 std::string def = "");
// A comma-separated subset of `values`, in the order given.
Flag list_flag(std::string name, std::string arg, const std::vector<std::string>& values, std::vector<std::string>& field,
               std::string help, std::string def = "");
// An entry of the option table as a command's own flag, writing into `into` (bench's --tile-size):
// its values, range, default and help from the table.
Flag option_flag(const std::string& option, RenderOptions& into);

// The flag among `c.flags` written `word`; null when none is.
const Flag* find_flag(const Command& c, const std::string& word);

}  // namespace dsr
