// The renderer's options by name, in one table: each entry's values, range, default and help.
// `dsr render`, `dsr view` and `dsr bench` parse their renderer flags from it (`--NAME VALUE`;
// `--NAME` / `--no-NAME` for the switches), the viewer's `set NAME VALUE` and its panel are
// made from it, and `--help` and docs/cli.md print it (app/help_text.h), so the names, ranges
// and help agree by construction. Adding an option is one entry in option_table.cpp.
// Pure data, no GL.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "deferred/options.h"
#include "deferred/view_names.h"

namespace dsr {

struct Scene;

// What the renderer flags of `dsr render` (and `dsr view`) set.
struct RenderOptions {
    ShaderOptions shader;  // depth `automatic` until choose_paths resolves it
    int bloom = -1, aa = -1;  // -1: as the scene's `post` line says
    View view = View::final;
    RenderOptions() { shader.depth = DepthPath::automatic; }
    // The options a DeferredShader is built with for a scene: bloom/aa from the scene's `post`
    // line where not set; the bloom view needs the bloom pass.
    ShaderOptions resolved(const Scene& scene) const;
};

enum class OptionKind {
    choice,  // one of `values`: --NAME VALUE
    on_off,  // on|off: --NAME on|off
    toggle,  // on|off, given as --NAME / --no-NAME on the command line, `set NAME on|off` in a script
    number,  // a float in [lo, hi]: --NAME X
    integer, // an integer in [lo, hi], or one of `values` (auto): --NAME N
    subset,  // a comma-separated subset of `values` (or `none`): --NAME a,b
};

struct RenderOption {
    std::string name;  // the flag without dashes: `set NAME VALUE`, the panel's label
    OptionKind kind;
    std::vector<std::string> values;  // choice and subset members
    float lo = 0, hi = 0;             // number and integer range
    // True when a change needs a new DeferredShader (other programs or buffer formats); false
    // when the next frame picks it up as it is (the view).
    bool rebuild = true;
    std::function<std::string(const RenderOptions&)> get;  // the value as `set` takes it
    std::function<void(RenderOptions&, const std::string&)> put;  // a value already checked
    std::string help = "";          // what it does, one sentence or two: --help, docs/cli.md, the panel's tooltip
    std::string arg = "";           // number and integer: the value's name in help ("S"); the others derive it
    std::string default_text = "";  // the default where get() of RenderOptions{} would mislead ("the scene's post line")
};

// Entries for a plain ShaderOptions field, so a new option is one line in make_table:
//   t.push_back(switch_option("depth-bounds", &ShaderOptions::depth_bounds));
//   t.push_back(integer_option("tile-size", 8, 512, &ShaderOptions::tile_size));
RenderOption switch_option(std::string name, bool ShaderOptions::*field);  // on|off
// with_auto: also takes `auto`, stored as 0 (a default the GL decides).
RenderOption integer_option(std::string name, int lo, int hi, int ShaderOptions::*field, bool with_auto = false);

// Every option, in the order the panel shows them.
const std::vector<RenderOption>& render_options();
// The skips, one entry each in SkipOptions' order: --no-skip's name ("variants", "empty-lights",
// ...), the field's name (the bench's `skips_off` and `no-NAME` rows: "material_variants", ...) and
// the field. The one list both read.
struct SkipName {
    const char* flag;
    const char* field;
    bool SkipOptions::*on;
};
const std::vector<SkipName>& skip_names();
// The names (`name`: &SkipName::flag or &SkipName::field) of the skips `skip` has turned off, in
// SkipOptions' order.
std::vector<std::string> skip_names_off(const SkipOptions& skip, const char* SkipName::*name);
// The entry of `name` ("scissor", "no-skip", ...), null when there is none.
const RenderOption* find_render_option(const std::string& name);
// The value's error, or "" when it is one `o` takes ("expected on|off, got 'maybe'").
std::string check_render_option(const RenderOption& o, const std::string& value);
// Checks and sets; returns the error as check_render_option does (nothing set then).
std::string set_render_option(RenderOptions& ro, const RenderOption& o, const std::string& value);
// What follows --NAME in help: "auto|texture|...", "on|off", "S", "auto|N", "LIST"; "" for a
// toggle (written --NAME or --no-NAME).
std::string option_arg(const RenderOption& o);
// The range in help's words where option_arg does not show it: "0..16", "8..512",
// "variants, empty-lights, ... (comma-separated) or none"; "" for the others.
std::string option_range(const RenderOption& o);
// The default as help says it: default_text, else get() of RenderOptions{}.
std::string option_default(const RenderOption& o);
// The flags `dsr render` takes for the table ("--depth", "--bloom", "--no-bloom", ...).
std::vector<std::string> render_option_flags();

}  // namespace dsr
