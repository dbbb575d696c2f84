// decide_ambient and ambient_before_plan (deferred/ambient_writer.h): which pass writes the
// ambient term, over every combination of the facts (2^9 before the plan x 2^2 after it), each
// answer checked against the rules written out here on their own.
#include <gtest/gtest.h>

#include <string>

#include "deferred/ambient_writer.h"

namespace dsr {
namespace {

constexpr int kBefore = 9, kAfter = 2;

AmbientFacts facts_for(int bits) {
    AmbientFacts a;
    a.material_pass = bits & 1;
    a.ssao = bits & 2;
    a.fold_program = bits & 4;
    a.geometry_draws_own = bits & 8;
    a.has_lights = bits & 16;
    a.full_screen_light = bits & 32;
    a.handoff_program = bits & 64;
    a.plan_reads_back = bits & 128;
    a.emission = bits & 256;
    return a;
}

PlanFacts plan_for(int bits) {
    PlanFacts p;
    p.own_pass = bits & 1;
    p.hands_off = bits & 2;
    return p;
}

std::string trace(const AmbientFacts& a, const PlanFacts& p) {
    return "material " + std::to_string(a.material_pass) + " ssao " + std::to_string(a.ssao) + " fold_program " +
           std::to_string(a.fold_program) + " draws_own " + std::to_string(a.geometry_draws_own) + " lights " +
           std::to_string(a.has_lights) + " full_screen " + std::to_string(a.full_screen_light) + " handoff_program " +
           std::to_string(a.handoff_program) + " reads_back " + std::to_string(a.plan_reads_back) + " emission " +
           std::to_string(a.emission) + " own_pass " +
           std::to_string(p.own_pass) + " hands_off " + std::to_string(p.hands_off);
}

// The rules, each on its own, in order of precedence:
//  1. the material pass wrote it: nothing else does;
//  2. SSAO scales Listing 15's pass alone, and only that pass (with the emission pass after it)
//     adds emission and occlusion to a frame with them: that pass, first unless the plan reads back;
//  3. the screen geometry (with lights and the fold form built) writes it in its first batch;
//  4. a full-screen light whose pass is its own (fold form built) writes it in that pass;
//  5. a frame that hands its depth off, with the hand-off's ambient form, writes it there;
//  6. else Listing 15's pass: before the plan where nothing of 3-5 could have taken it (no fold
//     form, or neither a screen geometry with lights nor a full-screen light; and no hand-off
//     form) and the plan does not read back; after it otherwise.
AmbientWriter expected(const AmbientFacts& a, const PlanFacts& p) {
    if (a.material_pass) return AmbientWriter::material_pass;
    const bool fold_form = !a.ssao && !a.emission && a.fold_program;
    if (fold_form && a.geometry_draws_own && a.has_lights) return AmbientWriter::geometry_first_batch;
    if (fold_form && a.full_screen_light && p.own_pass) return AmbientWriter::light_fold;
    const bool handoff_form = !a.ssao && !a.emission && a.handoff_program;
    if (handoff_form && p.hands_off) return AmbientWriter::handoff;
    const bool could_be_taken = (fold_form && ((a.geometry_draws_own && a.has_lights) || a.full_screen_light)) ||
                                handoff_form;
    return !could_be_taken && !a.plan_reads_back ? AmbientWriter::pass_before_plan : AmbientWriter::pass_after_plan;
}

TEST(AmbientWriter, EveryCombinationFollowsTheRules) {
    int seen[6] = {0, 0, 0, 0, 0, 0};
    for (int b = 0; b < (1 << kBefore); ++b)
        for (int q = 0; q < (1 << kAfter); ++q) {
            const AmbientFacts a = facts_for(b);
            const PlanFacts p = plan_for(q);
            SCOPED_TRACE(trace(a, p));
            const AmbientWriter w = decide_ambient(a, p);
            EXPECT_EQ(ambient_writer_name(w), std::string(ambient_writer_name(expected(a, p))));
            ++seen[int(w)];
        }
    for (int w = 0; w < 6; ++w) EXPECT_GT(seen[w], 0) << ambient_writer_name(AmbientWriter(w));
}

// Emission and occlusion reach P-buffer 0 only through the material pass's ambient target or the
// emission pass after Listing 15's pass: in a frame with them no other writer is ever chosen, and
// without them every writer some combination chooses is still chosen.
TEST(AmbientWriter, EmissionKeepsTheWritersThatCarryIt) {
    bool seen_without[6] = {false, false, false, false, false, false};
    for (int b = 0; b < (1 << kBefore); ++b)
        for (int q = 0; q < (1 << kAfter); ++q) {
            const AmbientFacts a = facts_for(b);
            SCOPED_TRACE(trace(a, plan_for(q)));
            const AmbientWriter w = decide_ambient(a, plan_for(q));
            if (!a.emission) seen_without[int(w)] = true;
            if (a.emission) {
                EXPECT_TRUE(w == AmbientWriter::material_pass || w == AmbientWriter::pass_before_plan ||
                            w == AmbientWriter::pass_after_plan);
            }
        }
    for (int w = 0; w < 6; ++w) EXPECT_TRUE(seen_without[w]) << ambient_writer_name(AmbientWriter(w));
}

// The step before the plan answers only what no fact after it can change, and answers the pass
// before the plan, the one GL drawing that must happen before it, exactly where decide_ambient does.
TEST(AmbientWriter, TheStepBeforeThePlanAgreesWithEveryPlan) {
    for (int b = 0; b < (1 << kBefore); ++b) {
        const AmbientFacts a = facts_for(b);
        const std::optional<AmbientWriter> early = ambient_before_plan(a);
        bool all_same = true;
        const AmbientWriter first = decide_ambient(a, plan_for(0));
        for (int q = 0; q < (1 << kAfter); ++q) {
            SCOPED_TRACE(trace(a, plan_for(q)));
            const AmbientWriter w = decide_ambient(a, plan_for(q));
            all_same = all_same && w == first;
            if (early) {
                EXPECT_EQ(int(*early), int(w));
            }
            if (w == AmbientWriter::pass_before_plan) {
                EXPECT_TRUE(early.has_value());
            }
        }
        // Undecided only where the plan's facts do change the answer.
        if (!early) {
            EXPECT_FALSE(all_same) << trace(a, plan_for(0));
        }
    }
}

TEST(AmbientWriter, DepthIsHandedOffOnlyWhereP0HasADepthBufferAndAPassTestsIt) {
    for (int b = 0; b < 16; ++b) {
        const bool accum = b & 1, lights = b & 2, forward = b & 4, bounds = b & 8;
        EXPECT_EQ(hands_off_depth(accum, lights, forward, bounds), accum && (lights || forward || bounds)) << b;
    }
}

}  // namespace
}  // namespace dsr
