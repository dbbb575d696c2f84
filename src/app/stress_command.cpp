// `dsr stress`: the numerical stress sweep (issue 6). Parses the flags, runs every case of
// stress_cases.h (src/analysis/stress_run.h) on a context of the chosen backend, prints one row
// per case on stdout (progress on stderr) and the depth-accuracy tables, and exits non-zero when
// any invariant fails. --json writes the rows; --report rewrites the generated block of
// docs/accuracy.md; --plot draws relative z error against far/near (src/analysis/stress_report.h).
#include <algorithm>
#include <cstdio>

#include "dsr_clock.h"
#include "analysis/stress_report.h"
#include "analysis/stress_run.h"
#include "app/args.h"
#include "app/commands.h"
#include "app/files.h"
#include "dsr_error.h"
#include "platform/context.h"
#include "platform/resources.h"
#include "scene/image.h"
#include "scene/user_file.h"

namespace dsr {

namespace {

// The report file's text, checked for its generated block.
std::string read_report(const std::string& path) {
    std::string text;
    try {
        text = read_user_text(path, "report", kMaxSceneBytes);  // a regular file, never a FIFO
    } catch (const Error& e) {
        throw Error(std::string("dsr stress: --report: ") + e.what());
    }
    check_report_block(text, path);
    return text;
}

}  // namespace

int cmd_stress(const std::vector<std::string>& argv) {
    Args args("stress", argv);
    bool quick = false;
    std::string json_path, report_path, plot_path, only, geometry;
    std::string backend = default_context_backend();  // --context, else $DSR_CONTEXT
    while (!args.done()) {
        std::string a = args.next();
        if (a == "--quick") quick = true;
        else if (a == "--json") json_path = args.value(a);
        else if (a == "--report") report_path = args.value(a);
        else if (a == "--plot") plot_path = args.value(a);
        else if (a == "--only") only = args.value(a);
        else if (a == "--context") backend = args.value(a);
        else if (a == "--light-geometry") geometry = args.value(a);
        else args.fail("unknown option '" + a + "' (expected --quick, --json FILE, --report FILE.md, --plot FILE.png, "
                       "--only TEXT, --light-geometry NAME, --context NAME)");
    }
    if (!report_path.empty()) read_report(report_path);  // a wrong file fails before the sweep
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
        if (cases.empty()) args.fail("--only: no case name contains '" + only + "'");
    }
    // --light-geometry: every case through that geometry instead of the tutorial's quad, so its
    // depth hand-off, meshes and stencil meet the same far/near ratios and coordinates.
    if (!geometry.empty()) {
        LightGeometry g = LightGeometry::quad;
        try {
            g = light_geometry_from_name(geometry);
        } catch (const Error& e) {
            args.fail(std::string("--light-geometry: ") + e.what());
        }
        for (StressCase& c : cases) c.opts.light_geometry = g;
    }
    int mw = 1, mh = 1;
    for (const StressCase& c : cases) mw = std::max(mw, c.width), mh = std::max(mh, c.height);

    const double t0 = now_ms();
    auto ctx = create_context(ContextDesc{backend, mw, mh});
    StressRunner runner(*ctx, resource_dir("glsl120"));
    std::vector<StressResult> results;
    int failed = 0;
    for (size_t i = 0; i < cases.size(); ++i) {
        results.push_back(runner.run(cases[i]));
        const StressResult& r = results.back();
        failed += r.counts_as_failure();
        std::fprintf(stderr, "[%3zu/%zu] %-30s %6.0f ms %s\n", i + 1, cases.size(), r.name.c_str(), r.ms,
                     r.passed() ? "pass" : r.limit ? "fails (limit case, not counted)" : "FAIL");
        for (const std::string& f : r.failures()) std::fprintf(stderr, "          %s\n", f.c_str());
    }
    const double seconds = (now_ms() - t0) / 1000.0;

    std::printf("%s", stress_case_table(results, false).c_str());
    const std::string acc = stress_accuracy_tables(results);
    if (!acc.empty()) std::printf("\n%s", acc.c_str());
    std::printf("\n%zu cases, %d failed (and %d limit cases past the required range fail, not counted), %.1f s on %s\n",
                results.size(), failed, stress_limit_failures(results), seconds, runner.renderer().c_str());

    if (!json_path.empty()) {
        const std::string command =
            std::string("dsr stress") + (quick ? " --quick" : "") + (only.empty() ? "" : " --only " + only) +
            (geometry.empty() ? "" : " --light-geometry " + geometry);
        outputs.put_text("--json", json_path,
                         stress_json(results, command, runner.renderer(), seconds)
                                 .dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    }
    if (!report_path.empty())
        outputs.put_text("--report", report_path,
                         splice_report_block(read_report(report_path), report_path,
                                             stress_report_block(results, quick, runner.renderer())));
    if (!plot_path.empty()) outputs.put_image("--plot", plot_path, stress_accuracy_plot(results));
    outputs.commit();
    return failed ? 1 : 0;
}

}  // namespace dsr
