// The bench's goal table and its judge (bench_goals.h): one measure per goal, one printer for all.
#include "analysis/bench_goals.h"

#include <algorithm>
#include <optional>

#include "analysis/number_format.h"
#include "dsr_error.h"

namespace dsr::bench {

namespace {

const char* const kNotMeasured = "not measured in this run";

// Every light geometry but auto, in the order the goals' information lines list them.
constexpr LightGeometry kFixedGeometries[] = {LightGeometry::quad, LightGeometry::volume, LightGeometry::stencil,
                                              LightGeometry::tiles, LightGeometry::screen};

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

// A ratio goal round by round: frame i of each row of a variant ran in round i (Row::frames_ms),
// so num[i] / den[i] is the goal's figure with both frames under the same load from elsewhere on
// the machine. The figures' range and in how many rounds the goal held, after the verdict: a
// verdict on medians that holds in few rounds is the noise's. "" with fewer than two rounds.
std::string per_round(const Goal& g, const std::vector<double>& num, const std::vector<double>& den) {
    std::vector<double> r;
    int held = 0;
    for (size_t i = 0; i < std::min(num.size(), den.size()); ++i) {
        if (!(den[i] > 0)) continue;
        r.push_back(num[i] / den[i]);
        held += met(g, judged(num[i], den[i], "")) ? 1 : 0;
    }
    if (r.size() < 2) return "";
    std::sort(r.begin(), r.end());
    return "; round by round " + format_number("%.2f", r.front()) + "-" + format_number("%.2f", r.back()) +
           ", held in " + std::to_string(held) + " of " + std::to_string(r.size()) + " rounds";
}

// The rows that turned off the light sphere test alone: the depth-span test without it.
bool only_sphere_test_off(const Row& r) {
    SkipOptions only;
    only.light_sphere_test = false;
    return skips_off(r.skip) == skips_off(only);
}

// What auto's counted frame chose, " (auto's lights: ...)", or "" for a row of another geometry.
std::string auto_choice(const Row& a) {
    if (!a.frame || !a.frame->auto_geometry.on) return "";
    const auto& c = a.frame->auto_geometry.lights;
    return " (auto's lights: " + std::to_string(c[at(LightPath::quad)]) + " by quads, " +
           std::to_string(c[at(LightPath::volume)]) + " by volumes, " + std::to_string(c[at(LightPath::tiles)]) +
           " by the tiles)";
}

// The pixel-light pairs dsr's default (find_default_row: auto, else quad) paid for in its light
// passes (light_evaluations: each draw's invocations times the lights its fragments evaluate)
// against the ideal: a retired goal, its figure information. The tutorial's per-light quad follows:
// its rectangles run the shader at every pixel, inside the light's sphere or not.
Figure invocations(const Goal& g, const GoalInput& in) {
    const Row* d = find_default_row(in.rows, in.scene, in.lights);
    const bool ideal = d && d->ideal_fragments && *d->ideal_fragments > 0;
    const std::optional<long long> evals = d ? light_evaluations(*d) : std::nullopt;
    Figure f = !ideal  ? not_judged()
               : !evals ? not_judged(std::string(kNotMeasured) + " (the GL lacks ARB_pipeline_statistics_query)",
                                     kNotMeasured)
                        : judged(double(*evals), double(*d->ideal_fragments),
                                 over(*evals, *d->ideal_fragments) + " (" + light_geometry_name(d->light_geometry) +
                                     ")" + auto_choice(*d));
    // Every fixed geometry's ratio, fewest first: whether any way of drawing the lights meets the
    // goal on this GL (auto chooses each light's path by its time, not by its pairs).
    std::vector<std::pair<double, std::string>> each;
    for (LightGeometry g2 : kFixedGeometries)
        if (const Row* r = find_geometry_row(in.rows, in.scene, in.lights, g2))
            if (const std::optional<double> ratio = evaluations_ratio(*r))
                each.emplace_back(*ratio, light_geometry_name(g2));
    std::stable_sort(each.begin(), each.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    if (each.size() >= 2) {
        std::string list;
        for (const auto& [ratio, name] : each) list += (list.empty() ? "" : ", ") + name + " " + format_number("%.3f", ratio);
        f.info.push_back("(information: each fixed geometry's light_evaluations / ideal, fewest first: " + list + ")");
    }
    const Row* q = find_geometry_row(in.rows, in.scene, in.lights, LightGeometry::quad);
    if (!q || !q->ideal_fragments || *q->ideal_fragments <= 0) return f;
    if (q != d && light_invocations(*q))
        f.info.push_back("(information: the tutorial's quad per light, --light-geometry quad: light_invocations / "
                         "ideal = " + over(*light_invocations(*q), *q->ideal_fragments) + ")");
    if (const std::optional<long long> frags = light_fragments(*q)) {
        if (q->skip.light_sphere_test)
            f.info.push_back("(information, not a goal: quad's light_fragments / ideal = " +
                             over(*frags, *q->ideal_fragments) +
                             "; it holds by construction, since the light sphere test discards every fragment "
                             "whose surface point lies outside the sphere and the ideal counts the points inside)");
        else
            f.info.push_back("(information: quad's light_fragments / ideal = " + over(*frags, *q->ideal_fragments) +
                             ")");
    }
    for (const Row& r : in.rows)
        if (r.scene == in.scene && r.lights == in.lights && r.renderer == Renderer::deferred &&
            r.light_geometry == LightGeometry::quad && only_sphere_test_off(r) && light_fragments(r))
            f.info.push_back("(information, quad with the depth-span test only, --no-skip light-sphere-test: "
                             "light_fragments / ideal = " + over(*light_fragments(r), *q->ideal_fragments) +
                             (light_invocations(r) ? "; light_invocations / ideal = " +
                                                         over(*light_invocations(r), *q->ideal_fragments)
                                                   : std::string()) +
                             ")");
    return f;
}

// The frame against what the same work could cost at least (bench_floor.h), judged at
// kFloorWidth x kFloorHeight with kFloorLights lights and on kFloorDemo (LearnOpenGL's demo, whose
// frame the GPU goals time) only: the floor leaves out the frame's fixed
// costs (the ambient term, the copy to the main buffer, per-light set-up), which weigh more the
// smaller the frame, so a ratio at 512x512 says little about one at 1080p. Elsewhere the figure is
// printed as information. The frame is dsr's default's (auto, else quad): what a user gets.
Figure against_floor(const Goal& g, const GoalInput& in) {
    const Row* d = find_default_row(in.rows, in.scene, in.lights);
    if (!d || !d->floor_ratio || !d->floor_ms) return not_judged();
    // The output's clear (bench_floor.h (d)) named, so the ratio without it can be read off too.
    const std::string working = ms(d->ms_median) + " / " + ms(*d->floor_ms) + " = " + format_number("%.2f", *d->floor_ratio) +
                                (d->floor_output_ms ? " (the floor's output clear " + ms(*d->floor_output_ms) + ")" : "");
    const std::string where = std::to_string(kFloorWidth) + "x" + std::to_string(kFloorHeight) + " with " +
                              std::to_string(kFloorLights) + " lights or on " + kFloorDemo;
    if ((in.lights != kFloorLights && d->lights_label != kFloorDemo) || d->w != kFloorWidth || d->h != kFloorHeight)
        return not_judged(working + " (information: judged at " + where + " only; this row is " + std::to_string(d->w) +
                              "x" + std::to_string(d->h) + " with " + std::to_string(in.lights) + " lights)",
                          "judged at " + where + " only");
    return judged(*d->floor_ratio, 1, working);
}

// Deferred against the faster forward multi-pass row (float or RGBA8 accumulation).
Figure speed(const Goal& g, const GoalInput& in) {
    const int n = std::stoi(g.on);
    const Row* d = find_row(in.rows, in.scene, n, Renderer::deferred);
    const Row* m = fastest_row(in.rows, in.scene, n, Renderer::forward_multi);
    if (!d || !m) return not_judged();
    const double ratio = m->ms_median / d->ms_median;
    Figure f = judged(ratio, 1,
                      row_words(*m) + " " + ms(m->ms_median) + " / " + ms(d->ms_median) + " = " +
                          format_number("%.1f", ratio) + "x");
    f.after = per_round(g, m->frames_ms, d->frames_ms);
    return f;
}

// The CPU time of a frame (FrameStats ms.cpu: the submitting thread's) of dsr's default at the
// goal's light count, where the run has rows of it: its frames back to back (Row::cpu_alone_ms),
// else (rows made without them) those of the rounds.
Figure cpu(const Goal& g, const GoalInput& in) {
    const Row* d = find_default_row(in.rows, in.scene, std::stoi(g.on));
    if (!d) return not_judged();
    if (!d->cpu_alone_ms)
        return judged(d->cpu_ms, 1, ms(d->cpu_ms) + " CPU a frame (" + row_words(*d) + ", " + ms(d->ms_median) + " a frame)");
    return judged(*d->cpu_alone_ms, 1,
                  ms(*d->cpu_alone_ms) + " CPU a frame, frames back to back (" + ms(d->cpu_ms) +
                      " in the rounds among the other rows; " + row_words(*d) + ", " + ms(d->ms_median) + " a frame)");
}

// The stencil geometry's invocations against the ideal, where the GL's counter can tell.
Figure stencil(const Goal& g, const GoalInput& in) {
    const Row* s = find_geometry_row(in.rows, in.scene, in.lights, LightGeometry::stencil);
    const std::optional<long long> invocations = s ? light_invocations(*s) : std::nullopt;
    if (!s || !s->ideal_fragments || *s->ideal_fragments <= 0 || !invocations) return not_judged();
    const std::optional<long long> frags = light_fragments(*s);
    if (in.probe && in.probe->counts_rejected())
        // The counter cannot tell what the stencil let through from what it rejected.
        return not_judged("cannot be judged on this GL: its fragment-shader invocation counter counts fragments "
                          "the stencil test rejects (probe: " + std::to_string(in.probe->invocations) +
                          " invocations for " + std::to_string(in.probe->pixels) +
                          " pixels that all fail the stencil test); invocations " +
                          over(*invocations, *s->ideal_fragments) +
                          (frags ? "; what passed the stencil (occlusion query) " + over(*frags, *s->ideal_fragments) +
                                       " (information)"
                                 : std::string()),
                          "cannot be judged on this GL (see the report)");
    return judged(double(*invocations), double(*s->ideal_fragments), over(*invocations, *s->ideal_fragments));
}

// A row's frame with its light stage replaced by the ideal: one light pass's per-pixel floor over
// the frame (the floor's (b): the G-buffer reads every light pass pays at a pixel before its first
// light) and the ideal pixel-light pairs at the screen row's cost per evaluation, that floor taken
// out of it (its light stage less (b) per pixel of each of its passes, over lights x pixels). An
// estimate, not a bound: the light shader's own set-up at a pixel (position, normal, view vector)
// costs more than (b), and a loop over fewer lights a pixel pays it over fewer evaluations
// (docs/benchmarks.md, "How the floor is made").
struct IdealFrame {
    std::string per_eval;  // how the cost per evaluation was found, for the line
    double fixed_ms = 0, pass_floor_ms = 0, pairs_ms = 0;
    double light_stage() const { return pass_floor_ms + pairs_ms; }
    double frame() const { return fixed_ms + light_stage(); }
};
std::optional<IdealFrame> ideal_frame(const Row& s, int n, const Row& d) {
    if (!s.lights_ms || !d.lights_ms || !d.ideal_fragments || n <= 0) return std::nullopt;
    const double px = double(s.w) * s.h;
    const double floor_ns = s.floor_light_ns.value_or(0.0);
    IdealFrame f;
    f.pass_floor_ms = floor_ns * px * 1e-6;
    const int passes = std::max(1, light_passes(s).value_or(1));
    const double per_eval_ns = std::max(0.0, *s.lights_ms - passes * f.pass_floor_ms) * 1e6 / (double(n) * px);
    f.fixed_ms = d.ms_median - *d.lights_ms;
    f.pairs_ms = double(*d.ideal_fragments) * per_eval_ns * 1e-6;
    const std::string floor_text =
        s.floor_light_ns ? " less " + std::to_string(passes) + " x its per-pixel floor (" + format_number("%.2f", floor_ns) +
                               " ns a pixel: " + ms(passes * f.pass_floor_ms) + ")"
                         : " (no floor measured)";
    f.per_eval = "the screen row's light stage " + ms(*s.lights_ms) + floor_text + " over " + std::to_string(n) +
                 " x " + std::to_string(s.w * s.h) + " evaluations is " + format_number("%.2f", per_eval_ns) + " ns each";
    return f;
}

// "frame outside its light stage ... plus ... ideal pairs at that cost (...) is X ms": the sum
// ideal_frame makes, in words, for the row `who`.
std::string ideal_sum(const IdealFrame& f, const Row& d, const std::string& who) {
    return who + "'s frame outside its light stage " + ms(f.fixed_ms) + " plus one pass's floor (" + ms(f.pass_floor_ms) +
           ") plus " + std::to_string(*d.ideal_fragments) + " ideal pairs at that cost (" + ms(f.pairs_ms) + ") is " +
           ms(f.frame());
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
    Figure f = judged(tq->ms_median, tt->ms_median,
                      ms(tq->ms_median) + " / " + ms(tt->ms_median) + " = " +
                          format_number("%.2f", tq->ms_median / tt->ms_median) + "x");
    f.after = per_round(g, tq->frames_ms, tt->frames_ms);
    // How far the goal could go on this GL: quad over the tiles row's ideal frame, at the cost per
    // evaluation of the scene's screen row (every light at every pixel, the same arithmetic).
    const Row* s = find_geometry_row(in.rows, tt->scene, tt->lights, LightGeometry::screen);
    if (const std::optional<IdealFrame> e = s ? ideal_frame(*s, tt->lights, *tt) : std::nullopt)
        f.info.push_back("(information: " + e->per_eval + "; " + ideal_sum(*e, *tt, "the tiles row") + ", and quad " +
                         format_number("%.2f", tq->ms_median / e->frame()) +
                         "x slower than that; the tiles row's light stage is " + ms(*tt->lights_ms) + ", " +
                         format_number("%.2f", *tt->lights_ms / e->light_stage()) + "x that ideal's " +
                         ms(e->light_stage()) + ")");
    return f;
}

// The scene variant and light count the run measured for the --lights entry `label` (its rows
// carry the label). False when it has none.
bool variant_of(const std::vector<Row>& rows, const std::string& label, std::string& scene, int& lights) {
    for (const Row& r : rows)
        if (r.lights_label == label) {
            scene = r.scene, lights = r.lights;
            return true;
        }
    return false;
}

// The withdrawn goal "best deferred >= 1.5x faster than forward single-pass on 32-large", kept as
// information: the fastest deferred row (every skip, RGBA8 G-buffer; any depth path, scissor or
// geometry but screen) against the faster forward single-pass row; with the same rows on the scene
// without lights (count 0 of the same set), what 1.5x would leave the deferred row for its lights.
// Empty when the run has not the rows.
std::string forward_bound(const std::vector<Row>& rows, const std::string& label) {
    const double withdrawn = 1.5;
    const Row* best = nullptr;
    const Row* fwd = nullptr;
    for (const Row& r : rows)
        if (r.lights_label == label) {
            if (r.renderer == Renderer::deferred && !r.linear_law && skips_off(r.skip).empty() && !r.gbuffer_half &&
                r.accum_format == AccumFormat::rgba8 && r.light_geometry != LightGeometry::screen && (!best || r.ms_median < best->ms_median))
                best = &r;
            if (r.renderer == Renderer::forward_single && (!fwd || r.ms_median < fwd->ms_median)) fwd = &r;
        }
    if (!best || !fwd) return "";
    std::string s = "(information, withdrawn as a goal: best deferred against forward single-pass on " + label + ": " +
                    row_words(*fwd) + " " + ms(fwd->ms_median) + " / " + row_words(*best) + " " +
                    ms(best->ms_median) + " = " + format_number("%.2f", fwd->ms_median / best->ms_median) +
                    "x. Forward single-pass is the bound here on GL 2.x, not a rival to beat by " +
                    format_number("%g", withdrawn) +
                    "x: over 9 boxes it shades each pixel once, with every light in one shader, and the pixels lie "
                    "inside most of the lights, so no light geometry leaves out any of its work and deferred adds "
                    "the G-buffer";
    const size_t dash = label.find('-');
    const std::string unlit = "0" + (dash == std::string::npos ? std::string() : label.substr(dash));  // "0-large"
    const Row* fwd0 = nullptr;
    const Row* best0 = nullptr;
    for (const Row& r : rows)
        if (r.lights_label == unlit) {
            if (r.renderer == fwd->renderer && config_text(r) == config_text(*fwd)) fwd0 = &r;
            if (r.renderer == best->renderer && config_text(r) == config_text(*best)) best0 = &r;
        }
    if (fwd0 && best0 && best->ideal_fragments)
        s += "; without lights (" + unlit + ") " + format_number("%.2f", fwd0->ms_median) + " and " +
             ms(best0->ms_median) + ", so forward's light work takes " + ms(fwd->ms_median - fwd0->ms_median) +
             " and " + format_number("%g", withdrawn) + "x would leave the deferred row " +
             ms(fwd->ms_median / withdrawn - best0->ms_median) + " for " + std::to_string(*best->ideal_fragments) +
             " ideal pixel-light pairs";
    return s + ")";
}

// How far the demo goal could go on this GL: the default row's ideal frame (ideal_frame), and the
// screen row over it.
std::string demo_estimate(const std::vector<Row>& rows, const std::string& on) {
    std::string scene;
    int n = 0;
    if (!variant_of(rows, on, scene, n)) return "";
    const Row* s = find_geometry_row(rows, scene, n, LightGeometry::screen);
    const Row* d = find_default_row(rows, scene, n);
    if (!s || !d) return "";
    const std::optional<IdealFrame> f = ideal_frame(*s, n, *d);
    if (!f) return "";
    return "(information: " + f->per_eval + "; " + ideal_sum(*f, *d, "the default row") + ", " +
           format_number("%.2f", s->ms_median / f->frame()) + "x faster than screen; the default row's light stage is " +
           ms(*d->lights_ms) + ", " + format_number("%.2f", *d->lights_ms / f->light_stage()) + "x that ideal's " +
           ms(f->light_stage()) + ")";
}

// dsr's default (find_default_row: auto, else quad) against the screen geometry, LearnOpenGL's
// deferred demo's lighting pass, on the demo's scene (the goal's --lights entry, 32-large), with
// the size the rows ran at (the demo's is 800x600). The withdrawn forward goal follows as
// information.
Figure demo(const Goal& g, const GoalInput& in) {
    Figure f = not_judged();
    std::string scene;
    int n = 0;
    if (variant_of(in.rows, g.on, scene, n)) {
        const Row* s = find_geometry_row(in.rows, scene, n, LightGeometry::screen);
        const Row* d = find_default_row(in.rows, scene, n);
        if (s && d) {
            const bool automatic = d->light_geometry == LightGeometry::automatic;
            const bool demo_size = s->w == kDemoWidth && s->h == kDemoHeight;
            f = judged(s->ms_median, d->ms_median,
                       "screen " + ms(s->ms_median) + " / " + light_geometry_name(d->light_geometry) + " " +
                           ms(d->ms_median) + " = " + format_number("%.2f", s->ms_median / d->ms_median) +
                           "x (dsr's default geometry: " + (automatic ? "auto" : "quad, the run has no auto row") +
                           "; " + std::to_string(s->w) + "x" + std::to_string(s->h) +
                           (demo_size ? ", the demo's size" : ", not the demo's 800x600") + ")");
            f.after = per_round(g, s->frames_ms, d->frames_ms);
        }
    }
    const std::string estimate = demo_estimate(in.rows, g.on);
    if (!estimate.empty()) f.info.push_back(estimate);
    const std::string bound = forward_bound(in.rows, g.on);
    if (!bound.empty()) f.info.push_back(bound);
    return f;
}

// The attenuation law against Equation 2's linear law on the same pixel-light pairs (N-large's rows
// and their linear-law twins, timed in the same rounds): the light stage of dsr's default geometry
// under each law. Each light program is built in a form per law (docs/light_geometry.md), so the
// attenuation law should cost no more per pair than the linear one; the other geometries' ratios
// follow as information.
Figure law(const Goal& g, const GoalInput& in) {
    std::string scene;
    int n = 0;
    if (!variant_of(in.rows, g.on, scene, n)) return not_judged();
    const Row* a = find_default_row(in.rows, scene, n);
    const Row* l = a ? find_linear_law_row(in.rows, scene, n, a->light_geometry) : nullptr;
    if (!a || !l || !a->lights_ms || !l->lights_ms)
        return not_judged(std::string(kNotMeasured) + " (no linear-law row)", kNotMeasured);
    const auto ratio = [](double x, double y) { return ms(x) + " / " + ms(y) + " = " + format_number("%.2f", x / y); };
    const auto working = [&](const Row& x, const Row& y) { return ratio(*x.lights_ms, *y.lights_ms); };
    const std::string head = "light stage, attenuation law / linear law, " +
                             std::string(light_geometry_name(a->light_geometry)) + ": ";
    const std::string pairs = a->ideal_fragments ? " (" + std::to_string(*a->ideal_fragments) + " ideal pairs each)" : "";
    Figure f;
    if (a->goal_rounds_lights_ms && l->goal_rounds_lights_ms) {  // the two rows' own rounds (Row::goal_rounds_ms)
        const double x = *a->goal_rounds_lights_ms, y = *l->goal_rounds_lights_ms;
        f = judged(x, y, head + ratio(x, y) + pairs + ", in " + std::to_string(a->goal_rounds_lights_frames_ms.size()) +
                             " rounds of their own");
        f.after = per_round(g, a->goal_rounds_lights_frames_ms, l->goal_rounds_lights_frames_ms);
        f.info.push_back("(information: in the rounds of every row, " + working(*a, *l) +
                         per_round(g, a->lights_frames_ms, l->lights_frames_ms) + ")");
    } else {
        f = judged(*a->lights_ms, *l->lights_ms, head + working(*a, *l) + pairs);
        f.after = per_round(g, a->lights_frames_ms, l->lights_frames_ms);
    }
    std::string others;
    for (LightGeometry geo : kFixedGeometries) {
        if (geo == a->light_geometry) continue;
        const Row* x = find_geometry_row(in.rows, scene, n, geo);
        const Row* y = find_linear_law_row(in.rows, scene, n, geo);
        if (x && y && x->lights_ms && y->lights_ms)
            others += std::string(others.empty() ? "" : "; ") + light_geometry_name(geo) + " " + working(*x, *y);
    }
    if (!others.empty()) f.info.push_back("(information: the same for the other geometries: " + others + ")");
    return f;
}

// On each bench scene, the auto geometry against the fastest fixed one (quad, volume, stencil,
// tiles) on the default configuration: auto's choices should cost little over the best single
// geometry's.
Figure automatic(const Goal& g, const GoalInput& in) {
    const std::optional<LightSpec> spec = parse_light_spec(in.set);
    if (!spec) return not_judged();
    const std::string scene = bench_scene_name(in.scene, *spec);
    const int n = spec->count < 0 ? in.lights : spec->count;
    const Row* a = find_geometry_row(in.rows, scene, n, LightGeometry::automatic);
    if (!a) return not_judged(std::string(kNotMeasured) + " (no auto row)", kNotMeasured);
    // The fastest fixed row by a median it has: in the rounds of every row, or in their own rounds.
    const std::vector<const Row*> fixed = fixed_geometry_rows(in.rows, scene, n);
    const auto fastest = [&](std::optional<double> (*median_of)(const Row&)) {
        const Row* best = nullptr;
        for (const Row* r : fixed)
            if (median_of(*r) && (!best || *median_of(*r) < *median_of(*best))) best = r;
        return best;
    };
    const Row* best = fastest([](const Row& r) { return std::optional<double>(r.ms_median); });
    if (!best) return not_judged(std::string(kNotMeasured) + " (no row of a fixed geometry)", kNotMeasured);
    // What auto chose (its counted frame): a ratio between two rows that drew every light the same
    // way is the rounds' noise, not the cost model's choice.
    const std::string chose = auto_choice(*a);
    const auto working = [&](double num, const Row& den, double den_ms) {
        return "auto " + ms(num) + " / " + light_geometry_name(den.light_geometry) + " " + ms(den_ms) + " = " +
               format_number("%.2f", num / den_ms);
    };
    // The rows' own rounds where the run has them (Row::goal_rounds_ms): the fastest fixed row there.
    const Row* alone = a->goal_rounds_ms ? fastest([](const Row& r) { return r.goal_rounds_ms; }) : nullptr;
    if (!alone) {
        Figure f = judged(a->ms_median, best->ms_median, working(a->ms_median, *best, best->ms_median) + chose);
        f.after = per_round(g, a->frames_ms, best->frames_ms);
        return f;
    }
    Figure f = judged(*a->goal_rounds_ms, *alone->goal_rounds_ms,
                      working(*a->goal_rounds_ms, *alone, *alone->goal_rounds_ms) + chose + ", in " +
                          std::to_string(a->goal_rounds_frames_ms.size()) +
                          " rounds of auto and the fixed geometries within " + format_number("%.1f", kGoalRoundsWithin) +
                          "x of the fastest alone");
    f.after = per_round(g, a->goal_rounds_frames_ms, alone->goal_rounds_frames_ms);
    f.info.push_back("(information: in the rounds of every row, " + working(a->ms_median, *best, best->ms_median) +
                     per_round(g, a->frames_ms, best->frames_ms) + ")");
    return f;
}

// Every geometry's image against quad's, every scene variant of the run: the largest difference.
// The screen rows (LearnOpenGL's lighting pass, one rounding per pixel where quad rounds each
// light's pass) are not dsr's: their largest difference follows as information.
Figure geometry_lsb(const Goal& g, const GoalInput& in) {
    struct Worst {
        double lsb = -1;
        std::string row;
        int compared = 0;
    } dsr, screen;
    for (const Row& r : in.rows)
        if (r.renderer == Renderer::deferred && r.err_quad && r.light_geometry != LightGeometry::quad) {
            Worst& w = r.light_geometry == LightGeometry::screen ? screen : dsr;
            ++w.compared;
            if (r.err_quad->max_lsb() > w.lsb) {
                w.lsb = r.err_quad->max_lsb();
                w.row = row_words(r) + ", " + r.scene + " at " + std::to_string(r.lights) + " lights";
            }
        }
    auto largest = [](const Worst& w) {
        return "largest " + format_number("%.0f", w.lsb) + " LSB (" + w.row + ", " + std::to_string(w.compared) +
               " rows)";
    };
    Figure f = dsr.compared == 0 ? not_judged() : judged(dsr.lsb, 1, largest(dsr));
    if (screen.compared > 0)
        f.info.push_back("(information: the screen rows, LearnOpenGL's lighting pass, round each pixel's sum once "
                         "where quad rounds each light's pass: " + largest(screen) + ")");
    return f;
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
    replace_all(s, "{set}", in.set);
    return s;
}

// The goal judged: its line, its verdict, its plain sentence; its lines of information into `info`.
GoalResult judge(const Goal& g, const GoalInput& in, std::vector<std::string>& info) {
    GoalResult r;
    r.goal = &g;
    r.lights = in.lights;
    r.figure = g.measure(g, in);
    const Figure& f = r.figure;
    r.verdict = !f.judged || g.retired ? Verdict::not_judged : met(g, f) ? Verdict::met : Verdict::not_met;
    r.line = sentence(g.sentence, g, in, f.judged) + ": " + f.working;
    if (g.retired)  // the figure as information, with why it is no goal
        r.line = "  (information, retired as a goal " + std::string(g.retired) + ": " + r.line + f.after + ")";
    else if (f.judged)
        r.line += std::string(" -> ") + (r.verdict == Verdict::met ? "met" : "NOT met") + f.after;
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
        // Per light set: a pass per --lights entry of goal_light_sets(), at the scene's own count.
        const std::vector<std::string> sets =
            t[i].scope == Scope::per_light_set ? goal_light_sets() : std::vector<std::string>{""};
        const std::vector<int> counts = t[i].scope == Scope::per_light_count ? std::vector<int>{own_lights, kManyLights}
                                        : t[i].scope == Scope::per_light_set ? std::vector<int>{own_lights}
                                                                             : std::vector<int>{0};
        for (const std::string& set : sets)
            for (int n : counts)
                for (size_t k = i; k < j; ++k) {
                    std::vector<std::string> info;
                    const GoalResult r = judge(t[k], GoalInput{rows, scene, n, probe, set}, info);
                    if (!t[k].retired) out.push_back(r);
                    if (!lines) continue;
                    lines->push_back(r.line);
                    lines->insert(lines->end(), info.begin(), info.end());
                }
    }
    return out;
}

}  // namespace

const std::vector<std::string>& goal_light_sets() {
    static const std::vector<std::string> sets = {"own", "256", "1024", "1024-overlap", "32-large"};
    return sets;
}

const std::vector<Goal>& goal_table() {
    static const std::vector<Goal> table = {
        {"invocations", GoalGroup::renderer, Scope::per_light_count,
         "dsr's default light_evaluations / ideal, {scene} with {lights} lights",
         "dsr's default evaluates few more pixel-light pairs than its lights really reach ({scene}, {lights} lights)",
         1.25, Comparison::at_most, "", invocations,
         "(auto prices time, not pixel-light pairs: on llvmpipe fewer evaluations can cost more time)"},
        {"floor", GoalGroup::renderer, Scope::per_light_count,
         "floor_ratio {cmp} {t} at 1920x1080 with 1024 lights or on 32-large, {scene} with {lights} lights",
         "at 1920x1080 with 1024 lights or on 32-large, a frame takes {cmp words} {t} times the least its work could "
         "take ({scene}, {lights} lights)",
         1.5, Comparison::at_most, "", against_floor, nullptr},
        {"speed_256", GoalGroup::renderer, Scope::once,
         "deferred {cmp} {t}x faster than the faster forward multi-pass at {on} lights[, {scene}]",
         "deferred shading is {cmp words} {t} times as fast as forward multi-pass at {on} lights[ ({scene})]", 10,
         Comparison::at_least, "256", speed, nullptr},
        {"cpu", GoalGroup::renderer, Scope::once, "cpu ms {cmp} {t} a frame at {on} lights[, {scene}]",
         "the CPU spends {cmp words} {t} ms on a frame at {on} lights[ ({scene})]", 0.5, Comparison::at_most, "4096",
         cpu, nullptr},
        {"stencil", GoalGroup::light_geometry, Scope::per_light_count,
         "stencil light_invocations {cmp} {t} x ideal, {scene} with {lights} lights",
         "with stencil light volumes, the light shader runs {cmp words} {t} times per pixel a light really "
         "reaches ({scene}, {lights} lights)",
         1.25, Comparison::at_most, "", stencil, nullptr},
        {"tiles", GoalGroup::light_geometry, Scope::once, "tiles {cmp} {t}x faster than quad on {on}",
         "screen tiles are {cmp words} {t} times as fast as one quad per light on {on}", 3, Comparison::at_least,
         "1024-overlap", tiles, nullptr},
        {"demo", GoalGroup::light_geometry, Scope::once,
         "dsr's default {cmp} {t}x faster than screen (LearnOpenGL's lighting pass) on {on}",
         "dsr's default is {cmp words} {t} times as fast as LearnOpenGL's deferred demo, every light at every pixel, "
         "on {on}",
         3, Comparison::at_least, "32-large", demo, nullptr},
        {"geometry_lsb", GoalGroup::light_geometry, Scope::once, "every light geometry within {t} LSB of quad's image",
         "every way of drawing the lights gives quad's image to within {t} LSB", 1, Comparison::at_most, "",
         geometry_lsb, nullptr},
        {"law", GoalGroup::light_geometry, Scope::once,
         "attenuation law's light stage {cmp} {t} x the linear law's on the same pairs, {on}",
         "a light with LearnOpenGL's attenuation law costs {cmp words} {t} times one with the tutorial's linear law on "
         "the same pixels ({on})",
         1.05, Comparison::at_most, "32-large", law, nullptr},
        {"auto", GoalGroup::light_geometry, Scope::per_light_set,
         "auto {cmp} {t} x the fastest fixed geometry (quad, volume, stencil, tiles), {scene} at --lights {set}",
         "the auto light geometry takes {cmp words} {t} times the fastest fixed geometry's time ({scene}, --lights "
         "{set})",
         1.1, Comparison::at_most, "", automatic, nullptr},
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
        if (r.scene != scene || r.lights != lights || r.renderer != renderer || r.linear_law) continue;
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

namespace {

// The first row of `scene` with `lights` lights, this geometry and a configuration `config` accepts.
const Row* find_configured_row(const std::vector<Row>& rows, const std::string& scene, int lights,
                               LightGeometry geometry, bool (*config)(const Row&)) {
    for (const Row& r : rows)
        if (r.scene == scene && r.lights == lights && config(r) && r.light_geometry == geometry) return &r;
    return nullptr;
}

}  // namespace

const Row* find_geometry_row(const std::vector<Row>& rows, const std::string& scene, int lights,
                             LightGeometry geometry) {
    return find_configured_row(rows, scene, lights, geometry, default_configuration);
}

const Row* find_linear_law_row(const std::vector<Row>& rows, const std::string& scene, int lights,
                               LightGeometry geometry) {
    return find_configured_row(rows, scene, lights, geometry, default_configuration_twin);
}

std::vector<const Row*> fixed_geometry_rows(const std::vector<Row>& rows, const std::string& scene, int lights) {
    std::vector<const Row*> fixed;
    for (LightGeometry g : {LightGeometry::quad, LightGeometry::volume, LightGeometry::stencil, LightGeometry::tiles})
        if (const Row* r = find_geometry_row(rows, scene, lights, g)) fixed.push_back(r);
    return fixed;
}

const Row* find_default_row(const std::vector<Row>& rows, const std::string& scene, int lights) {
    const Row* a = find_geometry_row(rows, scene, lights, LightGeometry::automatic);
    return a ? a : find_geometry_row(rows, scene, lights, LightGeometry::quad);
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
