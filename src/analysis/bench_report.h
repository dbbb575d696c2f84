// What `dsr bench` prints and writes, from measured rows (bench_run.h): the table (text and
// markdown), the JSON later tools read, the plot and the markdown report, with the goals judged on
// the rows (bench_goals.h). Pure functions of their arguments, so tests call them on hand-made rows.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/bench_goals.h"
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

// The table as the report holds it (markdown).
std::string markdown_table(const std::vector<Row>& rows);

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
    std::vector<std::string> goals, notes;        // goals: every goal's line and its information (goals())
    std::vector<GoalResult> goal_results;         // the same goals judged (judge_goals()), for the summary
    std::optional<InvocationProbe> invocation_probe;  // null where the GL cannot be probed
};

// docs/benchmarks.json: machine, GL, config, seconds, goals, notes, skip_savings (bench_skips.h), rows.
nlohmann::ordered_json to_json(const Summary& s);

// What `dsr bench` prints on stdout, short enough to read at a glance: one line on the run, each
// goal as a plain sentence with its figures and met / NOT met / not judged, where the report (the
// table, every goal's working, the notes) and the JSON went, and what the exit status means.
// report_path, json_path: "" when not written.
std::string text_summary(const Summary& s, const std::string& report_path, const std::string& json_path);

// The report's "Light geometries" section: what each geometry is, and one line per geometry row.
std::string light_geometry_markdown(const std::vector<Row>& rows);

// docs/benchmarks.md; `plot_name` is the plot's file name beside it, linked relatively.
std::string markdown_report(const Summary& s, const std::string& plot_name);

}  // namespace dsr::bench
