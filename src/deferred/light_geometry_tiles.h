// The tiles geometry's parts (light_geometry_tiles.cpp), for the auto geometry, which measures
// the depth spans first, decides from them which lights the tiles take, and has only those drawn.
#pragma once
#include <memory>
#include <vector>

#include "deferred/light_geometry.h"
#include "deferred/tile_plan.h"

namespace dsr {

class TilesPass : public LightGeometryPass {
public:
    // Whether the tiles cull by depth (the spans' programs were built: float targets behind
    // framebuffer objects, --tile-depth on).
    virtual bool depth_culling() const = 0;
    virtual int tile_size() const = 0;
    virtual int lights_per_pass() const = 0;
    // The depth spans of every tile (empty without depth culling), with P-buffer 0 bound for
    // rendering before and after; timed into stats.tiles.depth_ms.
    virtual std::vector<DepthSpan> depth_spans(const FrameDef& f, RenderTargets& targets, FrameStats& stats) = 0;
    // The tiles' boxes and f's lights' bounds into `depth`; null (and nothing written) without spans.
    virtual const TileDepth* tile_boxes(const FrameDef& f, const std::vector<DepthSpan>& spans, TileDepth& depth) const = 0;
    // f's lights through the tiles, culled by `cull` (its lights f's, in order; null: no culling).
    // kept: each light's tiles as tiles_kept gave them for f's rectangles and `cull` (the list
    // plan uses them instead of culling again); null: culled here.
    virtual void draw_lights(const FrameDef& f, const TileDepth* cull, LightQueries& q, FrameStats& stats,
                             const std::vector<std::vector<int>>* kept = nullptr) = 0;
};

std::unique_ptr<TilesPass> make_tiles_pass(const ShaderConfig& config, ProgramSet& programs, int width, int height);

}  // namespace dsr
