// What `dsr bench` prints and writes, from measured rows (bench_run.h): the table (text and
// markdown), the goals judged on the rows, the JSON later tools read, the plot and the markdown
// report. Pure functions of their arguments, so tests call them on hand-made rows.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/bench_run.h"
#include "gl/invocation_probe.h"
#include "scene/image.h"

namespace dsr::bench {

// One row as JSON: every key of docs/benchmarks.json's rows; null where it does not apply
// (fragment counts of forward rows, analytic errors of scenes without an analytic reference).
nlohmann::ordered_json row_json(const Row& r);

// The table's column names, and one row's cells under them.
const std::vector<std::string>& table_header();
std::vector<std::string> table_cells(const Row& r);

// The table as `dsr bench` prints it (columns padded, a rule under the header) and as markdown.
std::string text_table(const std::vector<Row>& rows);
std::string markdown_table(const std::vector<Row>& rows);

// The row a goal is judged on: `scene` with `lights` lights and `renderer`; for deferred rows
// with default_config, only the default configuration (depth texture, scissor on, every skip on,
// RGBA8 G-buffer). Null when the run has no such row.
const Row* find_row(const std::vector<Row>& rows, const std::string& scene, int lights, const std::string& renderer,
                    bool default_config = true);

// Of the rows of `scene` with `lights` lights and `renderer`, the one with the lowest median
// (the forward baseline: the faster of its float and RGBA8 forms). Null when there is none.
const Row* fastest_row(const std::vector<Row>& rows, const std::string& scene, int lights,
                       const std::string& renderer);

// Goals of the issue, judged on the rows of `scene` (own_lights: its own light count): at the own
// count and at 1024 lights, light_invocations <= 1.25 x ideal and floor_ratio <= 1.3; at 256
// lights, deferred >= 10x faster than the faster forward multi-pass row. Each goal line ends
// "-> met" or "-> NOT met", or says it was not measured; lines starting with two spaces are
// information about the one before (light_fragments / ideal, which the sphere test makes hold
// by construction, is printed as such, never as "met").
// probe: the GL's invocation counter (gl/invocation_probe.h), for the stencil goal.
std::vector<std::string> goals(const std::vector<Row>& rows, const std::string& scene, int own_lights,
                               const std::optional<InvocationProbe>& probe = std::nullopt);
// The light geometries' goals (issue 12), which goals() appends: stencil light_invocations <= 1.25 x
// ideal at the own count and 1024; tiles >= 3x faster than quad on 1024-overlap; the best deferred
// row >= 1.5x faster than forward single-pass on 32-large; every geometry's image within 1 LSB of
// quad's. A goal whose rows are missing says "not measured in this run". Where the probe found that
// the GL's invocation counter counts fragments the stencil test rejects, the stencil goal says it
// "cannot be judged on this GL" and gives the occlusion-query ratio as information.
std::vector<std::string> geometry_goals(const std::vector<Row>& rows, const std::string& scene, int own_lights,
                                        const std::optional<InvocationProbe>& probe = std::nullopt);
// The default configuration (depth texture, scissor, every skip, RGBA8) with this light geometry.
const Row* find_geometry_row(const std::vector<Row>& rows, const std::string& scene, int lights,
                             const std::string& geometry);

// Run time against error: one panel per scene, a series per renderer kind.
Image plot_rows(const std::vector<Row>& rows, const std::vector<std::string>& scenes);

// Everything one `dsr bench` run reports.
struct Summary {
    std::string machine;                          // machine_name()
    std::string gl_renderer, gl_version, gl_vendor;
    Config config;
    std::vector<std::string> scenes;              // scene names (file_stem), the first one judged
    double seconds = 0;                           // the whole sweep
    std::vector<Row> rows;
    std::vector<std::string> goals, notes;
    std::optional<InvocationProbe> invocation_probe;  // null where the GL cannot be probed
};

// docs/benchmarks.json: machine, GL, config, seconds, goals, notes, rows.
nlohmann::ordered_json to_json(const Summary& s);

// What `dsr bench` prints on stdout: the header lines, the table, the goals and the notes.
std::string text_report(const Summary& s);

// The report's "Light geometries" section: what each geometry is, and one line per geometry row.
std::string light_geometry_markdown(const std::vector<Row>& rows);

// docs/benchmarks.md; `plot_name` is the plot's file name beside it, linked relatively.
std::string markdown_report(const Summary& s, const std::string& plot_name);

}  // namespace dsr::bench
