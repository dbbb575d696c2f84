// Final stage (§3.6, Appendix A step 4): P-buffer 0 drawn into the main frame buffer by fixed
// function, scaled with bilinear filtering when the output size differs from the buffers'. The
// debug views (--view) draw their buffers the same way. With an exposure, a tone-mapping operator
// or sRGB output (docs/hdr.md) the pass is the shader table's `tonemap` program instead; for
// --exposure auto it first reduces P-buffer 0's log luminance into a small float target.
#pragma once
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "deferred/render_targets.h"
#include "deferred/shader_table.h"
#include "gl/gl.h"
#include "gl/program.h"
#include "scene/image.h"

namespace dsr {

// The exposure scale --exposure auto applies: key / exp2(mean of log2(delta + L)) (Reinhard et
// al. 2002, Eqs. 1-2, key a = 0.18), from the reduced copy's means; 1 for an empty one. Pure.
float auto_exposure_scale(const std::vector<float>& block_log2_means, float key = 0.18f);

// `img` resampled to w x h as the final pass scales P-buffer 0 (bilinear, each output pixel's
// centre mapped onto the source's texel centres, clamped to its edge); img itself at its own size.
Image resample_bilinear(const Image& img, int w, int h);

class FinalStage {
public:
    // fbo: the P-buffers are framebuffer objects (the main one is bound back first).
    explicit FinalStage(bool fbo);
    ~FinalStage();
    // Takes the tonemap and log_luminance programs where the configuration uses them.
    void set_up(const ShaderConfig& c, ProgramSet& programs);
    void draw(const RenderTargets& targets, int out_w, int out_h);
    // Any texture, its content `extent` in texture coordinates, into the main frame buffer.
    void draw_texture(GLuint texture, int out_w, int out_h, glm::vec2 extent = {1, 1}) const;
    // The scale the last draw multiplied P-buffer 0 by (2^E, or auto's); 1 on the fixed-function path.
    float exposure_scale() const { return scale_; }
    // What the last draw wrote without its 8-bit main frame buffer: P-buffer 0 read back as float,
    // times exposure_scale() (negative values taken as 0, as the tonemap program takes them),
    // not clamped above; at out_w x out_h through resample_bilinear. For float image files
    // (docs/hdr.md): meaningful with the operator `none` and linear output.
    Image read_linear(const RenderTargets& targets, int out_w, int out_h) const;
    // P-buffer 0 reduced to a small grid (at most 64 blocks a side), each block's mean log2(1e-4 + L)
    // and its largest L, as (mean, max) pairs. Empty where the configuration has no log_luminance
    // program (--exposure auto or float accumulation, with float targets).
    std::vector<glm::vec2> reduce_luminance(const RenderTargets& targets);

private:
    bool fbo_;
    HdrOptions hdr_;
    Program tonemap_, log_luminance_;
    std::unique_ptr<PBuffer> reduced_;
    float scale_ = 1;
};

}  // namespace dsr
