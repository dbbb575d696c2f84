// What `dsr stress` prints and writes from its results (stress_run.h): the per-case table (text
// and markdown), the depth-accuracy tables, the JSON, the accuracy plot, and the generated block
// of docs/accuracy.md. Pure functions of their arguments, so tests call them on hand-made results.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/stress_run.h"
#include "scene/image.h"

namespace dsr {

// One row per case: the text table `dsr stress` prints (columns in words, fitted to the terminal
// by terminal_text.h), or the markdown table of the report.
std::string stress_case_table(const std::vector<StressResult>& results, bool markdown);

// The depth-accuracy tables (a row per depth path, a column per far/near) of the ratio cases;
// empty when there are none.
std::string stress_accuracy_tables(const std::vector<StressResult>& results);

// One case as JSON: every key of docs/stress.json's cases; null where nothing was measured.
nlohmann::ordered_json stress_case_json(const StressResult& r);

// docs/stress.json: the command line, GL renderer, run time, failure counts and every case.
nlohmann::ordered_json stress_json(const std::vector<StressResult>& results, const std::string& command,
                                   const std::string& gl_renderer, double seconds);

// Limit cases (StressCase::limit) that fail: reported, never counted as failures.
int stress_limit_failures(const std::vector<StressResult>& results);

// Relative z error against far/near: window-depth and eye-depth paths, max above, mean below.
Image stress_accuracy_plot(const std::vector<StressResult>& results);

// The sentences docs/accuracy.md's prose relies on, generated (one "- " line each): the log
// encoding against the goal (<= 2e-6 up to far/near 1e6: "met" or "**NOT met**") and the log,
// texture and corrected paths at 1e6 and 1e7 against their CPU twins. Empty without ratio cases.
std::string stress_summary(const std::vector<StressResult>& results);

// The generated block of docs/accuracy.md, its BEGIN and END markers included.
std::string stress_report_block(const std::vector<StressResult>& results, bool quick, const std::string& renderer);

// Throws dsr::Error naming `path` when `doc` (that file's text) has no `begin` ... `end` block;
// `doc` with that block, its markers included, replaced by `block`. Every generated block of a
// document (this sweep's, the shadow sweep's) goes through these two.
void check_marked_block(const std::string& doc, const std::string& path, const std::string& begin,
                        const std::string& end);
std::string splice_marked_block(std::string doc, const std::string& path, const std::string& begin,
                                const std::string& end, const std::string& block);

// Throws dsr::Error naming `path` when `doc` (that file's text) has no BEGIN ... END block.
// `dsr stress` checks before the sweep runs, so a wrong file fails at once.
void check_report_block(const std::string& doc, const std::string& path);
// `doc` with its generated block replaced by `block`; throws as check_report_block.
std::string splice_report_block(std::string doc, const std::string& path, const std::string& block);

}  // namespace dsr
