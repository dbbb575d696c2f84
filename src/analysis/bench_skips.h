// What each skip saves (docs/benchmarks.md, "What each skip saves"): the bench times the default
// configuration with every skip on and, beside it, with each skip turned off alone (bench_run.cpp,
// on the tutorial's per-light quads, where every skip applies); this pairs those rows up. Pure: a
// function of the rows, so tests call it on hand-made ones.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/bench_run.h"

namespace dsr::bench {

struct SkipSaving {
    std::string scene, lights_label;  // the variant: the rows' scene and --lights entry
    std::vector<std::string> skips_off;  // what the row turned off, by --no-skip's names: one skip or the ambient pair
    double with_ms = 0, without_ms = 0;  // frame medians: every skip on; this one off
    double with_min = 0, with_max = 0;   // the every-skip row's spread, to hold the difference against
    std::optional<double> with_lights_ms, without_lights_ms;  // the light stage's medians, where measured
    double saved_ms() const { return without_ms - with_ms; }  // > 0: the skip saves time
};

// Every row with skips turned off that has, in the same variant, the every-skip row of the same
// configuration (the default one with the quad geometry), in the rows' order.
std::vector<SkipSaving> skip_savings(const std::vector<Row>& rows);

// The report's section: one line per variant, a column per skip (saved ms), and how to read it.
std::string skip_savings_markdown(const std::vector<SkipSaving>& savings);

// JSON `skip_savings`: one object per pair.
nlohmann::ordered_json skip_savings_json(const std::vector<SkipSaving>& savings);

}  // namespace dsr::bench
