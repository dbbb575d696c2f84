// The bias sweep's report (`dsr stress`, the shadow cases of stress_cases.h): which bias and
// slope the sweep supports as LightShadow's defaults, its tables, and the block of
// docs/accuracy.md it rewrites. Pure functions of the results, so tests call them on hand-made ones.
#pragma once
#include <string>
#include <vector>

#include "analysis/stress_run.h"

namespace dsr {

// One (bias, slope) pair over every shadow case that ran it (all lights, settings and paths).
struct ShadowPairSummary {
    double bias = 0, slope = 0;
    int cases = 0;
    int acne_cases = 0;              // cases with any acne pixel (shadow_metrics.h)
    long long most_acne = 0;         // the most acne pixels of one case
    double mean_leak = 0, worst_leak = 0;    // contact leak fraction
    double mean_edge = 0, worst_edge = 0;    // the edge error's max, px
    int maps_missing = 0;            // cases whose frame drew no shadow map
};
std::vector<ShadowPairSummary> shadow_pair_summaries(const std::vector<StressResult>& results);

// The sweep's choice, among the pairs that drew every map: acne in the fewest cases (a case no
// pair keeps clean, where the map's texels are larger than the band the acne measure leaves
// around an edge, then decides nothing), then the least mean contact leak, then the least mean
// edge error, then the smaller bias, then the slope nearest LightShadow's (a tie is no evidence
// to move it), then the smaller slope. found is false when no pair qualifies; `why` says what
// decided.
struct ShadowBiasChoice {
    bool found = false;
    double bias = 0, slope = 0;
    std::string why;
};
ShadowBiasChoice choose_shadow_bias(const std::vector<StressResult>& results);

// The markdown tables: every pair, and every case of the chosen pair and of LightShadow's defaults.
std::string shadow_sweep_tables(const std::vector<StressResult>& results);

// docs/accuracy.md's shadow block, markers included; and the doc with it replaced (throws
// dsr::Error naming `path` when the doc has no such block).
std::string shadow_report_block(const std::vector<StressResult>& results, const std::string& command,
                                const std::string& renderer);
void check_shadow_report_block(const std::string& doc, const std::string& path);
std::string splice_shadow_report_block(std::string doc, const std::string& path, const std::string& block);

}  // namespace dsr
