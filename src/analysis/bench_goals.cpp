// The bench's goal table and its judge (bench_goals.h): one measure per goal, one printer for all.
#include "analysis/bench_goals.h"

#include <cstring>

#include "analysis/number_format.h"
#include "dsr_error.h"

namespace dsr::bench {

namespace {

const char* const kNotMeasured = "not measured in this run";

std::string ms(double v) { return format_number("%.2f", v) + " ms"; }

// "a / b = a/b" with three decimals: the working of a count against the ideal.
std::string over(long long a, long long b) {
    return std::to_string(a) + " / " + std::to_string(b) + " = " + format_number("%.3f", double(a) / double(b));
}

// `brief`: the reason in a few words, where `why` runs long.
Figure not_judged(std::string why = kNotMeasured, std::string brief = "") {
    Figure f;
    f.working = std::move(why);
    f.brief = std::move(brief);
    return f;
}

Figure judged(double value, double scale, std::string working) {
    Figure f;
    f.judged = true;
    f.value = value, f.scale = scale;
    f.working = std::move(working);
    return f;
}

bool met(const Goal& g, const Figure& f) {
    return g.comparison == Comparison::at_most ? f.value <= g.threshold * f.scale : f.value >= g.threshold * f.scale;
}

// The rows that turned off the light sphere test alone: the depth-span test without it.
bool only_sphere_test_off(const Row& r) {
    SkipOptions only;
    only.light_sphere_test = false;
    return skips_off(r.skip) == skips_off(only);
}

// light_invocations against the ideal, on the default configuration; what passed the light
// passes (and the rows without the sphere test) as information.
Figure invocations(const Goal& g, const GoalInput& in) {
    const Row* d = find_row(in.rows, in.scene, in.lights, Renderer::deferred);
    const bool ideal = d && d->ideal_fragments && *d->ideal_fragments > 0;
    Figure f = !ideal                  ? not_judged()
               : !d->light_invocations ? not_judged(std::string(kNotMeasured) +
                                                    " (the GL lacks ARB_pipeline_statistics_query)",
                                                kNotMeasured)
                                       : judged(double(*d->light_invocations), double(*d->ideal_fragments),
                                                over(*d->light_invocations, *d->ideal_fragments));
    if (!ideal) return f;
    if (d->light_fragments) {
        if (d->skip.light_sphere_test)
            f.info.push_back("(information, not a goal: light_fragments / ideal = " +
                             over(*d->light_fragments, *d->ideal_fragments) +
                             "; it holds by construction, since the light sphere test discards every fragment "
                             "whose surface point lies outside the sphere and the ideal counts the points inside)");
        else
            f.info.push_back("(information: light_fragments / ideal = " +
                             over(*d->light_fragments, *d->ideal_fragments) + ")");
    }
    for (const Row& r : in.rows)
        if (r.scene == in.scene && r.lights == in.lights && r.renderer == Renderer::deferred &&
            only_sphere_test_off(r) && r.light_fragments)
            f.info.push_back("(information, with the depth-span test only, --no-skip light-sphere-test: "
                             "light_fragments / ideal = " + over(*r.light_fragments, *d->ideal_fragments) +
                             (r.light_invocations ? "; light_invocations / ideal = " +
                                                        over(*r.light_invocations, *d->ideal_fragments)
                                                  : std::string()) +
                             ")");
    return f;
}

// The frame against what the same work could cost at least (bench_floor.h).
Figure against_floor(const Goal& g, const GoalInput& in) {
    const Row* d = find_row(in.rows, in.scene, in.lights, Renderer::deferred);
    if (!d || !d->floor_ratio || !d->floor_ms) return not_judged();
    return judged(*d->floor_ratio, 1,
                  ms(d->ms_median) + " / " + ms(*d->floor_ms) + " = " + format_number("%.2f", *d->floor_ratio));
}

// Deferred against the faster forward multi-pass row (float or RGBA8 accumulation).
Figure speed(const Goal& g, const GoalInput& in) {
    const int n = std::stoi(g.on);
    const Row* d = find_row(in.rows, in.scene, n, Renderer::deferred);
    const Row* m = fastest_row(in.rows, in.scene, n, Renderer::forward_multi);
    if (!d || !m) return not_judged();
    const double ratio = m->ms_median / d->ms_median;
    return judged(ratio, 1,
                  config_text(*m) + " " + ms(m->ms_median) + " / " + ms(d->ms_median) + " = " +
                      format_number("%.1f", ratio) + "x");
}

// The stencil geometry's invocations against the ideal, where the GL's counter can tell.
Figure stencil(const Goal& g, const GoalInput& in) {
    const Row* s = find_geometry_row(in.rows, in.scene, in.lights, LightGeometry::stencil);
    if (!s || !s->ideal_fragments || *s->ideal_fragments <= 0 || !s->light_invocations) return not_judged();
    if (in.probe && in.probe->counts_rejected())
        // The counter cannot tell what the stencil let through from what it rejected.
        return not_judged("cannot be judged on this GL: its fragment-shader invocation counter counts fragments "
                          "the stencil test rejects (probe: " + std::to_string(in.probe->invocations) +
                          " invocations for " + std::to_string(in.probe->pixels) +
                          " pixels that all fail the stencil test); invocations " +
                          over(*s->light_invocations, *s->ideal_fragments) +
                          (s->light_fragments ? "; what passed the stencil (occlusion query) " +
                                                    over(*s->light_fragments, *s->ideal_fragments) + " (information)"
                                              : std::string()),
                          "cannot be judged on this GL (see the report)");
    return judged(double(*s->light_invocations), double(*s->ideal_fragments),
                  over(*s->light_invocations, *s->ideal_fragments));
}

// Tiles against quad on the scene the light generators name by the goal's --lights entry
// (bench_scenes.h), whichever scene carries it.
Figure tiles(const Goal& g, const GoalInput& in) {
    const Row* tq = nullptr;
    const Row* tt = nullptr;
    for (const Row& r : in.rows)
        if (r.scene.find(g.on) != std::string::npos || r.lights_label == g.on) {
            if (!tq) tq = find_geometry_row(in.rows, r.scene, r.lights, LightGeometry::quad);
            if (!tt) tt = find_geometry_row(in.rows, r.scene, r.lights, LightGeometry::tiles);
        }
    if (!tq || !tt) return not_judged();
    return judged(tq->ms_median, tt->ms_median,
                  ms(tq->ms_median) + " / " + ms(tt->ms_median) + " = " +
                      format_number("%.2f", tq->ms_median / tt->ms_median) + "x");
}

// The fastest deferred row (every skip, RGBA8 G-buffer; any depth path, scissor or geometry)
// against the faster forward single-pass row, on the large lights; with the same rows on the scene
// without lights (count 0 of the same set), what the threshold leaves the deferred row for its lights.
Figure large(const Goal& g, const GoalInput& in) {
    const Row* best = nullptr;
    const Row* fwd = nullptr;
    for (const Row& r : in.rows)
        if (r.lights_label == g.on) {
            if (r.renderer == Renderer::deferred && skips_off(r.skip).empty() && !r.gbuffer_half &&
                (!best || r.ms_median < best->ms_median))
                best = &r;
            if (r.renderer == Renderer::forward_single && (!fwd || r.ms_median < fwd->ms_median)) fwd = &r;
        }
    if (!best || !fwd) return not_judged();
    const std::string unlit = std::string("0") + std::strchr(g.on, '-');  // "32-large" -> "0-large"
    const Row* fwd0 = nullptr;
    const Row* best0 = nullptr;
    for (const Row& r : in.rows)
        if (r.lights_label == unlit) {
            if (r.renderer == fwd->renderer && config_text(r) == config_text(*fwd)) fwd0 = &r;
            if (r.renderer == best->renderer && config_text(r) == config_text(*best)) best0 = &r;
        }
    Figure f = judged(fwd->ms_median, best->ms_median,
                      config_text(*fwd) + " " + ms(fwd->ms_median) + " / " + config_text(*best) + " " +
                          ms(best->ms_median) + " = " + format_number("%.2f", fwd->ms_median / best->ms_median) +
                          "x");
    if (fwd0 && best0 && best->ideal_fragments)
        f.after = "; without lights (" + unlit + ") " + format_number("%.2f", fwd0->ms_median) + " and " +
                  ms(best0->ms_median) + ", so forward's light work takes " +
                  ms(fwd->ms_median - fwd0->ms_median) + " and " + format_number("%g", g.threshold) +
                  "x leaves the deferred row " + ms(fwd->ms_median / g.threshold - best0->ms_median) + " for " +
                  std::to_string(*best->ideal_fragments) + " ideal pixel-light pairs (information)";
    return f;
}

// Every geometry's image against quad's, every scene variant of the run: the largest difference.
Figure geometry_lsb(const Goal& g, const GoalInput& in) {
    double worst = -1;
    std::string worst_row;
    int compared = 0;
    for (const Row& r : in.rows)
        if (r.renderer == Renderer::deferred && r.err_quad && r.light_geometry != LightGeometry::quad) {
            ++compared;
            if (r.err_quad->max_lsb() > worst) {
                worst = r.err_quad->max_lsb();
                worst_row = config_text(r) + ", " + r.scene + " at " + std::to_string(r.lights) + " lights";
            }
        }
    if (compared == 0) return not_judged();
    return judged(worst, 1,
                  "largest " + format_number("%.0f", worst) + " LSB (" + worst_row + ", " + std::to_string(compared) +
                      " rows)");
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
}

// A goal's sentence (`text`: its sentence or its plain one) for this scene and light count; [...] kept (brackets dropped) on a judged line.
std::string sentence(const char* text, const Goal& g, const GoalInput& in, bool judged_line) {
    std::string s = text;
    for (size_t open = s.find('['); open != std::string::npos; open = s.find('[', open)) {
        const size_t close = s.find(']', open);
        if (judged_line) {
            s.erase(close, 1);
            s.erase(open, 1);
        } else {
            s.erase(open, close - open + 1);
        }
    }
    replace_all(s, "{cmp words}", g.comparison == Comparison::at_most ? "at most" : "at least");
    replace_all(s, "{cmp}", g.comparison == Comparison::at_most ? "<=" : ">=");
    replace_all(s, "{t}", format_number("%g", g.threshold));
    replace_all(s, "{on}", g.on);
    replace_all(s, "{scene}", in.scene);
    replace_all(s, "{lights}", std::to_string(in.lights));
    return s;
}

// The goal judged: its line, its verdict, its plain sentence; its lines of information into `info`.
GoalResult judge(const Goal& g, const GoalInput& in, std::vector<std::string>& info) {
    GoalResult r;
    r.goal = &g;
    r.lights = in.lights;
    r.figure = g.measure(g, in);
    const Figure& f = r.figure;
    r.verdict = !f.judged ? Verdict::not_judged : met(g, f) ? Verdict::met : Verdict::not_met;
    r.line = sentence(g.sentence, g, in, f.judged) + ": " + f.working;
    if (f.judged) r.line += std::string(" -> ") + (r.verdict == Verdict::met ? "met" : "NOT met") + f.after;
    r.plain = sentence(g.plain, g, in, f.judged);
    for (const std::string& i : f.info) info.push_back("  " + i);
    return r;
}

// Every goal judged, each followed in `lines` (when given) by its line and its information.
std::vector<GoalResult> judge_all(const std::vector<Row>& rows, const std::string& scene, int own_lights,
                                  const std::optional<InvocationProbe>& probe, std::optional<GoalGroup> only,
                                  std::vector<std::string>* lines) {
    const std::vector<Goal>& t = goal_table();
    std::vector<GoalResult> out;
    // Consecutive goals of one scope and group are judged together: per light count, every goal
    // of the run at the own count, then every one at kManyLights.
    for (size_t i = 0, j = 0; i < t.size(); i = j) {
        for (j = i; j < t.size() && t[j].scope == t[i].scope && t[j].group == t[i].group;) ++j;
        if (only && t[i].group != *only) continue;
        const std::vector<int> counts =
            t[i].scope == Scope::per_light_count ? std::vector<int>{own_lights, kManyLights} : std::vector<int>{0};
        for (int n : counts)
            for (size_t k = i; k < j; ++k) {
                std::vector<std::string> info;
                out.push_back(judge(t[k], GoalInput{rows, scene, n, probe}, info));
                if (!lines) continue;
                lines->push_back(out.back().line);
                lines->insert(lines->end(), info.begin(), info.end());
            }
    }
    return out;
}

}  // namespace

const std::vector<Goal>& goal_table() {
    static const std::vector<Goal> table = {
        {"invocations", GoalGroup::renderer, Scope::per_light_count,
         "light_invocations {cmp} {t} x ideal, {scene} with {lights} lights",
         "the light shader runs {cmp words} {t} times per pixel a light really reaches ({scene}, {lights} lights)",
         1.25, Comparison::at_most, "", invocations},
        {"floor", GoalGroup::renderer, Scope::per_light_count, "floor_ratio {cmp} {t}, {scene} with {lights} lights",
         "a frame takes {cmp words} {t} times the least its work could take ({scene}, {lights} lights)", 1.3,
         Comparison::at_most, "", against_floor},
        {"speed_256", GoalGroup::renderer, Scope::once,
         "deferred {cmp} {t}x faster than the faster forward multi-pass at {on} lights[, {scene}]",
         "deferred shading is {cmp words} {t} times as fast as forward multi-pass at {on} lights[ ({scene})]", 10,
         Comparison::at_least, "256", speed},
        {"stencil", GoalGroup::light_geometry, Scope::per_light_count,
         "stencil light_invocations {cmp} {t} x ideal, {scene} with {lights} lights",
         "with stencil light volumes, the light shader runs {cmp words} {t} times per pixel a light really "
         "reaches ({scene}, {lights} lights)",
         1.25, Comparison::at_most, "", stencil},
        {"tiles", GoalGroup::light_geometry, Scope::once, "tiles {cmp} {t}x faster than quad on {on}",
         "screen tiles are {cmp words} {t} times as fast as one quad per light on {on}", 3, Comparison::at_least,
         "1024-overlap", tiles},
        {"large", GoalGroup::light_geometry, Scope::once,
         "best deferred {cmp} {t}x faster than forward single-pass on {on}",
         "the fastest deferred configuration is {cmp words} {t} times as fast as forward single-pass on {on}", 1.5,
         Comparison::at_least, "32-large", large},
        {"geometry_lsb", GoalGroup::light_geometry, Scope::once, "every light geometry within {t} LSB of quad's image",
         "every way of drawing the lights gives quad's image to within {t} LSB", 1, Comparison::at_most, "",
         geometry_lsb},
    };
    return table;
}

const Goal& goal(const std::string& id) {
    for (const Goal& g : goal_table())
        if (id == g.id) return g;
    throw Error("bench: no goal named '" + id + "'");
}

std::string goal_bound(const Goal& g) {
    return std::string(g.comparison == Comparison::at_most ? "<= " : ">= ") + format_number("%g", g.threshold);
}

const Row* find_row(const std::vector<Row>& rows, const std::string& scene, int lights, Renderer renderer,
                    bool default_config) {
    for (const Row& r : rows) {
        if (r.scene != scene || r.lights != lights || r.renderer != renderer) continue;
        if (renderer == Renderer::deferred && default_config &&
            !(default_configuration(r) && r.light_geometry == LightGeometry::quad))
            continue;
        return &r;
    }
    return nullptr;
}

const Row* fastest_row(const std::vector<Row>& rows, const std::string& scene, int lights, Renderer renderer) {
    const Row* best = nullptr;
    for (const Row& r : rows)
        if (r.scene == scene && r.lights == lights && r.renderer == renderer && (!best || r.ms_median < best->ms_median))
            best = &r;
    return best;
}

const Row* find_geometry_row(const std::vector<Row>& rows, const std::string& scene, int lights,
                             LightGeometry geometry) {
    for (const Row& r : rows)
        if (r.scene == scene && r.lights == lights && default_configuration(r) && r.light_geometry == geometry)
            return &r;
    return nullptr;
}

std::vector<GoalResult> judge_goals(const std::vector<Row>& rows, const std::string& scene, int own_lights,
                                    const std::optional<InvocationProbe>& probe) {
    return judge_all(rows, scene, own_lights, probe, std::nullopt, nullptr);
}

std::vector<std::string> goals(const std::vector<Row>& rows, const std::string& scene, int own_lights,
                               const std::optional<InvocationProbe>& probe) {
    std::vector<std::string> lines;
    judge_all(rows, scene, own_lights, probe, std::nullopt, &lines);
    return lines;
}

std::vector<std::string> geometry_goals(const std::vector<Row>& rows, const std::string& scene, int own_lights,
                                        const std::optional<InvocationProbe>& probe) {
    std::vector<std::string> lines;
    judge_all(rows, scene, own_lights, probe, GoalGroup::light_geometry, &lines);
    return lines;
}

}  // namespace dsr::bench
