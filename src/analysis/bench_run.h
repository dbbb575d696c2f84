// The benchmark (`dsr bench`): every configuration of one sweep measured in the same process, on
// the same context, against the same references. Per row: frame time (median, min, max after
// warm-up), light-pass fragments (occlusion queries) and light-shader invocations (pipeline
// statistics) against the ideal count, the frame against its floor (bench_floor.h), and the
// image's error against the forward reference (and, for scenes with constant materials,
// against the analytic one). bench_goals.h judges the goals on the rows; bench_report.h turns them
// into tables, JSON, a plot and a report; src/app/bench_command.cpp only parses flags, runs this,
// and prints or writes what comes back.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/bench_scenes.h"
#include "analysis/image_metrics.h"
#include "deferred/frame_stats.h"
#include "deferred/options.h"
#include "gl/caps.h"
#include "scene/scene.h"

namespace dsr::bench {

// What one sweep measures. Defaults: the full sweep (`dsr bench --quick` sets the small one).
struct Config {
    bool quick = false;
    int w = 512, h = 512;
    bool size_given = false;  // --size given: every variant at w x h (else N-large at the demo's, variant_size)
    int frames = 10, warmup = 2;
    bool frames_given = false;  // --frames given: every variant that many (else N-large kLargeFrameFactor x, variant_frames)
    // Warm-up: until `warmup` frames in a row build no program and explore no path, at most
    // warmup + compile_warmup frames (warm_up).
    int compile_warmup = 12;
    std::vector<int> lights;  // light counts of the sweep; -1: the scene's own lights
    std::vector<LightSet> light_sets;  // parallel to lights (bench_scenes.h); missing: spread
    std::string lights_text;  // --lights as given (or its default), e.g. "own,32,256"
    int tile_size = ShaderOptions{}.tile_size;      // the tiles rows' --tile-size and --tile-lights
    int tile_lights = ShaderOptions{}.tile_lights;
    TileGrouping tile_plan = ShaderOptions{}.tile_plan;
    bool tile_depth = ShaderOptions{}.tile_depth;
    // Light geometries with rows of their own (the default configuration with each); quad's rows
    // are always there. screen is LearnOpenGL's lighting pass, measured beside dsr's (goal `demo`).
    std::vector<LightGeometry> geometries = {LightGeometry::quad, LightGeometry::volume, LightGeometry::stencil,
                                             LightGeometry::tiles, LightGeometry::screen};
};

// Which renderer a row measured: the deferred one, or the forward one in one of its modes
// (ForwardMode: Listing 3's single pass, Listing 4's pass per light).
enum class Renderer { deferred, forward_single, forward_multi };
// "deferred", "forward-single", "forward-multi": the JSON's `renderer` and the tables' names.
const char* renderer_name(Renderer r);

// The skips a row turned off, by their SkipOptions field names ("empty_lights", ...), in the
// struct's order: JSON `skips_off`, and "no-NAME" in the configuration text.
std::vector<std::string> skips_off(const SkipOptions& skip);

// One measured configuration. Optional fields are JSON null where they do not apply.
struct Row {
    std::string scene;
    Renderer renderer = Renderer::deferred;
    // Forward rows: ForwardOptions::float_target as run. JSON `accum`: "float" (an RGBA32F
    // target) | "rgba8" (the main buffer); null where not recorded.
    std::optional<bool> float_accum;
    // Deferred rows, as run (JSON null on forward rows): the depth path, what the packed target
    // holds (JSON `encoding`: packed rows only), the G-buffer's precision (JSON `gbuffer`: "half" |
    // "rgba8"), the light geometry, and the tiles' settings (--tile-size/--tile-lights auto resolved).
    DepthPath depth = DepthPath::texture;
    DepthEncoding encoding = DepthEncoding::corrected;
    bool gbuffer_half = false;
    AccumFormat accum_format = AccumFormat::rgba8;  // deferred rows: P-buffer 0 (--accum, docs/hdr.md); JSON `accum`
    LightGeometry light_geometry = LightGeometry::quad;
    std::optional<int> tile_size, tile_lights;
    // Deferred rows on N-large: the scene's lights drawn with Equation 2's linear law at their own
    // radii (linear_law_twin), beside the rows with the scene's attenuation law, on the same pixel-light
    // pairs: goal `law`. Compared with the twin's own forward reference and quad row. JSON `linear_law`.
    bool linear_law = false;
    // Deferred rows of a variant whose scene has a Phong material: dsr's default configuration with
    // quad on the scene's metal_rough_twin (bench_scenes.h), its scene named metal_rough_name(scene),
    // beside the default quad row on the same pixel-light pairs and in the same rounds: the material
    // model's cost per pair (bench_material.h). Its image is held against the twin's forward render,
    // which draws a metallic-roughness material as Phong (the base colour, no highlight).
    bool metal_rough = false;
    bool scissor = false;
    SkipOptions skip;                       // every skip on unless the row turned one off
    int lights = 0, w = 0, h = 0, frames = 0;
    int warmup_frames = 0;                  // untimed frames before them (warm_up), and their wall times
    std::vector<double> warmup_frames_ms;
    std::string lights_label;               // the --lights entry it came from: "own", "32", "1024-overlap", ...
    int sweep_index = 0;                    // place of its light count in --lights (plot marker size)
    double ms_median = 0, ms_min = 0, ms_max = 0;
    // The timed frames, round by round: frame i of every row of a variant ran in round i (a slow
    // row, given fewer frames, in the first ones), so two rows' frames pair up round by round.
    // lights_frames_ms: deferred rows' light stages, the same way (empty on forward rows).
    std::vector<double> frames_ms, lights_frames_ms;
    double cpu_ms = 0;  // median CPU time of the submitting thread per frame (dsr_clock.h thread_cpu_ms)
    // Deferred rows, the CPU's frame in parts (FrameStats ms.cpu_make_frame, ms.cpu_lights: the frame's
    // set-up and culling, the light stage's submission), medians, and the CPU time of each timed frame.
    std::optional<double> cpu_make_frame_ms, cpu_lights_ms;
    std::vector<double> cpu_frames_ms;
    // dsr's default row of each variant (find_default_row), goal `cpu`: the submitting thread's CPU
    // in as many frames again, run back to back after the rounds as an application draws them, and
    // their median (null on the other rows). In the rounds each frame follows the other rows'
    // frames and finds the caches holding their data.
    std::optional<double> cpu_alone_ms;
    std::vector<double> cpu_alone_frames_ms;
    // The goals that compare rows within 5-10% of each other (auto, law): the rows they compare run
    // again after the rounds, those rows alone, kGoalRoundsFactor x as many rounds (goal_rounds_rows):
    // their frames and light stages round by round and the medians (null and empty on the other
    // rows). In the rounds of every row such a verdict between two rows drawing the same passes
    // flips with the rounds' noise (docs/benchmarks.md, "How the rows are timed").
    std::optional<double> goal_rounds_ms, goal_rounds_lights_ms;
    std::vector<double> goal_rounds_frames_ms, goal_rounds_lights_frames_ms;
    // The ideal count of pixel-light pairs, from exact surface points (ideal_source says which),
    // which the counted frame's light counts (light_fragments() and the rest, below) are held against.
    std::optional<long long> ideal_fragments;
    std::optional<std::string> ideal_source;  // "analytic" (exact eye depth) | "depth24" (G-buffer depth in double)
    std::optional<int> passes;                // forward rows: the passes drawn
    // The frame's floor (bench_floor.h), deferred rows: its parts, floor_ms and ms_median / floor_ms.
    std::optional<double> floor_fill_ms, floor_light_ns, floor_post_ms, floor_output_ms, floor_ms, floor_ratio;
    ImageDiff err;                          // vs the forward reference
    std::optional<ImageDiff> err_analytic;  // vs the analytic reference, interior pixels
    std::optional<ImageDiff> err_quad;      // deferred rows: vs the default quad row's image
    // Deferred rows: the counted frame's stats whole (the frame after the timed ones), JSON `frame`
    // (analysis/frame_stats_json.h, the schema `render --stats` writes): the one place the row keeps
    // its light counts (light_fragments() and the rest read them) and auto's choice.
    std::optional<FrameStats> frame;
    std::optional<double> depth_copy_ms;    // deferred rows: the depth hand-off's median ms (0: not run)
    std::optional<double> lights_ms;        // deferred rows: the light stage's median ms (FrameStats ms.lights)
    int gbuffer_bytes_per_pixel = 0;        // deferred rows: the G-buffer's colour targets + depth, from the
                                            // formats allocated (Paths::gbuffer_bytes_per_pixel); forward rows: 0
};

// The default configuration, on which the goals are judged and every light geometry's image is
// compared: a deferred row with the depth texture, scissor on, every skip on and the RGBA8
// G-buffer, whatever its light geometry, drawing the scene's own lights (not linear_law).
bool default_configuration(const Row& r);
// A linear-law row (Row::linear_law) in the default configuration otherwise: the twin of a
// default_configuration row, which the law goal and the twin's image check read.
bool default_configuration_twin(const Row& r);
// "default-metal-rough": the scene name of a variant's metallic-roughness row (Row::metal_rough).
std::string metal_rough_name(const std::string& scene);

// A deferred row's light counts, read from its counted frame (Row::frame; LightCounts): samples
// that passed the light passes (occlusion queries), fragments that entered the light shader
// (ARB_pipeline_statistics_query), those times the lights each evaluated, the light-shader draws.
// Null on a row without a frame (forward rows) and where the GL did not count.
std::optional<long long> light_fragments(const Row& r);
std::optional<long long> light_invocations(const Row& r);
std::optional<long long> light_evaluations(const Row& r);
std::optional<int> light_passes(const Row& r);

// light_evaluations / ideal_fragments, where both are known and the ideal is above 0.
std::optional<double> evaluations_ratio(const Row& r);

// The row's configuration as the tables print it: "forward-multi", "deferred texture sc",
// "deferred packed/log sc half no-empty_lights", ...
std::string config_text(const Row& r);

// The row's configuration in plain words, as the terminal and the goals' figures name it: the
// renderer, for deferred rows the light geometry (none named: the tutorial's quad per light) and
// every setting that differs from the default configuration (depth texture, scissor on, every skip
// on, 8-bit G-buffer and light sums): "deferred, no scissor", "deferred, auto light geometry",
// "forward, a pass per light and object, float sums".
std::string row_words(const Row& r);

// True when every material is constant (no maps), so the analytic reference applies.
bool analytic_capable(const Scene& s);

// The size a scene variant of `set` runs at: N-large (LearnOpenGL's demo) at the demo's
// kDemoWidth x kDemoHeight unless --size was given; every other variant at the sweep's w x h.
std::pair<int, int> variant_size(const Config& cfg, LightSet set);
// The timed frames of a variant: the sweep's, or kLargeFrameFactor times as many on N-large where
// --frames was not given. Its frames are short (but for quad's and the screen's rows), and its
// goals (demo, law, auto) compare close rows, where ten frames of a noisy machine decide the
// verdict more than the renderers do (docs/benchmarks.md, "How the rows are timed").
constexpr int kLargeFrameFactor = 3;
int variant_frames(const Config& cfg, LightSet set);
// " (N-large M)" where the sweep has an N-large variant timed with M frames other than cfg.frames, else "".
std::string large_frames_note(const Config& cfg);
// The context the sweep needs: as large as every variant of cfg.lights in each dimension.
std::pair<int, int> context_size(const Config& cfg);

// The order in which round `round` of the timed frames takes a variant's rows (indices 0..rows-1):
// a permutation of its own each round, the same in every run. In one fixed order a GPU's row that
// follows a long one pays more a frame, most of it CPU time after the long wait, every round
// (docs/benchmarks.md, "How the rows are timed").
std::vector<size_t> round_order(size_t rows, int round);

// The goals' own rounds (Row::goal_rounds_ms): the indices of the rows of `scene` with `lights`
// lights that run them. Goal auto's: the auto row, then each fixed geometry's row (quad, volume,
// stencil, tiles; default configuration) whose median in the rounds of every row (ms_median) is
// within kGoalRoundsWithin of the fastest of them (a row further off cannot be the fastest whatever
// the noise), where there are both. Goal law's: dsr's default row (find_default_row) and its
// linear-law twin, where the variant has one. Each row once; they run kGoalRoundsFactor x the first
// row's frames.
constexpr double kGoalRoundsWithin = 1.3;
constexpr int kGoalRoundsFactor = 3;
std::vector<size_t> goal_rounds_rows(const std::vector<Row>& rows, const std::string& scene, int lights);

// A row's warm-up: frames until `warmup` in a row have built no shader program and drawn no light
// by a path auto was exploring (AutoStats::explored), at most warmup + compile_warmup, or
// until a slow frame (its own warm-up); returns the frames run. The timed frames are then the
// renderer's steady state, whatever it learns first: auto measures a path it has not drawn by
// drawing it (exploration_plan) and builds a path's programs when it first takes it (the tiles'
// per-count ones, linked and compiled at their first draw). A fixed count of warm-up frames left
// such builds and explorations among the timed frames (docs/benchmarks.md, "How the rows are
// timed"). The same rule for every row: a fixed geometry explores nothing. The JSON's
// warmup_frames and warmup_frames_ms show it.
struct WarmupFrame {
    bool built = false;      // the frame built a program
    bool exploring = false;  // auto drew lights by a path to measure it
    bool slow = false;       // it took over kSlowFrameMs
};
int warm_up(int warmup, int compile_warmup, const std::function<WarmupFrame()>& frame);

// Frames to time after warm-up: the configured count, unless one frame takes over 2 s (forward
// passes at 1024 lights on a software rasteriser), then as many as fit in 20 s, at least 3.
int frames_for(double first_ms, int frames);

// "MODEL NAME, N logical CPUs" from /proc/cpuinfo.
std::string machine_name();

// A path's file name without folder and extension: a scene's name in the tables.
std::string file_stem(const std::string& path);

// A scene variant's ideal count (docs/benchmarks.md, "ideal") and where it came from: the one
// count of ideal_fragments.h (ideal_count, by each light's volume) on exact surface points, not on
// the light shader's reconstruction. The runner takes the analytic trace's exact eye depth where the
// scene has one (source "analytic"), else the first depth-texture row's 24-bit depth codes decoded
// in double ("depth24").
struct IdealCount {
    std::optional<long long> fragments;
    std::optional<std::string> source;
};
IdealCount ideal_from_eye_depth(const Scene& scene, int w, int h, const std::vector<double>& eye_depth);
IdealCount ideal_from_depth_codes(const Scene& scene, int w, int h, const std::vector<uint32_t>& codes);

// Measures the rows of each scene variant on the current GL context, which must be at least
// context_size(cfg) (the caller creates it with create_context).
class Runner {
public:
    Runner(const Config& cfg, const Caps& caps, const std::string& shader_dir);

    // Every row of one scene variant: the scene at `path` with `light_count` lights (-1: its
    // own); `sweep_index` is the light count's place in cfg.lights; index/total number the
    // variant in progress lines.
    void run_scene(const std::string& path, int light_count, int sweep_index, int index, int total);

    const std::vector<Row>& rows() const { return rows_; }
    const std::vector<std::string>& notes() const { return notes_; }  // configurations left out, and why

    // Called with each progress line (no newline); none by default. `dsr bench` prints them on stderr.
    std::function<void(const std::string&)> progress;

private:
    Config cfg_;
    Caps caps_;
    std::string shaders_;
    std::vector<Row> rows_;
    std::vector<std::string> notes_;
};

}  // namespace dsr::bench
