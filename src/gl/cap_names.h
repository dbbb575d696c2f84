// The capabilities `--caps` (and $DSR_CAPS) can hide, in one table: each name, the extension or
// feature it hides and what then runs instead. probe_caps (caps.cpp) reads these names, the
// command line checks them, and `--help` and docs/cli.md list them. Pure data, no GL.
#pragma once
#include <string>
#include <vector>

namespace dsr {

struct CapName {
    const char* name;    // "no-mrt"
    const char* hides;   // "ARB_draw_buffers"
    const char* effect;  // what dsr does without it
};

// Every name, in the order help lists them.
const std::vector<CapName>& cap_names();

// True when `name` is in the table.
bool is_cap_name(const std::string& name);

// "" when every name is in the table, else the first unknown one's error:
// "unknown capability 'x' (expected no-mrt, ..., no-depth-bounds or no-framebuffer-blit)".
std::string check_cap_names(const std::vector<std::string>& names);

// "no-mrt,,no-fbo" -> {"no-mrt", "no-fbo"}: the --caps / $DSR_CAPS list, empty items dropped.
std::vector<std::string> split_caps(const std::string& list);

}  // namespace dsr
