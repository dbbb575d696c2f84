// The bench's goals as one table (docs/benchmarks.md, "Goals"): each goal a named threshold, its
// comparison, the sentence that states it and the way its figure is measured on the rows. goals()
// judges every row of the table and prints each line from it; no threshold is written anywhere
// else. Pure functions of the rows, so tests call them on hand-made rows.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "analysis/bench_run.h"
#include "gl/invocation_probe.h"

namespace dsr::bench {

enum class Comparison { at_most, at_least };  // figure <= threshold, figure >= threshold

// Where a goal is judged: at the scene's own light count and at kManyLights (a line each), once
// on the rows its `on` names, or on each of goal_light_sets() (a line each).
enum class Scope { per_light_count, once, per_light_set };
constexpr int kManyLights = 1024;
// The size and light count the floor goal is judged at (a GPU goal: the floor leaves out the
// frame's fixed costs, which weigh more the smaller the frame, so its ratio depends on the size).
constexpr int kFloorWidth = 1920, kFloorHeight = 1080, kFloorLights = kManyLights;
constexpr const char* kFloorDemo = "32-large";  // the floor goal's other light set (--lights entry)

// The --lights entries a per_light_set goal is judged on: the full bench's scenes but 32.
const std::vector<std::string>& goal_light_sets();

// goals() prints both groups; geometry_goals() the light geometries' (docs/light_geometry.md).
enum class GoalGroup { renderer, light_geometry };

// What a goal's measure found on the rows.
struct Figure {
    bool judged = false;
    // Judged: the figure is value / scale, and the goal is met when value <= threshold x scale
    // (at_most) or value >= threshold x scale (at_least): the comparison the figure's working shows,
    // without a division's rounding.
    double value = 0, scale = 1;
    std::string working;            // judged: how the figure came ("120 / 100 = 1.200"); else why not judged
    std::string brief;              // not judged: why, in a few words (the summary's); empty: working
    std::string after;              // after the verdict: information ("; without lights ...")
    std::vector<std::string> info;  // lines of information that follow the goal's line (never judged)
};

// What a measure reads: the rows, the scene judged, the light count (per_light_count goals; the
// scene's own for the others), the GL's invocation counter where it was probed, and the --lights
// entry a per_light_set goal judges ("own", "256", "1024-overlap", ...).
struct GoalInput {
    const std::vector<Row>& rows;
    const std::string& scene;
    int lights;
    const std::optional<InvocationProbe>& probe;
    std::string set = "";
};

struct Goal {
    const char* id;  // a short name: "invocations", "floor", "speed_256", ...
    GoalGroup group;
    Scope scope;
    // The goal as printed. {cmp}: "<=" or ">=" ({cmp words}: "at most" or "at least"); {t}: the threshold (%g); {on}: the --lights entry it
    // is judged on; {scene}, {lights}: the scene and light count judged; {set}: the --lights entry
    // of a per_light_set goal; [...]: only on a judged line.
    const char* sentence;
    // The goal as a plain sentence for the summary `dsr bench` prints first (the same placeholders).
    const char* plain;
    double threshold;
    Comparison comparison;
    const char* on;  // the --lights entry a `once` goal reads ("256", "1024-overlap", "32-large", "4096"); "" otherwise
    Figure (*measure)(const Goal& goal, const GoalInput& in);
    // Null for a goal; for a retired one, why it is no goal now: its figure is still measured and
    // printed as information (goals()), never judged, and the summary leaves it out (judge_goals()).
    const char* retired;
};

// Every goal, in the order the report lists them.
const std::vector<Goal>& goal_table();
// The goal with this id; throws dsr::Error for an unknown one.
const Goal& goal(const std::string& id);
// "<= 1.3": the goal's comparison and threshold, as its sentence states them.
std::string goal_bound(const Goal& g);

// The row a goal is judged on: `scene` with `lights` lights and `renderer`, never a linear-law
// twin; for deferred rows with default_config, only the default configuration (bench_run.h
// default_configuration) with the quad geometry. Null when the run has no such row.
const Row* find_row(const std::vector<Row>& rows, const std::string& scene, int lights, Renderer renderer,
                    bool default_config = true);

// Of the rows of `scene` with `lights` lights and `renderer`, the one with the lowest median
// (the forward baseline: the faster of its float and RGBA8 forms). Null when there is none.
const Row* fastest_row(const std::vector<Row>& rows, const std::string& scene, int lights, Renderer renderer);

// The default configuration with this light geometry.
const Row* find_geometry_row(const std::vector<Row>& rows, const std::string& scene, int lights,
                             LightGeometry geometry);

// The default configuration with this light geometry, drawing the scene's linear-law twin
// (Row::linear_law, N-large only). Null when the run has none.
const Row* find_linear_law_row(const std::vector<Row>& rows, const std::string& scene, int lights,
                               LightGeometry geometry);

// The default configuration's rows of the fixed geometries auto chooses among (quad, volume,
// stencil, tiles), in that order, those the run has: goal auto's rivals.
std::vector<const Row*> fixed_geometry_rows(const std::vector<Row>& rows, const std::string& scene, int lights);

// dsr's default: the default configuration with the default light geometry, auto; quad's row
// where the run has no auto row. Null when it has neither.
const Row* find_default_row(const std::vector<Row>& rows, const std::string& scene, int lights);

// One goal judged on one scene and light count: what goals() prints and what the summary says.
enum class Verdict { met, not_met, not_judged };
struct GoalResult {
    const Goal* goal = nullptr;
    int lights = 0;                 // per_light_count goals: the count judged
    Figure figure;
    Verdict verdict = Verdict::not_judged;
    std::string line;               // the goal's line, as goals() prints it
    std::string plain;              // the goal's plain sentence for this scene and count
};

// Every goal of the table judged on the rows, in goals()' order (its lines without the information);
// the retired ones left out.
std::vector<GoalResult> judge_goals(const std::vector<Row>& rows, const std::string& scene, int own_lights,
                                    const std::optional<InvocationProbe>& probe = std::nullopt);

// Every goal of the table judged on the rows of `scene` (own_lights: its own light count). Each
// goal line ends "-> met" or "-> NOT met", or says why it was not judged ("not measured in this
// run", or for the stencil goal on a GL whose invocation counter counts fragments the stencil test
// rejects, "cannot be judged on this GL"); lines starting with two spaces are information about the
// one before (light_fragments / ideal, which the sphere test makes hold by construction, is printed
// as such, never as "met"); a retired goal is such a line, "  (information, retired as a goal: ...)".
// probe: the GL's invocation counter (gl/invocation_probe.h).
std::vector<std::string> goals(const std::vector<Row>& rows, const std::string& scene, int own_lights,
                               const std::optional<InvocationProbe>& probe = std::nullopt);
// The light geometries' goals alone, as goals() ends with them.
std::vector<std::string> geometry_goals(const std::vector<Row>& rows, const std::string& scene, int own_lights,
                                        const std::optional<InvocationProbe>& probe = std::nullopt);

}  // namespace dsr::bench
