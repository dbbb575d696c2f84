// The frame against its floor (`dsr bench`): what the cheapest renderer that does the same work
// could take, measured in the same run, on the same context and size as the rows. Three parts:
//   (a) G-buffer fill floor: the scene's triangles drawn once, no depth pre-pass, with a trivial
//       shader (glsl120/floor_fill.*) writing constants into the same targets (same count, same
//       formats, same depth attachment) after one clear of colour and depth; depth test GL_LEQUAL
//       with depth writes on, back faces culled. Timed per frame (glFinish + wall clock) in the
//       rows' interleaved rounds; its median.
//   (b) per-fragment cost of a light pass: a full-screen quad through glsl120/floor_light.frag
//       (one read of each of the four G-buffer targets the light shader reads, one colour
//       written, additive blending into an RGBA8 target like P-buffer 0), drawn `passes` times
//       back to back and timed as one batch; median over batches of batch_ms / (passes x w x h).
//   (c) post floor: each post pass's texel reads over its buffer, each read costed at a quarter
//       of (b) (b's fragment makes four reads). The bench's rows run with post off, so (c) = 0.
//   (d) output floor: one clear of an RGBA8 target like P-buffer 0. (b) writes only the lit pixels,
//       but a frame writes every pixel of its output at least once (the clear's background, the
//       ambient term); without (d) the floor's image would be undefined wherever no light
//       reaches. Timed like (b), without a glFinish of its own: batches of n clears, each followed
//       by a one-pixel point (so that no GL merges one clear into the next), against batches of
//       the n points alone, about 30 ms a batch; (d) = the difference of the two medians / n.
//       Once per scene variant: the target is the same whatever the G-buffer layout.
// floor_ms = (a) + ideal_fragments x (b) + (c) + (d); floor_ratio = ms_median / floor_ms.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "deferred/options.h"
#include "gl/caps.h"
#include "scene/scene.h"

namespace dsr {
class GpuScene;
class PBuffer;
class Program;
}  // namespace dsr

namespace dsr::bench {

// The G-buffer a deferred row fills: its colour targets, their format and its depth attachment.
struct GbufferLayout {
    // One format per colour target (Paths::gbuffer_formats): 3, or 4 with the packed depth or
    // position target.
    std::vector<TargetFormat> formats = {TargetFormat::rgba8, TargetFormat::rgba8, TargetFormat::rgba8};
    bool depth_texture = true;  // a depth texture (the depth-texture path) or a renderbuffer (the others)
    bool operator<(const GbufferLayout& o) const {
        return std::tie(formats, depth_texture) < std::tie(o.formats, o.depth_texture);
    }
};

// The measured parts, and the arithmetic that makes a floor of them.
struct FloorParts {
    double fill_ms = 0;             // (a)
    double light_ns_per_fragment = 0;  // (b), nanoseconds
    double post_ms = 0;             // (c)
    double output_ms = 0;           // (d)
};

// (a) + ideal x (b) + (c) + (d), in ms. Null when there is no ideal count.
std::optional<double> floor_ms(const FloorParts& f, std::optional<long long> ideal_fragments);
// ms_median / floor_ms; null when the floor is null or not positive.
std::optional<double> floor_ratio(double ms_median, std::optional<double> floor);

// Texel reads of the post passes over their buffers at w x h: bloom's two blurs at 1/bloom_scale
// (bloom_taps reads a pixel each) and its add back (one read a pixel); anti-alias: 9 reads of the
// normal target and/or 9 of the depth for the factor, 9 of the colour. 0 with both off.
long long post_texel_reads(const PostOptions& post, int w, int h);
// (c): post_texel_reads x (b) / 4.
double post_floor_ms(const PostOptions& post, int w, int h, double light_ns_per_fragment);

// The GL part: (a) and (b) for one layout, on the current context, at w x h.
class FloorBench {
public:
    FloorBench(const Caps& caps, int w, int h, const GbufferLayout& layout, const std::string& shader_dir);
    ~FloorBench();
    void set_scene(const Scene& scene);
    // One (a) frame: clear, the triangles once, glFinish; returns its wall time in ms.
    double fill_frame(const Scene& scene);
    // (b): `batches` batches of full-screen passes, each long enough to time (about 30 ms; at
    // least 2 passes); the median ns per fragment. Reads what the last fill_frame wrote.
    double light_ns_per_fragment(int batches = 5);
    // (d): `batches` pairs of batches, with and without the clears; ms a clear (0 at least).
    double output_clear_ms(int batches = 5);
    const GbufferLayout& layout() const { return layout_; }

private:
    template <class Draw>
    double output_pass_ms(const char* what, Draw&& draw);
    double light_batch_ms(int passes);
    double output_batch_ms(int n, bool clear);
    int w_, h_;
    GbufferLayout layout_;
    std::unique_ptr<PBuffer> gbuf_, accum_;
    std::unique_ptr<Program> fill_, light_;
    std::unique_ptr<GpuScene> gpu_;
};

}  // namespace dsr::bench
