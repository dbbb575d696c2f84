// The renderer flags of the option table (deferred/option_table.h) on a command line: every
// flag of `render` and `view` the table has (parse_command_line, command_line.h), and bench's
// --tile-* (option_flag).
#pragma once
#include <string>

#include "app/args.h"
#include "deferred/option_table.h"

namespace dsr {

// When `a` is one of the table's flags, reads its value (if it takes one) from `args`, sets it
// in `ro` and returns true; a bad value is args.fail's one line ("--depth: expected ..."). False
// when `a` is not in the table.
bool parse_render_flag(Args& args, const std::string& a, RenderOptions& ro);

}  // namespace dsr
