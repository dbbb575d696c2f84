// The tiles geometry's depth culling (tile_plan.h TileDepth): a pass of one fragment per tile column
// and window row (glsl120/tile_depth.frag) into a float target, a second that takes each tile's rows
// together (tile_depth_reduce.frag), and a read-back of one texel per tile give each tile's span of
// surface eye z; the plan then leaves out a tile's lights whose sphere lies wholly in front of or
// behind its surfaces. The read-back waits for the geometry pass, which the light passes wait for
// anyway; on a GPU it is a pipeline drain, measured with the rest of the light stage (ms.lights).
// On a CPU rasteriser with the depth texture, the G-buffer's depth and normal targets are read back
// instead and each tile's span taken on the CPU (tile_spans.h): there the read-backs and the
// CPU's loop cost less than the passes (docs/tiles.md, "Depth culling of the tiles").
#pragma once
#include <memory>
#include <vector>

#include "deferred/frame.h"
#include "deferred/shader_table.h"
#include "deferred/tile_plan.h"
#include "deferred/tile_timeline.h"
#include "gl/pbuffer.h"
#include "gl/program.h"

namespace dsr {

class TileDepthPass {
public:
    // Needs the table's "tile_depth" and "tile_depth_reduce" (a float target behind a framebuffer
    // object), except where the spans are read back (tile_spans_by_readback); the buffers are made
    // here and at resize, never inside a frame: creating their textures would disturb the
    // G-buffer's texture bindings.
    TileDepthPass(const ShaderConfig& c, ProgramSet& programs, int width, int height);
    ~TileDepthPass();
    TileDepthPass(const TileDepthPass&) = delete;
    TileDepthPass& operator=(const TileDepthPass&) = delete;
    void resize(int width, int height);
    // Each tile's span, row by row: its two passes into its own buffers and the read-back, which
    // read the G-buffer's normal and depth targets on units 0 and 3 (P-buffer 0 must not be bound);
    // or, where readback_, the two targets read back and the spans made on the CPU.
    // timeline: its spans_end stamped before the read-back (tile_timeline.h), where given.
    // stats: the wait for the GPU to reach the read-back, timed apart from it (wait_ms,
    // wait_cpu_ms), where given.
    std::vector<DepthSpan> spans(const FrameDef& f, const PBuffer& gbuffer, TileTimeline* timeline = nullptr,
                                 TileStats* stats = nullptr);

private:
    std::vector<DepthSpan> spans_by_readback(const FrameDef& f, const PBuffer& gbuffer, TileStats* stats);
    std::vector<float> depth_;          // the read-back's storage, kept between frames
    std::vector<unsigned char> normal_;
    Program rows_prog_, reduce_prog_;  // the passes' (none where readback_)
    int tile_size_;
    bool pow2_;
    bool readback_;  // the spans from the G-buffer read back, not from the passes
    // An occlusion query around the reduce pass, whose result's arrival tells that the GPU has
    // drawn the spans (0: none, glFinish waits instead): polled with sleeps between, so that the
    // wait for the GPU costs the CPU no spin (docs/tiles.md, "Depth culling of the tiles").
    GLuint drawn_query_ = 0;
    std::unique_ptr<PBuffer> rows_;  // RGBA32F: a texel per tile column and window row
    std::unique_ptr<PBuffer> tiles_;  // RGBA32F: a texel per tile, read back
};

}  // namespace dsr
