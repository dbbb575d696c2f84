// The shader table (Doom 3's program table, { type, name, "interaction.vfp" }): one row per
// program the deferred shader can draw with, its GLSL files and its defines as a function of the
// configuration. Every program a configuration uses is compiled and linked when the
// DeferredShader is built, so a shader that does not compile fails at start-up, never mid-frame;
// each stage then takes its own programs out of the set. `dsr info` prints the table.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "deferred/options.h"
#include "deferred/paths.h"
#include "gl/caps.h"
#include "gl/program.h"

namespace dsr {

// What the rows are a function of: the capabilities, the options as run (choose_paths resolved
// the depth path and the tiles' sizes) and the paths chosen, and what the tiles geometry measured
// on this GL.
struct ShaderConfig {
    Caps caps;
    ShaderOptions opts;
    Paths paths;
    // tiles only (0 / unmeasured otherwise): the lights light_tiles.frag holds in its uniform
    // arrays, and how this GL rounds into RGBA8 (gl/rounding_probe.h): the truncation bits of
    // the model that fits (-1: none does, the shader then adds tile_round before rounding down).
    int tile_batch = 0;
    bool rounding_measured = false;
    int rounding_bits = -1;
    float tile_round = 0.5f;
    // tiles, screen and auto in scenes with shadowed lights: the shadowed lights a batch holds
    // (shadow.glsl SHADOW_SLOTS, their maps on units 4 ..), kShadowSlots or fewer where the texture
    // units or the uniform budget hold fewer; 0: none (they are drawn as quads instead).
    int shadow_slots = 0;
};

// The most shadowed lights a batched light pass holds (shadow.glsl SHADOW_SLOTS).
constexpr int kShadowSlots = 8;
// The first of the units the light passes bind shadow maps on (units 0-3: the G-buffer).
constexpr int kShadowUnit = 4;

// choose_paths and, for the tiles geometry, the two measurements. Needs a current context for
// tiles; throws dsr::Error with choose_paths' refusal.
ShaderConfig shader_config(const Caps& caps, const ShaderOptions& opts);

using Defines = std::vector<std::string>;

// glsl120/shadow.glsl's lookup: SHADOW, SHADOW_PACKED for maps packed in RGB8, and the filter's
// define (options.h ShadowFilter). The light programs' shadow rows and the transparent pass's
// shadow form both compile it with these.
Defines shadow_lookup_defines(bool packed, ShadowFilter filter);

// The shader forms of what a model brings (gpu_scene.h SurfaceBits): TWO_SIDED (a back face's
// normal flipped, gl_FrontFacing), VERTEX_COLOR (per-vertex colour times diffuse and coverage),
// CUT_OUT (coverage below the `alpha_cutoff` uniform discarded). The material pass, the shadow
// casters, the forward renderers and the transparent pass add them to their own rows' defines
// (ProgramSources::build) for the surfaces that have them; a surface without any draws with the
// rows as they are. The shadow casters take only CUT_OUT and VERTEX_COLOR (they draw both faces).
Defines surface_defines(int surface);

// The tiles' depth culling (tile_depth.h): whether the configuration has it, and whether its
// spans come from the G-buffer read back to the CPU (a CPU rasteriser with the depth texture)
// rather than from its two passes, whose programs are then not in the table's set.
bool tile_depth_culling(const ShaderConfig& c);
bool tile_spans_by_readback(const ShaderConfig& c);

// log_luminance.frag's taps per side of each block it reduces (final_stage.h).
constexpr int kLogLuminanceTaps = 4;

struct ShaderRow {
    const char* name;
    const char* vert;
    const char* frag;
    const char* role;                          // what it draws, in a few words (dsr info)
    bool (*used)(const ShaderConfig&);         // this configuration draws with it
    Defines (*defines)(const ShaderConfig&);
    // Without MRT (§3.2, "rendering one pass per buffer"): one program per G-buffer target,
    // named "name/t", with TARGET_t defined.
    bool per_target = false;
};

const std::vector<ShaderRow>& shader_rows();

// One program of the configuration: a used row with its defines, per target where it says so.
struct ProgramSpec {
    std::string name, vert, frag, role;
    Defines defines;
};
std::vector<ProgramSpec> shader_programs(const ShaderConfig& config);
// One line per program: name, files, defines (dsr info).
std::string describe_programs(const ShaderConfig& config);

// Some of a configuration's programs as the table gives them, kept to compile variants later: a
// stage that needs a define the table cannot know in advance (the screen geometry's light count)
// builds the program with it when it first needs it.
class ProgramSources {
public:
    ProgramSources(std::string shader_dir, std::vector<ProgramSpec> specs) : dir_(std::move(shader_dir)), specs_(std::move(specs)) {}
    bool has(const std::string& name) const;
    // The program `name` with `extra` defines after the table's; throws dsr::Error when it is not here.
    Program build(const std::string& name, const Defines& extra) const;

private:
    std::string dir_;
    std::vector<ProgramSpec> specs_;
};

// Every program of shader_programs(config), compiled and linked; each stage takes its own.
class ProgramSet {
public:
    // `only`: just these programs (empty: all of them).
    ProgramSet(const std::string& shader_dir, const ShaderConfig& config, const std::vector<std::string>& only = {});
    bool has(const std::string& name) const { return programs_.count(name) != 0; }
    // Moves the program out; throws dsr::Error when the table did not build it here.
    Program take(const std::string& name);
    size_t size() const { return programs_.size(); }
    // The specs of the programs built here whose names start with `prefix`, taken or not.
    ProgramSources sources(const std::string& prefix) const;

private:
    std::string dir_;
    std::vector<ProgramSpec> specs_;  // of the programs built
    std::map<std::string, Program> programs_;
};

}  // namespace dsr
