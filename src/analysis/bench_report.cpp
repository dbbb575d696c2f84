// The benchmark's tables, JSON, plot and report (bench_report.h); the goals are bench_goals.cpp's.
#include "analysis/bench_report.h"
#include "analysis/bench_material.h"
#include "analysis/bench_skips.h"
#include "analysis/frame_stats_json.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/number_format.h"
#include "dsr_text.h"
#include "analysis/plot.h"
#include "analysis/terminal_text.h"

namespace dsr::bench {

using json = nlohmann::ordered_json;

namespace {

std::string psnr_text(double db) { return std::isfinite(db) ? format_number("%.1f", db) : "inf"; }

}  // namespace

json row_json(const Row& r) {
    const bool deferred = r.renderer == Renderer::deferred;
    json j;
    j["scene"] = r.scene;
    j["renderer"] = renderer_name(r.renderer);
    j["accum"] = deferred ? json(accum_format_name(r.accum_format))
                 : r.float_accum ? json(*r.float_accum ? "float" : "rgba8") : json(nullptr);
    j["depth"] = deferred ? json(depth_path_name(r.depth)) : json(nullptr);
    j["encoding"] = deferred && r.depth == DepthPath::packed ? json(encoding_name(r.encoding)) : json(nullptr);
    j["gbuffer"] = deferred ? json(r.gbuffer_half ? "half" : "rgba8") : json(nullptr);
    j["gbuffer_bytes_per_pixel"] = r.gbuffer_bytes_per_pixel;  // 0: forward rows have no G-buffer
    j["light_geometry"] = deferred ? json(light_geometry_name(r.light_geometry)) : json(nullptr);
    j["tile_size"] = r.tile_size ? json(*r.tile_size) : json(nullptr);
    j["tile_lights"] = r.tile_lights ? json(*r.tile_lights) : json(nullptr);
    j["scissor"] = r.scissor;
    j["skips_off"] = skips_off(r.skip);
    j["linear_law"] = r.linear_law;
    j["lights"] = r.lights;
    j["lights_label"] = r.lights_label;
    j["size"] = {r.w, r.h};
    j["frames"] = r.frames;
    j["warmup_frames"] = r.warmup_frames;
    j["warmup_frames_ms"] = r.warmup_frames_ms;
    j["ms_median"] = r.ms_median;
    j["ms_min"] = r.ms_min;
    j["ms_max"] = r.ms_max;
    j["frames_ms"] = r.frames_ms;  // the timed frames, round by round (bench_run.h)
    j["cpu_ms_median"] = r.cpu_ms;
    j["cpu_frames_ms"] = r.cpu_frames_ms;
    j["cpu_alone_ms_median"] = r.cpu_alone_ms ? json(*r.cpu_alone_ms) : json(nullptr);
    j["cpu_alone_frames_ms"] = r.cpu_alone_frames_ms;
    j["goal_rounds_ms_median"] = r.goal_rounds_ms ? json(*r.goal_rounds_ms) : json(nullptr);
    j["goal_rounds_frames_ms"] = r.goal_rounds_frames_ms;
    j["goal_rounds_lights_ms_median"] = r.goal_rounds_lights_ms ? json(*r.goal_rounds_lights_ms) : json(nullptr);
    j["goal_rounds_lights_frames_ms"] = r.goal_rounds_lights_frames_ms;
    j["cpu_make_frame_ms"] = r.cpu_make_frame_ms ? json(*r.cpu_make_frame_ms) : json(nullptr);
    j["cpu_lights_ms"] = r.cpu_lights_ms ? json(*r.cpu_lights_ms) : json(nullptr);
    // The light counts are the counted frame's, under `frame`; the row holds them against the ideal.
    const std::optional<long long> frags = deferred ? light_fragments(r) : std::nullopt;
    const std::optional<long long> invocations = deferred ? light_invocations(r) : std::nullopt;
    j["ideal_fragments"] = deferred && r.ideal_fragments ? json(*r.ideal_fragments) : json(nullptr);
    j["fragments_ratio"] = frags && r.ideal_fragments && *r.ideal_fragments > 0
                               ? json(double(*frags) / double(*r.ideal_fragments))
                               : json(nullptr);
    j["passes"] = r.passes ? json(*r.passes) : json(nullptr);
    j["max_lsb"] = r.err.max_lsb();
    j["mean_lsb"] = r.err.mean_lsb();
    j["psnr_db"] = finite_or_null(r.err.psnr_db);
    j["max_lsb_analytic"] = r.err_analytic ? json(r.err_analytic->max_lsb()) : json(nullptr);
    j["mean_lsb_analytic"] = r.err_analytic ? json(r.err_analytic->mean_lsb()) : json(nullptr);
    j["psnr_db_analytic"] = r.err_analytic ? finite_or_null(r.err_analytic->psnr_db) : json(nullptr);
    auto opt = [](const auto& v) { return v ? json(*v) : json(nullptr); };
    j["invocations_ratio"] = invocations && r.ideal_fragments && *r.ideal_fragments > 0
                                 ? json(double(*invocations) / double(*r.ideal_fragments))
                                 : json(nullptr);
    j["evaluations_ratio"] = deferred ? opt(evaluations_ratio(r)) : json(nullptr);
    j["ideal_source"] = deferred ? opt(r.ideal_source) : json(nullptr);
    j["floor_fill_ms"] = opt(r.floor_fill_ms);
    j["floor_light_ns"] = opt(r.floor_light_ns);
    j["floor_post_ms"] = opt(r.floor_post_ms);
    j["floor_output_ms"] = opt(r.floor_output_ms);
    j["floor_ms"] = opt(r.floor_ms);
    j["floor_ratio"] = opt(r.floor_ratio);
    j["depth_copy_ms"] = opt(r.depth_copy_ms);
    j["lights_ms"] = opt(r.lights_ms);
    j["lights_frames_ms"] = r.renderer == Renderer::deferred ? json(r.lights_frames_ms) : json(nullptr);
    j["max_lsb_vs_quad"] = r.err_quad ? json(r.err_quad->max_lsb()) : json(nullptr);
    // The counted frame (docs/stats.md): its light counts, auto's choice; a forward row has none.
    j["frame"] = deferred && r.frame ? frame_stats_json(*r.frame) : json(nullptr);
    return j;
}


// Cells of one row, shared by the text table and the markdown table.
std::vector<std::string> table_cells(const Row& r) {
    auto ll = [](const std::optional<long long>& v) { return v ? std::to_string(*v) : std::string("-"); };
    const bool deferred = r.renderer == Renderer::deferred;
    const std::optional<long long> frags = light_fragments(r);
    std::string ratio = "-";
    if (deferred && frags && r.ideal_fragments && *r.ideal_fragments > 0)
        ratio = format_number("%.2f", double(*frags) / double(*r.ideal_fragments));
    std::vector<std::string> c = {r.scene,
                                  std::to_string(r.lights),
                                  config_text(r),
                                  std::to_string(r.frames),
                                  format_number("%.2f", r.ms_median),
                                  format_number("%.2f", r.ms_min) + "-" + format_number("%.2f", r.ms_max),
                                  deferred ? ll(frags) : "-",
                                  deferred ? ll(r.ideal_fragments) : "-",
                                  ratio,
                                  format_number("%.0f", r.err.max_lsb()),
                                  format_number("%.3f", r.err.mean_lsb()),
                                  psnr_text(r.err.psnr_db)};
    if (r.err_analytic) {
        c.push_back(format_number("%.0f", r.err_analytic->max_lsb()));
        c.push_back(format_number("%.3f", r.err_analytic->mean_lsb()));
        c.push_back(psnr_text(r.err_analytic->psnr_db));
    } else {
        c.insert(c.end(), {"-", "-", "-"});
    }
    c.push_back(deferred ? ll(light_invocations(r)) : "-");
    c.push_back(deferred ? ll(light_evaluations(r)) : "-");
    const std::optional<double> er = deferred ? evaluations_ratio(r) : std::nullopt;
    c.push_back(er ? format_number("%.2f", *er) : "-");
    c.push_back(r.floor_ms ? format_number("%.2f", *r.floor_ms) : "-");
    c.push_back(r.floor_ratio ? format_number("%.2f", *r.floor_ratio) : "-");
    c.push_back(format_number("%.2f", r.cpu_ms));
    c.push_back(deferred ? std::to_string(r.gbuffer_bytes_per_pixel) : "-");  // no G-buffer: forward
    return c;
}

const std::vector<std::string>& table_header() {
    static const std::vector<std::string> h = {"scene", "lights", "configuration", "frames", "ms med", "ms min-max",
                                               "light frags", "ideal", "ratio", "max LSB", "mean LSB", "PSNR dB",
                                               "an. max", "an. mean", "an. PSNR", "invocations", "evaluations",
                                               "eval/ideal",
                                               "floor ms", "floor ratio", "cpu ms", "G-buf B/px"};
    return h;
}

std::string markdown_table(const std::vector<Row>& rows) {
    const std::vector<std::string>& kHeader = table_header();
    std::ostringstream out;
    out << "|";
    for (auto& h : kHeader) out << " " << h << " |";
    out << "\n|";
    for (size_t i = 0; i < kHeader.size(); ++i) out << (i == 0 || i == 2 ? " --- |" : " ---: |");
    out << "\n";
    for (const Row& r : rows) {
        out << "|";
        for (auto& c : table_cells(r)) out << " " << c << " |";
        out << "\n";
    }
    return out.str();
}

Image plot_rows(const std::vector<Row>& rows, const std::vector<std::string>& scenes) {
    std::vector<PlotPanel> panels;
    const glm::vec3 grey(0.7f);
    for (const std::string& scene : scenes) {
        bool analytic = false;
        for (const Row& r : rows)
            if (r.scene == scene && r.err_analytic) analytic = true;
        PlotPanel p;
        p.title = scene + (analytic ? " scene: error vs analytic" : " scene: error vs forward");
        p.x_label = "MS PER FRAME (MEDIAN)";
        p.y_label = analytic ? "MEAN ERROR (LSB) VS ANALYTIC" : "MEAN ERROR (LSB) VS FORWARD";
        p.y_floor = 0.01;  // below a hundredth of an LSB on average: a few pixels at most, or none
        PlotSeries def{"dsr default (auto light geometry)", {0.1f, 0.35f, 0.85f}, {}};
        PlotSeries single{"forward single-pass (listing 3)", {0.1f, 0.65f, 0.2f}, {}};
        PlotSeries multi{"forward multi-pass (listing 4)", {0.85f, 0.2f, 0.1f}, {}};
        PlotSeries other{"other deferred configurations", grey, {}};
        auto point = [&](const Row& r, bool labelled) {
            PlotPoint pt;
            pt.x = r.ms_median;
            pt.y = analytic ? r.err_analytic->mean_lsb() : r.err.mean_lsb();
            pt.radius = labelled ? 3 : 2;
            if (labelled) pt.label = std::to_string(r.lights);  // the light count beside the dot
            return pt;
        };
        std::vector<int> counts;
        for (const Row& r : rows)
            if (r.scene == scene && std::find(counts.begin(), counts.end(), r.lights) == counts.end()) counts.push_back(r.lights);
        for (int n : counts) {
            const Row* d = find_default_row(rows, scene, n);
            const Row* fs = fastest_row(rows, scene, n, Renderer::forward_single);
            const Row* fm = fastest_row(rows, scene, n, Renderer::forward_multi);
            for (const Row& r : rows) {
                if (r.scene != scene || r.lights != n) continue;
                if (analytic && !r.err_analytic) continue;  // the linear-law rows: the trace has the scene's law
                if (&r == d) def.points.push_back(point(r, true));
                else if (&r == fs) single.points.push_back(point(r, true));
                else if (&r == fm) multi.points.push_back(point(r, true));
                else if (r.renderer == Renderer::deferred) other.points.push_back(point(r, false));
            }
        }
        p.series = {other, single, multi, def};  // dsr's default drawn last, over the others
        panels.push_back(p);
    }
    return scatter_plot(panels, 480, 420);
}

json to_json(const Summary& s) {
    const Config& cfg = s.config;
    json j;
    j["machine"] = s.machine;
    j["gl_renderer"] = s.gl_renderer;
    j["gl_version"] = s.gl_version;
    j["config"] = {{"quick", cfg.quick}, {"size", {cfg.w, cfg.h}}, {"frames", cfg.frames}, {"warmup", cfg.warmup}, {"compile_warmup", cfg.compile_warmup},
                   {"lights", cfg.lights_text}, {"scenes", s.scenes}};
    std::vector<std::string> geometries;
    for (LightGeometry g : cfg.geometries) geometries.push_back(light_geometry_name(g));
    j["config"]["light_geometries"] = geometries;
    j["seconds"] = s.seconds;
    j["goals"] = s.goals;
    if (s.invocation_probe)
        j["invocation_probe"] = {{"pixels", s.invocation_probe->pixels},
                                 {"invocations", s.invocation_probe->invocations},
                                 {"samples_passed", s.invocation_probe->samples}};
    else
        j["invocation_probe"] = nullptr;
    j["notes"] = s.notes;
    j["skip_savings"] = skip_savings_json(skip_savings(s.rows));
    j["rows"] = json::array();
    for (const Row& r : s.rows) j["rows"].push_back(row_json(r));
    return j;
}

double time_spread(const Row& r) {
    std::vector<double> f = r.frames_ms;
    if (f.size() < 2 || !(r.ms_median > 0)) return 0;
    std::sort(f.begin(), f.end());
    const auto quartile = [&](double q) {  // linear between the two nearest frames
        const double at = q * double(f.size() - 1);
        const size_t i = size_t(at);
        return i + 1 < f.size() ? f[i] + (at - double(i)) * (f[i + 1] - f[i]) : f[i];
    };
    return (quartile(0.75) - quartile(0.25)) / 2 / r.ms_median;
}

std::string time_text(const Row& r) {
    return format_number("%.2f", r.ms_median) + " ±" + format_number("%.0f", 100 * time_spread(r)) + "%";
}

std::string rows_text(const std::vector<Row>& rows) {
    std::vector<std::string> scenes;
    for (const Row& r : rows)
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    std::string out;
    for (const std::string& scene : scenes) {
        std::vector<std::pair<int, std::string>> counts;  // light count, its --lights entry
        std::vector<std::string> configs;
        int w = 0, h = 0;
        for (const Row& r : rows) {
            if (r.scene != scene) continue;
            w = r.w, h = r.h;
            if (std::find_if(counts.begin(), counts.end(), [&](const auto& c) { return c.first == r.lights; }) == counts.end())
                counts.push_back({r.lights, r.lights_label});
            const std::string words = row_words(r);
            if (std::find(configs.begin(), configs.end(), words) == configs.end()) configs.push_back(words);
        }
        std::vector<std::string> header = {"configuration"};
        std::vector<bool> right = {false};
        for (const auto& [n, label] : counts) {
            const std::string lights = std::to_string(n) + (n == 1 ? " light" : " lights") +
                                       (label == "own" ? " (its own)" : "");
            header.push_back(lights + ": ms");
            header.push_back("max LSB");
            right.insert(right.end(), {true, true});
        }
        std::vector<std::vector<std::string>> cells;
        for (const std::string& c : configs) {
            std::vector<std::string> line = {c};
            for (const auto& count : counts) {
                const Row* found = nullptr;
                for (const Row& r : rows)
                    if (r.scene == scene && r.lights == count.first && row_words(r) == c) found = &r;
                line.push_back(found ? time_text(*found) : "");
                line.push_back(found ? format_number("%.0f", found->err.max_lsb()) : "");
            }
            cells.push_back(line);
        }
        out += (out.empty() ? "" : "\n") + std::string("The ") + scene + " scene at " + std::to_string(w) + "x" +
               std::to_string(h) + ": the median frame in ms, ± half the middle half of the frames' range; max LSB, "
               "the image's largest difference from forward single-pass with float sums (the reference). Deferred "
               "rows draw a quad per light where they name no other light geometry.\n" +
               text_table(header, cells, right);
    }
    return wrap_lines(out);
}

Conclusions conclusions(const std::vector<Row>& rows, const std::string& scene, const std::vector<GoalResult>& goals) {
    Conclusions c;
    c.scene = scene;
    for (const Row& r : rows)
        if (r.scene == scene && find_default_row(rows, scene, r.lights)) c.lights = std::max(c.lights, r.lights);
    c.default_row = find_default_row(rows, scene, c.lights);
    c.forward_single = fastest_row(rows, scene, c.lights, Renderer::forward_single);
    c.forward_multi = fastest_row(rows, scene, c.lights, Renderer::forward_multi);
    for (const Row* r : fixed_geometry_rows(rows, scene, c.lights))
        if (!c.fastest_geometry || r->ms_median < c.fastest_geometry->ms_median) c.fastest_geometry = r;
    std::vector<double> spreads;
    for (const Row& r : rows) {
        if (r.frames_ms.size() >= 2) spreads.push_back(time_spread(r));
        // The metallic-roughness rows' reference draws their materials as Phong (Row::metal_rough).
        if (r.renderer != Renderer::deferred || r.metal_rough) continue;
        if (find_default_row(rows, r.scene, r.lights) == &r) c.default_max_lsb = std::max(c.default_max_lsb, r.err.max_lsb());
        if (r.err.max_lsb() > c.deferred_max_lsb) c.deferred_max_lsb = r.err.max_lsb(), c.worst_deferred = &r;
    }
    if (!spreads.empty()) {
        std::sort(spreads.begin(), spreads.end());
        c.spread = spreads[spreads.size() / 2];
    }
    const Row* d = c.default_row;
    const std::string at = " at " + std::to_string(c.lights) + " lights on the " + scene + " scene";
    if (d) {
        std::string l = "Speed: dsr's default (" + row_words(*d) + ") draws a frame in " + format_number("%.2f", d->ms_median) +
                        " ms" + at;
        std::vector<std::string> fw;
        for (const Row* f : {c.forward_single, c.forward_multi})
            if (f)
                fw.push_back(format_number("%.2f", f->ms_median) + " ms with " +
                             (f->renderer == Renderer::forward_single ? "a pass per object" : "a pass per light") + " (" +
                             format_number("%.1f", f->ms_median / d->ms_median) + "x as long)");
        if (!fw.empty()) l += "; forward shading takes " + joined(fw, " and ");
        c.lines.push_back(l + ".");
    }
    if (c.fastest_geometry && d)
        c.lines.push_back("Light geometry: the fastest fixed one" + at + " is " +
                          light_geometry_name(c.fastest_geometry->light_geometry) + " (" +
                          format_number("%.2f", c.fastest_geometry->ms_median) + " ms)" +
                          (d->light_geometry == LightGeometry::automatic
                               ? "; auto, which picks a path per light by its predicted time, takes " +
                                     format_number("%.2f", d->ms_median) + " ms."
                               : std::string("; the run has no auto row.")));
    for (const MaterialCost& m : material_costs(rows))
        if (m.phong->scene == scene && m.phong->lights == c.lights)
            c.lines.push_back("Material model: " + material_cost_text(m) + ".");
    if (c.default_max_lsb >= 0)
        c.lines.push_back("Image: dsr's default differs from the forward reference by at most " +
                          format_number("%.0f", c.default_max_lsb) + " LSB in every row" +
                          (c.worst_deferred ? "; the largest difference of any deferred configuration is " +
                                                  format_number("%.0f", c.deferred_max_lsb) + " LSB (" +
                                                  row_words(*c.worst_deferred) + ", the " + c.worst_deferred->scene +
                                                  " scene at " + std::to_string(c.worst_deferred->lights) + " lights)"
                                            : std::string()) +
                          ".");
    int met = 0, not_met = 0, not_judged = 0;
    for (const GoalResult& g : goals)
        ++(g.verdict == Verdict::met ? met : g.verdict == Verdict::not_met ? not_met : not_judged);
    if (!goals.empty())
        c.lines.push_back("Goals: " + std::to_string(met) + " met, " + std::to_string(not_met) + " not met, " +
                          std::to_string(not_judged) + " not judged" +
                          (not_judged ? " (most need rows only the full `dsr bench` measures: 1024 lights, "
                                        "1024-overlap, 32-large, 1920x1080)"
                                      : std::string()) +
                          ".");
    if (c.spread >= 0)
        c.lines.push_back("Timing: the middle half of a row's frames lies within ±" + format_number("%.0f", 100 * c.spread) +
                          "% of its median (the median row); a difference between two rows smaller than that is noise.");
    return c;
}

std::string text_summary(const Summary& s, const std::string& report_path, const std::string& json_path) {
    const Config& cfg = s.config;
    const std::string scene = s.scenes.empty() ? std::string() : s.scenes[0];
    std::ostringstream o;
    o << "dsr bench" << (cfg.quick ? " --quick" : "") << ": " << s.rows.size() << " rows in "
      << format_number("%.0f", s.seconds) << " s at " << cfg.w << "x" << cfg.h << ", " << cfg.frames
      << " timed frames a row, on " << s.gl_renderer << ", OpenGL " << s.gl_version << "\n\n";
    o << "What this run shows:\n";
    for (const std::string& l : conclusions(s.rows, scene, s.goal_results).lines) o << "- " << l << "\n";
    o << "\nGoals, on the " << scene << " scene:\n";
    for (const GoalResult& g : s.goal_results) {
        const char* verdict = g.verdict == Verdict::met ? "met       " : g.verdict == Verdict::not_met ? "NOT met   " : "not judged";
        const Figure& f = g.figure;
        o << "  " << verdict << "  " << g.plain << ": " << (f.judged || f.brief.empty() ? f.working : f.brief)
          << (f.judged ? f.after : std::string()) << "\n";
    }
    o << "\n" << rows_text(s.rows) << "\n";
    if (!report_path.empty())
        o << "The report (each goal's working"
          << (s.notes.empty() ? std::string() : s.notes.size() == 1 ? ", the note" : ", the " + std::to_string(s.notes.size()) + " notes")
          << ", every row's fragments, floor and CPU time, the plot): " << report_path << "\n";
    if (!json_path.empty()) o << "Every row as JSON: " << json_path << "\n";
    o << "Exit status 0: the run completed (goals not met are findings, not errors).\n";
    return wrap_lines(o.str());
}

std::string light_geometry_markdown(const std::vector<Row>& rows) {
    std::ostringstream md;
    md << "## Light geometries\n\n"
          "How each light reaches its pixels (`--light-geometry`, docs/light_geometry.md), each on the default "
          "configuration (depth texture, scissor, every skip). *invocations*: fragments that entered the light "
          "shader (ARB_pipeline_statistics_query; llvmpipe counts 16 per 4x4 block each triangle touches, before "
          "its depth and stencil tests, so its counts favour the two-triangle quads); *evaluations*: each draw's "
          "invocations times the lights each of its fragments evaluates (one for a light's own pass; screen: the "
          "batch's lights; tiles: the tile's list), the pixel-light pairs paid for; *ideal*: pixel-light pairs "
          "whose surface point is inside the light's volume; *frags*: samples that passed (tiles and screen: per "
          "pixel and pass, not per light); *copy ms*: the depth hand-off.\n\n"
          "- `quad`: the tutorial's scissored quad per light (§3.4.2): every pixel of the rectangle runs the shader.\n"
          "- `volume`: the back faces of the light's volume mesh, depth test GL_GREATER against the scene depth "
          "handed to P-buffer 0; front faces culled, so the camera may be inside.\n"
          "- `stencil`: per light a two-sided stencil pass over the mesh (depth-fail counting), then the light "
          "pass only where the stencil is non-zero: the surface points inside the volume.\n"
          "- `tiles`: screen tiles; each tile's lights from their scissor rectangles, up to N per pass in one "
          "shader, so the G-buffer is read and P-buffer 0 blended once per N lights.\n\n"
          "| scene | lights | geometry | ms med | invocations | evaluations | ideal | eval/ideal | frags | passes | "
          "copy ms | max LSB vs quad |\n| --- | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | "
          "---: |\n";
    auto ll = [](const std::optional<long long>& v) { return v ? std::to_string(*v) : std::string("-"); };
    for (const Row& r : rows) {
        if (!default_configuration(r)) continue;
        const std::optional<double> er = evaluations_ratio(r);
        md << "| " << r.scene << " | " << r.lights_label << " (" << r.lights << ") | "
           << light_geometry_name(r.light_geometry) << " | "
           << format_number("%.2f", r.ms_median) << " | " << ll(light_invocations(r)) << " | "
           << ll(light_evaluations(r)) << " | " << ll(r.ideal_fragments) << " | "
           << (er ? format_number("%.2f", *er) : std::string("-"))
           << " | " << ll(light_fragments(r)) << " | " << (light_passes(r) ? std::to_string(*light_passes(r)) : "-")
           << " | " << (r.depth_copy_ms ? format_number("%.2f", *r.depth_copy_ms) : "-") << " | "
           << (r.err_quad ? format_number("%.0f", r.err_quad->max_lsb()) : "-") << " |\n";
    }
    md << "\n";
    return md.str();
}

namespace {

// " (N-large at 800x600, ...)": the variants that ran at a size of their own (bench_run.h variant_size).
std::string large_size(const std::vector<Row>& rows, const Config& cfg) {
    for (const Row& r : rows)
        if (r.w != cfg.w || r.h != cfg.h)
            return " (N-large at " + std::to_string(r.w) + "x" + std::to_string(r.h) + ", LearnOpenGL's demo's size)";
    return "";
}

}  // namespace

std::string markdown_report(const Summary& s, const std::string& plot_name) {
    const Config& cfg = s.config;
    std::ostringstream md;
    md << "# Benchmarks\n\n"
       << "Written by `make bench` (`build/dsr bench --json docs/benchmarks.json --report docs/benchmarks/report.md`); "
          "do not edit by hand. Raw numbers: `docs/benchmarks.json`.\n\n"
       << "- Machine: " << s.machine << "\n"
       << "- GL renderer: " << s.gl_renderer << ", OpenGL " << s.gl_version << " (" << s.gl_vendor << ")\n"
       << "- Size " << cfg.w << "x" << cfg.h << large_size(s.rows, cfg) << "; each row: warm-up frames until " << cfg.warmup
       << " in a row build no shader program and, in auto's rows, explore no light path (at most "
       << cfg.warmup + cfg.compile_warmup << ": the JSON's `warmup_frames` and `warmup_frames_ms`), then the median "
       << "and min-max of " << cfg.frames << " timed frames" << large_frames_note(cfg) << " (fewer where one frame takes over 2 s: the `frames` "
       << "column), all rows in one process; whole run " << format_number("%.0f", s.seconds) << " s.\n"
       << "- Post-processing off in every row.\n\n"
       << "## Goals\n\nJudged on the default deferred configuration (depth texture, scissor on, every skip on); "
          "the speed goal against the faster forward multi-pass row (float or RGBA8 accumulation) of the same run. "
          "`floor`, `demo` and `cpu` take dsr's default light geometry, auto (quad where the run has no auto row); `demo` "
          "against the screen rows, LearnOpenGL's deferred demo's lighting pass (every light at every pixel, one "
          "full-screen pass), on 32-large at the demo's 800x600. `law` times dsr's default light stage on 32-large "
          "against the same frame with every light given the tutorial's linear law at its own radius (the "
          "`linear-law` rows, on the same pixel-light pairs); within 5%, the medians' noise. `auto` compares the "
          "auto geometry with the fastest fixed one on each bench scene. Both are judged in rounds of their own "
          "after the rounds of every row: the rows they compare (auto's, each fixed geometry's within "
       << format_number("%.1f", kGoalRoundsWithin) << "x of the fastest, dsr's default and its linear-law twin), "
       << "those alone, " << kGoalRoundsFactor
       << "x as many rounds (JSON `goal_rounds_frames_ms`, `goal_rounds_lights_frames_ms`); the rounds of every "
          "row's figure follows as information. `floor` is judged at "
          "1920x1080 with 1024 lights and on 32-large only (the floor leaves out the frame's fixed costs, which weigh more the smaller the frame; elsewhere its figure is "
          "information), `cpu` where the run has 4096 lights, on the default row's frames run again back to back "
          "after the rounds, as an application draws them (in the rounds each frame follows the other rows' and "
          "finds the caches holding their data; JSON `cpu_alone_frames_ms`, the rounds' `cpu_frames_ms`). The goal of a deferred row 1.5x faster than forward "
          "single-pass on 32-large is withdrawn: on GL 2.x forward single-pass is the bound there; its figure "
          "follows `demo` as information. A goal that compares two rows ends with its figure round by round (the "
          "rows' frames run in rounds, one frame of each row a round): the range, and in how many rounds the goal "
          "held; a verdict on the medians that holds in few rounds is the machine's noise. Indented lines are "
          "information, not goals.\n\n";
    for (auto& g : s.goals) md << "- " << g << "\n";
    for (auto& n : s.notes) md << "\nNote: " << n << ".\n";
    md << "\n## Run time against error\n\n![run time against error](" << plot_name << ")\n\n"
       << "One panel per scene, both axes logarithmic: x is the median frame time in ms, y the mean "
          "absolute error in 8-bit LSB (RGB), against the forward reference for the default scene and "
          "against the analytic reference (interior pixels) for the analytic scene. Blue: dsr's default (auto "
          "light geometry); green: forward single-pass, red: forward multi-pass (each the faster of its float and "
          "RGBA8 forms); each of these dots labelled with its light count (" << cfg.lights_text << "; `own` is the "
          "scene's own lights). Grey: every other deferred row. A ring on the bottom axis is a mean error below "
          "0.01 LSB (exactly 0 for forward single-pass, which *is* the forward reference).\n\n"
       << "## How the floor is made\n\n"
          "Measured in the same run, on the same context and at the same size as the rows "
          "(`src/analysis/bench_floor.h`), once per scene variant and G-buffer layout:\n\n"
          "- (a) *G-buffer fill floor*: the scene's triangles drawn once, without a depth pre-pass, through a "
          "trivial shader (`glsl120/floor_fill.vert`/`.frag`: `ftransform()`, constants into every target) into a "
          "buffer with the row's G-buffer targets (same count and formats, RGBA8 or half; a depth texture on the "
          "depth-texture path, a depth renderbuffer on the packed path), after one clear of colour and depth; "
          "depth test `GL_LEQUAL` with depth writes, back faces culled. Timed like a row (glFinish, wall clock) "
          "in the rows' interleaved rounds; the median.\n"
          "- (b) *per-fragment cost of a light pass*: a full-screen quad through `glsl120/floor_light.frag` (one "
          "`texture2D` of each of the four G-buffer targets the light shader reads: normal, diffuse, specular, "
          "depth; one colour written, additive blending into an RGBA8 target like P-buffer 0), drawn back to back "
          "as many times as make about 30 ms (at least 2); the median over 5 batches of batch time / (passes x "
          "width x height).\n"
          "- (c) *post floor*: each post pass's texel reads over its buffer (bloom: two blurs of `bloom_taps` "
          "reads at 1/`bloom_scale`, one add; anti-alias: 9 reads per source and 9 of the colour), each read "
          "costed at (b) / 4. Every row here runs with post off, so (c) = 0 in every row.\n"
          "- (d) *output floor*: one clear of an RGBA8 target like P-buffer 0. (b) writes only the lit pixels, "
          "but a frame writes every pixel of its output at least once (the background, the ambient term): "
          "without (d) the floor's image would be undefined wherever no light reaches. Timed like (b): batches of "
          "n clears, each followed by a one-pixel point (so that no GL merges a clear into the next), against "
          "batches of the n points alone, about 30 ms a batch; (d) = the difference of the two medians / n, "
          "once per scene variant (the target is the same whatever the G-buffer layout).\n\n"
          "*floor ms* = (a) + *ideal* x (b) + (c) + (d); *floor ratio* = *ms med* / *floor ms* (goal "
       << goal_bound(goal("floor")) << "). The "
          "floor leaves out what a deferred frame does beyond these (the ambient term's reads and arithmetic, a "
          "pass of its own or one more target the material pass writes, the copy to the main "
          "buffer, per-light set-up), so it is a lower bound, not a target any renderer is known to reach. The "
          "parts of each row are in the JSON (`floor_fill_ms`, `floor_light_ns`, `floor_post_ms`, `floor_output_ms`).\n\n"
       << light_geometry_markdown(s.rows)
       << skip_savings_markdown(skip_savings(s.rows))
       << material_cost_markdown(s.rows)
       << "## Table\n\n"
       << "- *configuration*: `deferred DEPTH[/ENCODING] sc|-` (scissor on or off), `half` for half-float "
          "G-buffer targets (RGBA8 otherwise, as the tutorial), `accum-half` / `accum-float` for P-buffer 0 in "
          "RGBA16F / RGBA32F (docs/hdr.md; JSON `accum`), and `no-SKIP` for a skip turned off (all "
          "are on otherwise; `no-ambient_target no-ambient_pass` draws the tutorial's ambient pass, "
          "`no-ambient_target` alone the fold where a light covers the screen); `forward-single` is Listing 3 (all of an object's lights "
          "in one pass), `forward-multi` Listing 4 (one additive pass per light and object); `float`: they "
          "accumulate in an RGBA32F target copied to the main buffer once, `rgba8`: straight into the RGBA8 main "
          "buffer, every additive pass rounded to 8 bits, as the tutorial would have run them (JSON `accum`).\n"
       << "- *light frags*: samples that passed the light passes (occlusion queries): what survived the "
          "in-shader light tests. *invocations*: fragments that entered the light shader, summed over the light "
          "passes (ARB_pipeline_statistics_query, `GL_FRAGMENT_SHADER_INVOCATIONS_ARB`): what the passes pay; "
          "`-` (JSON null) where the GL lacks the query. *evaluations*: each light draw's invocations times the "
          "lights each of its fragments evaluates, summed (one for a light's own pass, the batch's lights for "
          "screen's full-screen passes, the tile's list for the tiles): the pixel-light pairs paid for, which is "
          "what compares with the ideal where a pass shades several lights. *ideal*: pixels whose exact surface "
          "point lies strictly "
          "inside a light's sphere, summed over the lights with non-zero colour, in double precision and "
          "independent of the light shader's arithmetic: from the analytic trace's exact eye depth for the "
          "scenes with constant materials, otherwise from the G-buffer's 24-bit depth read back as integers and "
          "inverted through the projection in double (JSON `ideal_source`: `analytic` | `depth24`). *ratio* = "
          "light frags / ideal (the sphere test makes it about 1 by construction); *eval/ideal* = evaluations / "
          "ideal (the goal).\n"
       << "- *max LSB*, *mean LSB*, *PSNR*: the final image against the forward single-pass reference "
          "(float accumulation) of the same scene and size. *an.*: against the analytic reference (double-"
          "precision ray tracing, Equations 1-6) on pixels away from silhouettes, for scenes with constant "
          "materials.\n"
       << "- Scenes with 32 or more lights are the scene's geometry with generated lights "
          "(`src/analysis/bench_scenes.h`): stratified over the floor, each floor point in about 2.5 spheres, "
          "every 8th light switched off (colour 0); `large` (`N-large`) is LearnOpenGL's deferred shading demo "
          "instead: its 9 objects as unit boxes, its camera, its `srand(13)` lights with its attenuation law "
          "(docs/light_geometry.md, \"32-large\").\n\n"
       << markdown_table(s.rows);
    return md.str();
}

}  // namespace dsr::bench
