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

// How far a row's timed frames spread: half their interquartile range over their median (0.1:
// the middle half of the frames within about ±10% of the median); 0 with fewer than 2 frames.
double time_spread(const Row& r);
// A row's frame time as the terminal prints it: the median in ms and its spread ("2.81 ±12%").
std::string time_text(const Row& r);

// The rows as `dsr bench` prints them: a table per scene, a line per configuration (row_words), for
// each light count its time (time_text) and the image's largest error against the forward
// reference beside it, in LSB; fitted to the terminal's width (terminal_text.h).
std::string rows_text(const std::vector<Row>& rows);

// What a run's rows say at a glance, the summary's first lines: on the judged scene at its largest
// light count, dsr's default frame against forward shading's two forms, the fastest light geometry,
// the image's largest error, the goals' count, and how far the frames of a row spread around their
// median. Each a plain sentence; none where the rows lack what it needs.
struct Conclusions {
    std::vector<std::string> lines;
    // The figures the sentences are made of (tests read these): the scene and count judged, dsr's
    // default row and the forward rows at that count (null where the run has none), the fastest light
    // geometry's row, the largest max LSB of dsr's default rows and of every deferred row (with it),
    // and the median over rows of their time_spread.
    std::string scene;
    int lights = 0;
    const Row* default_row = nullptr;
    const Row* forward_single = nullptr;
    const Row* forward_multi = nullptr;
    const Row* fastest_geometry = nullptr;
    double default_max_lsb = -1, deferred_max_lsb = -1;
    const Row* worst_deferred = nullptr;
    double spread = -1;
};
Conclusions conclusions(const std::vector<Row>& rows, const std::string& scene, const std::vector<GoalResult>& goals);

// The table's column names, and one row's cells under them.
const std::vector<std::string>& table_header();
std::vector<std::string> table_cells(const Row& r);

// The table as the report holds it (markdown).
std::string markdown_table(const std::vector<Row>& rows);

// Run time against error: one panel per scene; dsr's default, forward single-pass and forward
// multi-pass as series whose dots are labelled with their light count, every other deferred row a
// small grey dot of one more series; each series named in the legend.
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

// What `dsr bench` prints on stdout, within the terminal's width: one line on the run, what it shows
// (conclusions()), each goal as a plain sentence with its figures and met / NOT met / not judged,
// the rows (rows_text), where the report (every goal's working, the notes) and the JSON went, and
// what the exit status means. report_path, json_path: "" when not written.
std::string text_summary(const Summary& s, const std::string& report_path, const std::string& json_path);

// The report's "Light geometries" section: what each geometry is, and one line per geometry row.
std::string light_geometry_markdown(const std::vector<Row>& rows);

// docs/benchmarks.md; `plot_name` is the plot's file name beside it, linked relatively.
std::string markdown_report(const Summary& s, const std::string& plot_name);

}  // namespace dsr::bench
