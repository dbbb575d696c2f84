// Post-processing stage (§3.5, Figure 7, Appendix A step 3): bloom, then anti-alias, each only
// when enabled, on the four ping-pong P-buffers. With both off this costs nothing.
#pragma once
#include <glm/glm.hpp>

#include "deferred/frame.h"
#include "deferred/render_targets.h"
#include "deferred/shader_table.h"
#include "gl/program.h"

namespace dsr {

class PostStage {
public:
    PostStage(const ShaderConfig& c, ProgramSet& programs);
    bool bloom() const { return p_.bloom; }
    bool anti_alias() const { return p_.aa; }
    // Listing 22 from P-buffer `src` into `dst` (PRole) along `dir` (1,0) or (0,1); `select`
    // applies the bright-pass weighting of the first bloom pass. Needs bloom on.
    void blur(RenderTargets& targets, int src, int dst, glm::vec2 dir, bool select);
    // §3.5.2: horizontal blur 0 -> 2, vertical 2 -> 3, then P-buffer 3 added to 0.
    void draw_bloom(RenderTargets& targets);
    // §3.5.1: anti-alias P-buffer 0 into P-buffer 1, then swap so 0 holds the result;
    // factor_only writes the blur factor instead (Figure 8) and does not swap.
    void draw_anti_alias(const FrameDef& f, RenderTargets& targets, bool factor_only = false);

private:
    PostOptions p_;
    int depth_target_;
    Program blur_[2];  // [select], with bloom on
    Program aa_[2];    // [factor only]
};

}  // namespace dsr
