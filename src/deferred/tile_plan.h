// The tiles light geometry's plan (§3.4.3's "multiple lights per pass"; docs/tiles.md), pure math with
// no GL: which lights shade which screen tile in which draw.
//  1. Lights are ordered along a Morton curve of their scissor rectangle's centre tile, so that
//     lights near each other on screen share a batch, and cut into batches of `batch_size`: a
//     batch is what the light shader holds in its uniform arrays at once.
//  2. Within a batch each tile lists the batch's lights whose rectangle overlaps it; layer l of the
//     batch takes entries [l*N, (l+1)*N) of every tile's list (N = lights_per_pass).
//  3. One draw per (batch, layer): a quad for every tile with lights in that layer (neighbouring
//     tiles with the same lights merged: runs along a row, then equal runs down), each quad's
//     vertices carrying its lights' indices into the batch. So a frame is a handful of draws, not
//     one per tile: a GPU's CPU submits each draw, so their count is the plan's cost (docs/tiles.md).
#pragma once
#include <array>
#include <initializer_list>
#include <limits>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "deferred/scissor.h"

namespace dsr {

// Up to 32 light slots held inline: a plan at 1920x1080 has thousands of quads, and a heap
// vector each was a third of the plan's time.
class SlotList {
public:
    static constexpr int kCapacity = 32;  // tile_lights' upper bound (options.h)
    SlotList() = default;
    SlotList(std::initializer_list<int> l) { assign(l.begin(), l.end()); }
    template <class It>
    void assign(It first, It last) {
        n_ = 0;
        for (; first != last; ++first) push_back(*first);
    }
    void push_back(int s) { v_.at(size_t(n_++)) = s; }  // at(): more than kCapacity is a bug
    size_t size() const { return size_t(n_); }
    bool empty() const { return n_ == 0; }
    int operator[](size_t i) const { return v_[i]; }
    const int* begin() const { return v_.data(); }
    const int* end() const { return v_.data() + n_; }

private:
    int n_ = 0;
    std::array<int, kCapacity> v_{};
};

struct TileQuad {
    // Window pixels, x1/y1 exclusive: whole tiles (the last row and column may end at the edge).
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    SlotList slots;  // indices into the batch's lights, at most lights_per_pass
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

// An eye-space depth span [lo, hi] (eye z < 0 ahead of the camera): the surfaces of a tile that the
// light shader can light (tile_depth.frag). lo > hi: nothing (a tile of background only).
struct DepthSpan {
    float lo = -std::numeric_limits<float>::infinity();
    float hi = std::numeric_limits<float>::infinity();
};

// A light for depth culling: its sphere in eye space (a spot's cone lies in the sphere about its
// apex); radius < 0: unbounded (a directional light).
struct LightBound {
    glm::vec3 centre{0};
    float radius = -1;
};

// The eye-space box around every surface point of a tile: empty where the tile has no surface the
// light shader can light.
struct TileBox {
    glm::vec3 lo{0}, hi{0};
    bool empty = true;
};

// The box of window pixels [x0, x1) x [y0, y1) whose surfaces' eye z lie in `span`: a surface point
// is its pixel's view ray times -z, the ray through window point (x, y) being
// (x * ray_map.x + ray_map.z, y * ray_map.y + ray_map.w, -1) (affine, as light.frag's ray_map).
// xy_slack: a stored position's x and y may lie this far (relative) off its ray (--depth
// position16 rounds them to half floats); the box grows by it.
TileBox tile_box(const DepthSpan& span, float x0, float y0, float x1, float y1, glm::vec4 ray_map,
                 float xy_slack = 0);

// Whether the light's sphere reaches into the box, widened by 1e-5 of the magnitudes involved so
// that float rounding here or in the shader never culls a pair the shader would light.
bool sphere_meets_box(const LightBound& light, const TileBox& box);
// The same test as the culling makes it for four boxes at once (a lane each): lane `lane`'s answer.
bool meets_four_lanes(const LightBound& light, const std::array<TileBox, 4>& boxes, int lane);

// Depth culling for the plans (optional): a light shades a tile only where its sphere reaches the
// box around the tile's surfaces. Exact, not an approximation: outside its sphere every light type
// but the directional adds exactly 0 (lighting.glsl). Lights that reach no tile are left out of the
// batches.
struct TileDepth {
    std::vector<LightBound> lights;  // one per rect
    std::vector<TileBox> tiles;      // one per tile, row by row (tiles_x * tiles_y)
};

// How the tiles geometry groups its work (`--tile-plan`, TileGrouping in options.h):
//  lists   each tile shades exactly the lights whose rectangle overlaps it: batches in uniform
//          arrays, per-quad light slots, one draw per batch and layer (above); the shader indexes
//          the arrays with the slot it reads, a dynamic index.
//  groups  lights in Morton order cut into groups of lights_per_pass; one draw per group over every
//          tile any of its lights overlaps, each tile shading the whole group: the shader's loop
//          indexes the arrays with its counter, so the light data is uniform across the draw.
// rects: each light's scissor rectangle (empty ones are left out); the screen width x height cut
// into tile_size tiles. batch_size >= 1, lights_per_pass >= 1. depth: null for no depth culling.
// shadowed, when given (one flag per rect): no batch holds more than max_shadowed of the flagged
// lights (the shader's shadow map units, shadow.glsl SHADOW_SLOTS): a batch is cut where one more
// would enter it, else where it is full (max_shadowed >= 1).
TilePlan plan_tiles(const std::vector<ScissorRect>& rects, int width, int height, int tile_size,
                    int lights_per_pass, int batch_size, const TileDepth* depth = nullptr,
                    const std::vector<bool>* shadowed = nullptr, int max_shadowed = 0);

// plan_tiles a batch at a time, so that a renderer can draw a batch while it plans the next (on a
// GPU the plan is CPU time the GPU would otherwise wait through; docs/gpu_frame.md has the
// figures). The same batches and draws as plan_tiles. depth, when given, must outlive the planner. kept, when given, is each rectangle's tiles as tiles_kept (below) gave
// them for the same rects, size and depth: the planner takes them instead of culling again (auto
// has culled every light once to price it: it never culls a light twice).
class TilePlanner {
public:
    TilePlanner(const std::vector<ScissorRect>& rects, int width, int height, int tile_size, int lights_per_pass,
                int batch_size, const TileDepth* depth = nullptr, const std::vector<std::vector<int>>* kept = nullptr,
                const std::vector<bool>* shadowed = nullptr, int max_shadowed = 0);
    ~TilePlanner();
    const std::vector<std::vector<int>>& batches() const;
    // Appends batch b's draws (one per layer) to out; returns the (tile, light) pairs they shade.
    long long plan_batch(int b, std::vector<TileDraw>& out);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// For each rectangle's light, the tiles (row-major indices, ascending) of its rectangle, clipped to
// the screen, that the plans give it: all of them without depth; with it, those whose box its
// sphere meets (sphere_meets_box, tested a block of tiles first, as the plans do).
std::vector<std::vector<int>> tiles_kept(const std::vector<ScissorRect>& rects, int width, int height, int tile_size,
                                         const TileDepth* depth);

// vec4s of packed light slots a tile vertex carries (two slots per float): texture coordinates 2..
inline int tile_id_vecs(int lights_per_pass) { return (lights_per_pass + 7) / 8; }

// The groups plan: batches are the groups (at most lights_per_pass each), one draw per group whose
// quads cover every tile one of its lights overlaps, each quad's slots the whole group.
// shadowed, max_shadowed: as plan_tiles', for the groups.
TilePlan plan_tile_groups(const std::vector<ScissorRect>& rects, int width, int height, int tile_size,
                          int lights_per_pass, const TileDepth* depth = nullptr,
                          const std::vector<bool>* shadowed = nullptr, int max_shadowed = 0);

// Light indices `order` cut into batches of at most batch_size, in order, none holding more than
// max_shadowed of the lights flagged in `shadowed` (indexed by light; null: no such limit): a new
// batch starts where the last is full or where one more flagged light would exceed the limit.
std::vector<std::vector<int>> cut_batches(const std::vector<int>& order, int batch_size,
                                          const std::vector<bool>* shadowed = nullptr, int max_shadowed = 0);

// Morton (Z-order) code of tile (x, y), x and y < 2^16: interleaved bits.
unsigned morton2(unsigned x, unsigned y);

}  // namespace dsr
