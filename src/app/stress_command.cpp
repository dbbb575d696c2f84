// `dsr stress`: the numerical stress sweep (docs/accuracy.md). Parses the flags by its table
// (app/command_table.h), runs every case of stress_cases.h (src/analysis/stress_run.h) on a
// context of the chosen backend, prints one row per case on stdout (progress on stderr) and the
// depth-accuracy tables, and exits non-zero when any invariant fails. --json writes the rows;
// --report rewrites the generated block of docs/accuracy.md; --plot draws relative z error
// against far/near (src/analysis/stress_report.h).
#include <algorithm>
#include <cstdio>

#include "dsr_clock.h"
#include "analysis/stress_report.h"
#include "analysis/stress_run.h"
#include "analysis/stress_shadow_report.h"
#include "analysis/terminal_text.h"
#include "app/command_table.h"
#include "app/commands.h"
#include "app/files.h"
#include "dsr_error.h"
#include "platform/context.h"
#include "platform/resources.h"
#include "scene/image.h"
#include "scene/user_file.h"

namespace dsr {

namespace {

// The report file's text, checked for the generated blocks this run rewrites: the main one when
// cases other than the shadow ones run, the bias sweep's when shadow cases do.
std::string read_report(const std::string& path, bool main_block, bool shadow_block) {
    std::string text;
    try {
        text = read_user_text(path, "report", kMaxSceneBytes);  // a regular file, never a FIFO
    } catch (const Error& e) {
        throw Error(std::string("dsr stress: --report: ") + e.what());
    }
    if (main_block) check_report_block(text, path);
    if (shadow_block) check_shadow_report_block(text, path);
    return text;
}

}  // namespace

int cmd_stress(const std::vector<std::string>& argv) {
    StressSettings flags;  // the stress command's table (app/command_table.h)
    parse_command_line(stress_command(flags), argv);
    const bool quick = flags.quick;
    const std::string json_path = flags.json, report_path = flags.report, plot_path = flags.plot, only = flags.only,
                      geometry = flags.geometry;
    // The report is rewritten in place (its generated block); no other output may be it.
    OutputSet outputs("dsr stress");
    if (!json_path.empty()) outputs.add("--json", json_path);
    if (!report_path.empty()) outputs.add("--report", report_path);
    if (!plot_path.empty()) outputs.add("--plot", plot_path);
    std::vector<StressCase> cases = stress_cases(quick);
    if (!only.empty()) {
        std::vector<StressCase> kept;
        for (StressCase& c : cases)
            if (c.name.find(only) != std::string::npos) kept.push_back(std::move(c));
        cases = std::move(kept);
        if (cases.empty()) throw Error("dsr stress: --only: no case name contains " + quote(only));
    }
    bool main_cases = false, shadow_cases = false;
    for (const StressCase& c : cases) (c.shadow ? shadow_cases : main_cases) = true;
    if (!report_path.empty()) read_report(report_path, main_cases, shadow_cases);  // a wrong file fails before the sweep
    // --light-geometry: every case through that geometry instead of the tutorial's quad, so its
    // depth hand-off, meshes and stencil meet the same far/near ratios and coordinates.
    if (!geometry.empty())
        for (StressCase& c : cases) c.opts.light_geometry = light_geometry_from_name(geometry);  // checked by the flag
    int mw = 1, mh = 1;
    for (const StressCase& c : cases) mw = std::max(mw, c.width), mh = std::max(mh, c.height);

    const double t0 = now_ms();
    auto ctx = create_context(context_desc(flags.context, mw, mh));
    StressRunner runner(*ctx, resource_dir("glsl120"));
    std::vector<StressResult> results;
    int failed = 0;
    for (size_t i = 0; i < cases.size(); ++i) {
        results.push_back(runner.run(cases[i]));
        const StressResult& r = results.back();
        failed += r.counts_as_failure();
        std::fprintf(stderr, "[%3zu/%zu] %-30s %6.0f ms %s\n", i + 1, cases.size(), r.name.c_str(), r.ms,
                     r.passed() ? "pass" : r.limit ? "fails (limit case, not counted)" : "FAIL");
        for (const std::string& f : r.failures()) std::fputs(wrap_lines("          " + f + "\n").c_str(), stderr);
    }
    const double seconds = (now_ms() - t0) / 1000.0;

    // stdout fitted to the terminal (terminal_text.h); the report keeps the markdown.
    std::printf("%s", stress_case_table(results, false).c_str());
    const std::string acc = stress_accuracy_tables(results);
    if (!acc.empty()) std::printf("\n%s", markdown_for_terminal(acc).c_str());
    char total[512];
    std::snprintf(total, sizeof total,
                  "\n%zu cases, %d failed (and %d limit cases past the required range fail, not counted), %.1f s on %s\n",
                  results.size(), failed, stress_limit_failures(results), seconds, runner.renderer().c_str());
    std::fputs(wrap_lines(total).c_str(), stdout);

    const std::string command = std::string("dsr stress") + (quick ? " --quick" : "") +
                                (only.empty() ? "" : " --only " + only) +
                                (geometry.empty() ? "" : " --light-geometry " + geometry);
    if (!json_path.empty()) {
        outputs.put_text("--json", json_path,
                         stress_json(results, command, runner.renderer(), seconds)
                                 .dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    }
    std::vector<StressResult> main_results, shadow_results;
    for (const StressResult& r : results) (r.shadow ? shadow_results : main_results).push_back(r);
    const std::string sweep = shadow_sweep_tables(shadow_results);
    if (!sweep.empty()) std::printf("\n%s", markdown_for_terminal(sweep).c_str());
    if (!report_path.empty()) {
        std::string doc = read_report(report_path, main_cases, shadow_cases);
        if (main_cases) doc = splice_report_block(doc, report_path, stress_report_block(main_results, quick, runner.renderer()));
        if (shadow_cases)
            doc = splice_shadow_report_block(doc, report_path,
                                             shadow_report_block(shadow_results, command + " --report " + report_path,
                                                                 runner.renderer()));
        outputs.put_text("--report", report_path, doc);
    }
    if (!plot_path.empty()) outputs.put_image("--plot", plot_path, stress_accuracy_plot(results));
    outputs.commit();
    return failed ? 1 : 0;
}

}  // namespace dsr
