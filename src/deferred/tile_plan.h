// The tiles light geometry's plan (issue 12; §3.4.3's "multiple lights per pass"), pure math with
// no GL: which lights shade which screen tile in which draw.
//  1. Lights are ordered along a Morton curve of their scissor rectangle's centre tile, so that
//     lights near each other on screen share a batch, and cut into batches of `batch_size`: a
//     batch is what the light shader holds in its uniform arrays at once.
//  2. Within a batch each tile lists the batch's lights whose rectangle overlaps it; layer l of the
//     batch takes entries [l*N, (l+1)*N) of every tile's list (N = lights_per_pass).
//  3. One draw per (batch, layer): a quad for every tile with lights in that layer, each quad's
//     vertices carrying its lights' indices into the batch. So a frame is a handful of draws, not
//     one per tile (the earlier plan: 2040 draws at 1920x1080, 13 ms of CPU submission on the H200).
#pragma once
#include <vector>

#include "deferred/scissor.h"

namespace dsr {

struct TileQuad {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // window pixels, x1/y1 exclusive
    std::vector<int> slots;              // indices into the batch's lights, at most lights_per_pass
};

struct TileDraw {
    int batch = 0;
    std::vector<TileQuad> quads;
};

struct TilePlan {
    std::vector<std::vector<int>> batches;  // light indices (into the rects given), batch by batch
    std::vector<TileDraw> draws;
    long long tile_light_pairs = 0;         // (tile, light) pairs shaded: what the rectangles allow
};

// How the tiles geometry groups its work (`--tile-plan`, TileGrouping in options.h):
//  lists   each tile shades exactly the lights whose rectangle overlaps it: batches in uniform
//          arrays, per-quad light slots, one draw per batch and layer (above); the shader indexes
//          the arrays with the slot it reads, a dynamic index.
//  groups  lights in Morton order cut into groups of lights_per_pass; one draw per group over every
//          tile any of its lights overlaps, each tile shading the whole group: the shader's loop
//          indexes the arrays with its counter, so the light data is uniform across the draw.
// rects: each light's scissor rectangle (empty ones are left out); the screen width x height cut
// into tile_size tiles. batch_size >= 1, lights_per_pass >= 1.
TilePlan plan_tiles(const std::vector<ScissorRect>& rects, int width, int height, int tile_size,
                    int lights_per_pass, int batch_size);

// vec4s of packed light slots a tile vertex carries (two slots per float): texture coordinates 2..
inline int tile_id_vecs(int lights_per_pass) { return (lights_per_pass + 7) / 8; }

// The groups plan: batches are the groups (at most lights_per_pass each), one draw per group whose
// quads cover every tile one of its lights overlaps, each quad's slots the whole group.
TilePlan plan_tile_groups(const std::vector<ScissorRect>& rects, int width, int height, int tile_size,
                          int lights_per_pass);

// Morton (Z-order) code of tile (x, y), x and y < 2^16: interleaved bits.
unsigned morton2(unsigned x, unsigned y);

}  // namespace dsr
