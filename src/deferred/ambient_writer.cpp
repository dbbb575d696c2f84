// Which pass writes the ambient term (ambient_writer.h).
#include "deferred/ambient_writer.h"

namespace dsr {

namespace {
// A light's pass or the geometry's first batch may take the ambient pass's place.
bool may_fold(const AmbientFacts& a) {
    return !a.ssao && !a.emission && a.fold_program && ((a.geometry_draws_own && a.has_lights) || a.full_screen_light);
}
bool handoff_may_write(const AmbientFacts& a) { return !a.ssao && !a.emission && a.handoff_program; }
}  // namespace

std::optional<AmbientWriter> ambient_before_plan(const AmbientFacts& a) {
    if (a.material_pass) return AmbientWriter::material_pass;
    // The screen geometry's first batch needs no plan to know it covers every pixel.
    if (may_fold(a) && a.geometry_draws_own && a.has_lights) return AmbientWriter::geometry_first_batch;
    if (may_fold(a) || handoff_may_write(a)) return std::nullopt;  // the plan decides
    // Nothing else can write it: first, unless the plan reads back, which would then wait for it.
    return a.plan_reads_back ? AmbientWriter::pass_after_plan : AmbientWriter::pass_before_plan;
}

AmbientWriter decide_ambient(const AmbientFacts& a, const PlanFacts& p) {
    if (const std::optional<AmbientWriter> w = ambient_before_plan(a)) return *w;
    if (may_fold(a) && a.full_screen_light && p.own_pass) return AmbientWriter::light_fold;
    if (handoff_may_write(a) && p.hands_off) return AmbientWriter::handoff;
    return AmbientWriter::pass_after_plan;
}

bool ambient_pass_possible(const AmbientFacts& a, bool hands_off_certain) {
    return !a.material_pass && !(handoff_may_write(a) && hands_off_certain);
}

const char* ambient_writer_name(AmbientWriter w) {
    switch (w) {
        case AmbientWriter::material_pass: return "material-pass";
        case AmbientWriter::pass_before_plan: return "pass-before-plan";
        case AmbientWriter::pass_after_plan: return "pass-after-plan";
        case AmbientWriter::light_fold: return "light-fold";
        case AmbientWriter::geometry_first_batch: return "geometry-first-batch";
        case AmbientWriter::handoff: return "handoff";
    }
    return "?";
}

}  // namespace dsr
