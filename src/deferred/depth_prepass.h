// Whether the geometry stage runs the depth pre-pass (§3.3.1, Listing 8), decided per frame from
// what earlier frames measured (SkipOptions::depth_prepass). Pure: no GL; the geometry stage feeds
// it two occlusion-query counts and asks it before each frame.
//
// The pre-pass pays a depth-only draw of every surface so that the material pass shades each
// pixel once. Without it the material pass writes depth itself (GL_LEQUAL) and shades every
// fragment that passes in draw order: `shaded` against the `covered` pixels the pre-pass would
// have left it. At low depth complexity (shaded / covered near 1) the pre-pass is pure cost.
//
// Counts: a frame with the pre-pass measures both (the pre-pass's samples passed are exactly the
// fragments a material pass without it would shade; the material pass behind it shades the
// covered pixels). A frame without it measures `shaded` only and sets it against the last
// `covered`; every `remeasure` frames without the pre-pass one frame runs it to measure again.
#pragma once
#include <optional>

namespace dsr {

class DepthPrepassChoice {
public:
    // Up to this many shaded fragments per covered pixel the material pass's extra shading costs
    // less than the pre-pass: the pre-pass pays from about 1 / (1 - pre-pass fragment / shaded
    // fragment) on, with those costs measured on llvmpipe (docs/guide.md, "The depth pre-pass").
    static constexpr double kThreshold = 1.25;
    static constexpr int kRemeasure = 32;

    explicit DepthPrepassChoice(double threshold = kThreshold, int remeasure = kRemeasure)
        : threshold_(threshold), remeasure_(remeasure) {}
    // Whether the next frame runs the pre-pass. The first frame does: nothing is measured yet, and
    // only a frame with the pre-pass measures the covered pixels.
    bool run_next() const;
    // A frame with the pre-pass: its samples passed (shaded) and the material pass's (covered).
    void measured_with_prepass(long long shaded, long long covered);
    // A frame without it: the material pass's samples passed.
    void measured_without(long long shaded);
    // shaded / covered of the last measurement (1 where nothing was covered); null before any.
    std::optional<double> complexity() const;

private:
    double threshold_;
    int remeasure_;
    bool measured_ = false;
    long long shaded_ = 0, covered_ = 0;
    int frames_without_ = 0;  // since the last frame with the pre-pass
};

}  // namespace dsr
