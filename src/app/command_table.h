// Every dsr command's flags as data (command_line.h): each command's settings, with the default
// written beside each field, and the table that parses a command line into them. `dsr COMMAND
// --help`, `dsr --help` and docs/cli.md are printed from these tables (help_text.h); the
// renderer's own options come from deferred/option_table.h, the --caps names from gl/cap_names.h.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "analysis/bench_scenes.h"
#include "app/command_line.h"
#include "app/environment.h"
#include "deferred/option_table.h"
#include "platform/context.h"
#include "viewer/viewer.h"

namespace dsr {

// --context and --egl-device: resolved by the command ($DSR_CONTEXT, $DSR_EGL_DEVICE) when not
// given (app/environment.h context_desc).
struct ContextSettings {
    std::string backend;  // empty: $DSR_CONTEXT, else the build's first backend (osmesa)
    int egl_device = -1;  // -1: $DSR_EGL_DEVICE, else 0
};

// The folder the commands' default outputs go under, made when missing (git ignores it): a
// run without -o never writes into the checkout's own files.
inline constexpr const char* kOutDir = "out";

struct RenderSettings {
    std::string scene;                // empty: data/default.scene
    std::string out;                  // -o; empty: output()'s default
    int width = 512, height = 512;    // --size: the G-buffer and P-buffers
    int out_width = 0, out_height = 0;  // --out-size; 0: --size
    int frames = 1;
    std::string stats;                // --stats FILE.json; empty: none
    std::optional<LightSpec> lights;  // --lights; none: the scene's own
    LoadOptions load;                 // --strict, --from, --camera, --ambient
    RenderOptions options;            // the option table's flags
    std::string caps;                 // --caps, added to $DSR_CAPS
    ContextSettings context;
    // The image to write: -o, else out/<the scene file's stem>.png (out/default.png for the
    // default scene, out/bunny.png for bunny.obj).
    std::string output() const;
};

struct FiguresSettings {
    std::string scene;               // empty: data/default.scene (and the figures only it has)
    std::string dir = std::string(kOutDir) + "/figures";  // -o; `make figures` writes docs/figures
    int size = 512;                  // square
    ContextSettings context;
};

struct BenchSettings {
    std::string scene;            // empty: data/default.scene, tests/data/analytic.scene and a large mesh
    bool quick = false;
    std::string json;             // empty: not written
    std::string report = "out/bench.md";  // the full table, every goal's working, the notes; a plot beside it
    int width = 0, height = 0;    // 0: the sweep's default (bench::Config), or --quick's
    int frames = 0;               // 0: as width
    std::string lights;           // empty: kBenchLights, or kQuickLights
    std::vector<std::string> geometries = find_render_option("light-geometry")->values;  // all, in the table's order
    RenderOptions tiles;          // the tiles rows' --tile-size, --tile-lights, --tile-plan, --tile-depth
    ContextSettings context;
    // The light sets of a full sweep and of --quick, and --quick's size and frames.
    static constexpr const char* kBenchLights = "own,32,256,1024,1024-overlap,32-large";
    static constexpr const char* kQuickLights = "own,32,256";
    static constexpr int kQuickSize = 128, kQuickFrames = 11, kQuickWarmup = 1;
    static_assert(kQuickWarmup == 1, "--quick's help says one quiet warm-up frame");
};

struct StressSettings {
    bool quick = false;
    std::string json, report, plot, only;
    std::string geometry;         // --light-geometry; empty: each case's own (quad)
    ContextSettings context;
};

struct InfoSettings {
    std::string caps;
    ContextSettings context;
};

struct HdrSettings {
    int size = 256;               // square
    int frames = 5;               // timed frames per configuration, after one warm-up
    std::string caps;
    ContextSettings context;
};

struct CompareSettings {
    std::vector<std::string> files;
    double threshold_lsb = 2.0;
    double max_lsb = -1.0;        // -1: no limit
};

struct GenTexturesSettings {
    std::string dir;
};

struct GenModelSettings {
    std::string dir;
};

Command render_command(RenderSettings& s);
Command figures_command(FiguresSettings& s);
Command bench_command(BenchSettings& s);
Command stress_command(StressSettings& s);
Command info_command(InfoSettings& s);
Command hdr_command(HdrSettings& s);
Command gen_textures_command(GenTexturesSettings& s);
Command gen_model_command(GenModelSettings& s);
Command compare_command(CompareSettings& s);
Command view_command(ViewerConfig& s);  // dsr_view's (app/viewer_main.cpp)

// Every command, in the order `dsr --help` and docs/cli.md list them, each bound to settings of
// its own that only help reads.
const std::vector<Command>& command_table();
// The entry of `name`; null for an unknown command.
const Command* find_command(const std::string& name);

// --strict, --from, --camera and --ambient: how render and view read a scene or model.
std::vector<Flag> load_flags(LoadOptions& load);

}  // namespace dsr
