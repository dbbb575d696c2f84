// The command tables (command_table.h). A flag's value checks live in its parse, so a bad value
// fails before anything is loaded or written; checks that need the whole line stay in the
// command (compare's two files, gen-textures' folder).
#include "app/command_table.h"
#include "scene/user_file.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "analysis/bench_run.h"
#include "gl/cap_names.h"
#include "deferred/light_cost.h"
#include "dsr_error.h"
#include "gl/check.h"
#include "gl/frame_timer.h"
#include "gl/state.h"
#include "scene/framing.h"

namespace dsr {

namespace {

bool has_ext(const std::string& path, const std::string& ext) {
    if (path.size() < ext.size()) return false;
    std::string tail = path.substr(path.size() - ext.size());
    std::transform(tail.begin(), tail.end(), tail.begin(), ::tolower);
    return tail == ext;
}

// A file flag whose value must end in one of `exts` ("-o: expected a file ending .png, ...").
Flag file_flag(std::vector<std::string> names, std::string arg, std::string& field, std::vector<std::string> exts,
               std::string help, std::string def = "") {
    Flag f = text_flag(std::move(names), std::move(arg), field, std::move(help), std::move(def));
    f.parse = [&field, exts](Args& a, const std::string& flag) {
        const std::string v = a.value(flag);
        if (std::none_of(exts.begin(), exts.end(), [&](const std::string& e) { return has_ext(v, e); })) {
            std::string list;
            for (size_t i = 0; i < exts.size(); ++i) list += (i == 0 ? "" : i + 1 == exts.size() ? " or " : ", ") + exts[i];
            a.fail(flag + ": expected a file ending " + list + ", got " + quote(v));
        }
        field = v;
    };
    return f;
}

// SCENE, at most one.
Operand scene_operand(const std::string& help) { return Operand{"SCENE", help, true}; }
// An operand given at most once: a second is refused, naming it.
std::function<void(Args&, const std::string&)> one_operand(std::string& field, const std::string& what) {
    return [&field, what](Args& a, const std::string& w) {
        if (!field.empty()) a.fail("expected one " + what + ", got also " + quote(w));
        field = w;
    };
}

std::function<void(Args&, const std::string&)> one_scene(std::string& field) { return one_operand(field, "scene file"); }

Flag context_flag(ContextSettings& c) {
    return text_flag({"--context"}, "NAME", c.backend,
                     "GL context backend: osmesa (headless Mesa), egl (an EGL pbuffer: a GPU, or Mesa) or egl-gles2 "
                     "(the same on OpenGL ES 2.0, docs/gles2.md)",
                     "$DSR_CONTEXT, else osmesa");
}

Flag egl_device_flag(ContextSettings& c) {
    return int_flag("--egl-device", "N", 0, 15, c.egl_device, "with --context egl or egl-gles2: the EGL device", "$DSR_EGL_DEVICE, else 0");
}

Flag caps_flag(std::string& field) {
    Flag f{{"--caps"}, "LIST", "", "", "capabilities the probe reports missing, comma-separated and added to $DSR_CAPS, "
           "so the fallback paths can be forced (docs/legacy.md):", {}, nullptr};
    for (const CapName& c : cap_names()) f.items.emplace_back(c.name, std::string("hides ") + c.hides + ": " + c.effect);
    f.parse = [&field](Args& a, const std::string& flag) {
        const std::string v = a.value(flag);
        const std::string err = check_cap_names(split_caps(v));
        if (!err.empty()) a.fail(flag + ": " + err);
        field += "," + v;
    };
    return f;
}

// --gl-state-cache, --debug-gl and --timing: set where they live (gl/state.h, gl/check.h,
// gl/frame_timer.h), not in settings; their environment defaults are set before the command line
// is read (app/environment.h apply_gl_environment).
std::vector<Flag> gl_debug_flags() {
    Flag cache{{"--gl-state-cache"}, "on|off", "", "on, or $DSR_GL_STATE_CACHE",
               "off: every pass sets all of its GL state, so a cache bug can be told from a pass bug", {},
               [](Args& a, const std::string& flag) { gl_state().set_cache(a.on_off(flag)); }};
    Flag debug{{"--debug-gl"}, "", "", "", "check GL errors after every stage and name it (also DSR_DEBUG_GL=1)", {},
               [](Args&, const std::string&) { set_debug_gl(true); }};
    Flag timing{{"--timing"}, "measure|wall|gpu-timer", "", "$DSR_TIMING, else measure",
                "how the stages are timed (docs/stats.md): measure both ways on the GL and choose, or force the "
                "wall clock or timer queries (gpu-timer only where the GL has ARB_timer_query)", {},
                [](Args& a, const std::string& flag) {
                    const std::string v = a.value(flag);
                    if (v == "measure") set_timing_choice(TimingChoice::measure);
                    else if (v == "wall") set_timing_choice(TimingChoice::wall);
                    else if (v == "gpu-timer") set_timing_choice(TimingChoice::gpu_timer);
                    else a.fail(flag + ": expected measure, wall or gpu-timer, got " + quote(v));
                }};
    return {cache, debug, timing};
}

// --light-cost-scale: auto's starting cost scales, given instead of guessed.
Flag light_cost_scale_flag(RenderOptions& options) {
    return Flag{{"--light-cost-scale"}, "Q,V,T", "three positive numbers", "$DSR_LIGHT_COST_SCALE, else guessed",
                "--light-geometry auto: each path's starting cost scale, quad, volume, tiles (docs/light_geometry.md): "
                "given, they count as measured; a large one keeps a path out",
                {}, [&options](Args& a, const std::string& flag) {
                    const std::string v = a.value(flag);
                    try {
                        options.shader.light_cost_scale = parse_cost_scale(v);
                    } catch (const Error&) {
                        a.fail(flag + ": expected three positive numbers Q,V,T (quad, volume, tiles), got " + quote(v));
                    }
                }};
}

Flag lights_flag(std::optional<LightSpec>& field) {
    return Flag{{"--lights"}, "SPEC", "own, N, N-overlap, N-large, N-shadow or own-shadow; N in 0..65536", "own",
                "the scene's lights replaced by one of the bench's generated sets: N spread over the floor, "
                "N-overlap (clusters of 8; N a multiple of 8) or N-large (LearnOpenGL's demo: its 9 boxes and "
                "camera replace the scene too), N-shadow (N spot lights casting shadows) or own-shadow (the "
                "scene's own lights casting shadows), so a bench row's scene can be rendered and looked at",
                {}, [&field](Args& a, const std::string& flag) {
                    const std::string v = a.value(flag);
                    field = parse_light_spec(v);
                    if (!field)
                        a.fail(flag + ": expected 'own', a count N in [0, 65536], N-overlap (N a multiple of 8), "
                                      "N-large, N-shadow or own-shadow, got " + quote(v));
                }};
}

void append(std::vector<Flag>& to, std::vector<Flag> more) {
    for (Flag& f : more) to.push_back(std::move(f));
}

// --from's named sides, as a viewer names them: the view direction from the model's centre.
const std::vector<std::pair<std::string, glm::vec3>>& from_sides() {
    static const std::vector<std::pair<std::string, glm::vec3>> sides = {
        {"front", kFitFrom}, {"back", {-1, 1, -2}}, {"left", {-2, 1, 1}}, {"right", {2, 1, -1}},
        {"above", {0, 1, 0}}, {"below", {0, -1, 0}}};
    return sides;
}

}  // namespace

std::vector<Flag> load_flags(LoadOptions& load) {
    std::string names;
    for (const auto& [n, d] : from_sides()) names += (names.empty() ? "" : "|") + n;
    Flag from{{"--from"}, "SIDE", names + " or X,Y,Z", "front",
              "a model given as the scene is framed from this side of its centre: front is +Z (from the right "
              "and above), back is -Z, or a direction X,Y,Z; it also replaces a glTF file's own camera",
              {}, [&load](Args& a, const std::string& flag) {
                  const std::string v = a.value(flag);
                  for (const auto& [n, d] : from_sides())
                      if (v == n) return void(load.from = d);
                  glm::vec3 d(0);
                  char* end = nullptr;
                  const char* p = v.c_str();
                  for (int i = 0; i < 3; ++i) {
                      d[i] = std::strtof(p, &end);
                      if (end == p || !std::isfinite(d[i]) || (i < 2 && *end != ',')) {
                          d = glm::vec3(0);
                          break;
                      }
                      p = end + (i < 2 ? 1 : 0);
                  }
                  if (*end != '\0' || !(glm::length(d) > 1e-6f) || !std::isfinite(glm::length(d)))
                      a.fail(flag + ": expected " + "one of front, back, left, right, above, below or a non-zero "
                                    "direction X,Y,Z, got " + quote(v));
                  load.from = d;
              }};
    Flag camera{{"--camera"}, "N", "0..1000", "the file's first camera",
                "a glTF model's camera N (from 0) instead of its first", {}, [&load](Args& a, const std::string& flag) {
                    load.camera = a.int_value(flag, 0, 1000);
                }};
    Flag ambient{{"--ambient"}, "R,G,B", "each 0..1000", "the scene's (a glTF file's: none)",
                 "the ambient colour (Listing 15), replacing the scene's; a glTF file has none of its own",
                 {}, [&load](Args& a, const std::string& flag) {
                     const std::string v = a.value(flag);
                     glm::vec3 c(0);
                     char* end = nullptr;
                     const char* p = v.c_str();
                     bool ok = true;
                     for (int i = 0; i < 3 && ok; ++i) {
                         c[i] = std::strtof(p, &end);
                         ok = end != p && std::isfinite(c[i]) && c[i] >= 0 && c[i] <= 1000 && (i == 2 ? *end == '\0' : *end == ',');
                         p = end + 1;
                     }
                     if (!ok) a.fail(flag + ": expected three numbers R,G,B in [0, 1000], got " + quote(v));
                     load.ambient = c;
                 }};
    return {switch_flag("--strict", load.strict,
                        "refuse what the readers would substitute with a warning (an unknown material, a missing "
                        "texture, an unknown statement): the first warning is an error"),
            from, camera, ambient};
}

std::string RenderSettings::output() const {
    if (!out.empty()) return out;
    const std::string stem = scene.empty() ? "default" : std::filesystem::path(scene).stem().string();
    return std::string(kOutDir) + "/" + (stem.empty() ? "render" : stem) + ".png";
}

Command render_command(RenderSettings& s) {
    Command c{"render", "render SCENE with the deferred shader into one image",
              {scene_operand("scene file (default data/default.scene), or a model FILE.obj, FILE.gltf or FILE.glb "
                             "framed with a ground and three lights")},
              one_scene(s.scene), {}, &s.options, ""};
    c.flags = {
        file_flag({"-o", "--output"}, "FILE", s.out, {".png", ".exr", ".tif", ".tiff", ".jpg", ".ppm"},
                  "image to write, its format by the extension: .png (8-bit), .exr (half float), .tif, .jpg or .ppm; "
                  "without -o, the scene file's name under " + std::string(kOutDir) + "/ (out/default.png for the "
                  "default scene), the folder made if missing",
                  std::string(kOutDir) + "/SCENE.png"),
        size_flag("--size", s.width, s.height, "G-buffer and P-buffer size"),
        size_flag("--out-size", s.out_width, s.out_height,
                  "main frame buffer the final stage scales the image to, bilinearly (§3.6)", "--size"),
        int_flag("--frames", "N", 1, 100000, s.frames, "frames to render; --stats reports the medians"),
        file_flag({"--stats"}, "FILE.json", s.stats, {".json"},
                  "per-stage times, light counts and fragments, the paths chosen, as JSON"),
        lights_flag(s.lights),
        caps_flag(s.caps),
        context_flag(s.context),
        egl_device_flag(s.context),
        light_cost_scale_flag(s.options),
    };
    append(c.flags, load_flags(s.load));
    append(c.flags, gl_debug_flags());
    return c;
}

Command figures_command(FiguresSettings& s) {
    Command c{"figures",
              "the tutorial's figures 4, 6, 8-11, the SSAO and transparency figures as PNGs (docs/figures.md)",
              {scene_operand("scene file (default data/default.scene; the transparency figure needs it)")},
              one_scene(s.scene), {}, nullptr, ""};
    Flag size{{"--size"}, "NxN", "square, at least 64x64", std::to_string(s.size) + "x" + std::to_string(s.size),
              "the figures' size", {}, [&s](Args& a, const std::string& flag) {
                  int w = 0, h = 0;
                  a.size_value(flag, w, h);
                  if (w != h || w < 64)
                      a.fail(flag + ": expected a square size of at least 64x64, got '" + std::to_string(w) + "x" +
                             std::to_string(h) + "'");
                  s.size = w;
              }};
    c.flags = {text_flag({"-o"}, "DIR", s.dir,
                         "folder to write the PNGs into, made if missing (its parent must exist, but for the default's " +
                             std::string(kOutDir) + "/); make figures writes docs/figures"),
               size, context_flag(s.context)};
    return c;
}

Command bench_command(BenchSettings& s) {
    const std::string q = std::to_string(BenchSettings::kQuickSize);
    const std::string qsize = q + "x" + q;
    Command c{"bench", "depth path x scissor x skips x encodings x lights vs forward: times, fragments, error",
              {scene_operand("scene to measure (default: data/default.scene, tests/data/analytic.scene and, "
                             "without --quick, a generated 1-million-triangle mesh)")},
              one_scene(s.scene), {}, nullptr,
              "--tile-size, --tile-lights, --tile-plan and --tile-depth set the tiles rows, as render takes them.\n\n"
              "stdout: what the run shows first (dsr's default against forward, the fastest light geometry,\n"
              "the image's largest error, the goals' count, the frames' spread), then each goal as a sentence\n"
              "with its figures and met, NOT met or not judged, then every row in words with its median ms,\n"
              "its spread and the image's max LSB, and where the report and the JSON went; progress goes to\n"
              "stderr. Every line fits 120 columns.\n\n"
              "exit status: 0 when the run completed, whatever the goals (a goal not met is a finding, not an\n"
              "error); non-zero only on an error (a bad flag or scene, a GL failure, an output that cannot be\n"
              "written), with one line on stderr saying which.\n"};
    const bench::Config full;
    const std::vector<std::string>& geometries = find_render_option("light-geometry")->values;
    Flag lights{{"--lights"}, "LIST", "own, N, N-overlap, N-large, N-shadow or own-shadow, comma-separated",
                std::string(BenchSettings::kBenchLights) + "; --quick " + BenchSettings::kQuickLights,
                "light counts of the sweep: own, the scene's own lights; N lights spread over the floor; N-overlap, "
                "N lights (a multiple of 8) in clusters of 8, every lit pixel inside at least 8; N-large, 9 boxes "
                "and N lights covering most of the screen, as LearnOpenGL's demo, at its 800x600 unless --size is given; "
                "N-shadow, N spot lights casting shadows; own-shadow, the scene's own lights casting shadows",
                {}, [&s](Args& a, const std::string& flag) {
                    const std::string v = a.value(flag);
                    std::stringstream ss(v);
                    int n = 0;
                    for (std::string item; std::getline(ss, item, ','); ++n)
                        if (!parse_light_spec(item))
                            a.fail(flag + ": expected a comma-separated list of 'own', counts N in [0, 65536], N-overlap "
                                          "(N a multiple of 8) or N-large, got " + quote(item) + " in " + quote(v));
                    if (n == 0) a.fail(flag + ": expected at least one count, got ''");
                    s.lights = v;
                }};
    c.flags = {
        switch_flag("--quick", s.quick,
                    qsize + ", warm-up frames until one builds no shader program and explores no light path, " +
                        std::to_string(BenchSettings::kQuickFrames) + " timed frames, lights " + BenchSettings::kQuickLights),
        file_flag({"--json"}, "FILE.json", s.json, {".json"}, "every row, the goals and the machine (docs/benchmarks.json)"),
        file_flag({"--report"}, "FILE.md", s.report, {".md"},
                  "markdown report: the full table, each goal's working, the notes; the plot beside it as "
                  "FILE_plot.png (a folder of one level is created)"),
        size_flag("--size", s.width, s.height, "frame size of every row",
                  std::to_string(full.w) + "x" + std::to_string(full.h) + "; --quick " + qsize + "; N-large " +
                      std::to_string(kDemoWidth) + "x" + std::to_string(kDemoHeight)),
        int_flag("--frames", "N", 1, 1000, s.frames, "timed frames per row",
                 std::to_string(full.frames) + "; --quick " + std::to_string(BenchSettings::kQuickFrames) + "; N-large " +
                     std::to_string(bench::kLargeFrameFactor) + "x as many"),
        lights,
        list_flag("--light-geometry", "LIST", geometries, s.geometries, "light geometries with rows of their own"),
        option_flag("tile-size", s.tiles),
        option_flag("tile-lights", s.tiles),
        option_flag("tile-plan", s.tiles),
        option_flag("tile-depth", s.tiles),
        context_flag(s.context),
    };
    return c;
}

Command stress_command(StressSettings& s) {
    Command c{"stress", "numerical stress sweep; exit 1 if an invariant fails", {}, nullptr, {}, nullptr, ""};
    c.flags = {
        switch_flag("--quick", s.quick, "the quick subset (what `make test` runs)"),
        text_flag({"--json"}, "FILE", s.json, "every case's fields (docs/stress.json)"),
        text_flag({"--report"}, "FILE.md", s.report, "rewrite the file's generated block (docs/accuracy.md)"),
        text_flag({"--plot"}, "FILE.png", s.plot, "relative z error against far/near"),
        text_flag({"--only"}, "TEXT", s.only, "only the cases whose name contains TEXT"),
        choice_flag("--light-geometry", find_render_option("light-geometry")->values, s.geometry,
                    "every case through that light geometry", option_default(*find_render_option("light-geometry"))),
        context_flag(s.context),
    };
    return c;
}

Command info_command(InfoSettings& s) {
    Command c{"info", "GL vendor/renderer/version, capabilities, paths chosen", {}, nullptr, {}, nullptr, ""};
    c.flags = {caps_flag(s.caps), context_flag(s.context), egl_device_flag(s.context)};
    return c;
}

Command hdr_command(HdrSettings& s) {
    Command c{"hdr",
              "light beyond 1.0 (docs/hdr.md): clipped pixels and frame ms with P-buffer 0 in RGBA8, half and float, "
              "and each tone-mapping operator, on three scenes with lights brighter than 1",
              {}, nullptr, {}, nullptr, ""};
    c.flags = {int_flag("--size", "N", 64, 4096, s.size, "square size of the frames"),
               int_flag("--frames", "N", 1, 1000, s.frames, "timed frames per configuration (the median is printed)"),
               caps_flag(s.caps), context_flag(s.context), egl_device_flag(s.context)};
    return c;
}

Command gen_textures_command(GenTexturesSettings& s) {
    return Command{"gen-textures", "write the default scene's procedural textures",
                   {Operand{"DIR", "folder to write the textures into", false}},
                   one_operand(s.dir, "output folder"),
                   {}, nullptr, ""};
}

Command gen_model_command(GenModelSettings& s) {
    return Command{"gen-model",
                   "write a windmill dsr makes itself: OBJ + MTL + diffuse, normal and specular PNG maps",
                   {Operand{"DIR", "folder to write the model into (created when missing)", false}},
                   one_operand(s.dir, "output folder"),
                   {}, nullptr, ""};
}

Command compare_command(CompareSettings& s) {
    Command c{"compare", "compare two image files (RGB, 8-bit LSB) as the image tests do: one line on stdout",
              {Operand{"A", "the first image (any format dsr reads)", false},
               Operand{"B", "the second, the same size", false}},
              [&s](Args&, const std::string& w) { s.files.push_back(w); }, {}, nullptr, ""};
    c.flags = {
        float_flag("--threshold", "LSB", 0, 255, s.threshold_lsb, "count pixels with a channel over this difference"),
        float_flag("--max-lsb", "LSB", 0, 255, s.max_lsb, "exit 1 when the largest difference is over LSB", "none"),
    };
    return c;
}

Command view_command(ViewerConfig& s) {
    Command c{"view", "the renderer in a window (GLFW, GL 2.1) with a panel of every option, buffer and cost",
              {scene_operand("scene file (default data/default.scene), or a model FILE.obj, FILE.gltf or FILE.glb "
                             "framed with a ground and three lights")},
              one_scene(s.scene_path), {}, &s.options,
              "keys:\n"
              "  W A S D, Q E            move; Q/E down/up; shift: 4x faster; scroll: speed\n"
              "  right mouse button      hold and drag to look around\n"
              "  left mouse button       hold and drag to orbit the scene's target (a model's centre)\n"
              "  R                       back to the scene's camera\n"
              "  F                       frame the scene: look at its centre along the current view\n"
              "                          direction, its bounding sphere 70% of the window\n"
              "  F1 or Tab               show or hide the panel\n"
              "  1..7, V (shift+V)       buffer shown: final, normal, diffuse, specular, depth,\n"
              "                          blur-factor, bloom (next, previous)\n"
              "  C                       scissor on/off      O   scissor-rectangle overlay\n"
              "  B                       bloom on/off        N   anti-alias on/off\n"
              "  P                       depth path: texture/packed\n"
              "  L                       animate the lights (turn about the scene's target)\n"
              "  F12                     screenshot of the deferred image (no panel) into\n"
              "                          ./dsr_view_DATE_TIME.png; its path is printed\n"
              "  Esc                     quit\n"};
    c.flags = {
        size_flag("--size", s.width, s.height, "the window's size at start; the deferred buffers follow the window"),
        lights_flag(s.lights),
        text_flag({"--script"}, "FILE", s.script_path,
                  "run FILE's commands, one a line: size W H (0 0 minimises), camera pos X Y Z target X Y Z up X Y Z, "
                  "set NAME VALUE (a renderer option by its name without dashes: set scissor off, set view normal, "
                  "set bloom on; or panel, overlay, animate on|off), frames N, screenshot FILE (the deferred image, no "
                  "panel), screenshot FILE panel (the window as shown, the panel and overlay over the image), quit, wait. "
                  "The viewer closes after the script's last line unless that line is wait, which leaves the "
                  "window open"),
        caps_flag(s.caps_list),
        light_cost_scale_flag(s.options),
    };
    append(c.flags, load_flags(s.load));
    append(c.flags, gl_debug_flags());
    return c;
}

const std::vector<Command>& command_table() {
    static RenderSettings render;
    static FiguresSettings figures;
    static BenchSettings bench;
    static StressSettings stress;
    static InfoSettings info;
    static HdrSettings hdr;
    static GenTexturesSettings gen_textures;
    static GenModelSettings gen_model;
    static CompareSettings compare;
    static ViewerConfig view;
    static const std::vector<Command> t = {render_command(render), figures_command(figures), bench_command(bench),
                                           stress_command(stress),  info_command(info),       gen_textures_command(gen_textures),
                                           gen_model_command(gen_model), compare_command(compare), view_command(view),
                                           hdr_command(hdr)};
    return t;
}

const Command* find_command(const std::string& name) {
    for (const Command& c : command_table())
        if (c.name == name) return &c;
    return nullptr;
}

}  // namespace dsr
