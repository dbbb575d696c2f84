// The light geometries' factory (light_geometry.h): the one place that names every geometry's class.
#include "deferred/light_geometry.h"

#include "deferred/light_pass.h"
#include "dsr_error.h"

namespace dsr {

// Each defined in its geometry's file.
std::unique_ptr<LightGeometryPass> make_quad_geometry(const ShaderConfig& c, ProgramSet& programs);
std::unique_ptr<LightGeometryPass> make_volume_geometry(const ShaderConfig& c, ProgramSet& programs);
std::unique_ptr<LightGeometryPass> make_stencil_geometry(const ShaderConfig& c, ProgramSet& programs);
std::unique_ptr<LightGeometryPass> make_tiles_geometry(const ShaderConfig& c, ProgramSet& programs, int width,
                                                       int height);
std::unique_ptr<LightGeometryPass> make_auto_geometry(const ShaderConfig& c, ProgramSet& programs, int width,
                                                      int height);
std::unique_ptr<LightGeometryPass> make_screen_geometry(const ShaderConfig& c, ProgramSet& programs);

namespace {

// A copy of f without its shadowed lights.
FrameDef unshadowed(const FrameDef& f) {
    FrameDef out = f;
    out.lights.clear();
    for (const LightDraw& l : f.lights)
        if (l.shadow < 0) out.lights.push_back(l);
    return out;
}

// The geometries that shade many lights in one pass out of uniform arrays (tiles, screen, auto)
// hold up to ShaderConfig::shadow_slots shadowed lights a batch, a texture unit each. Where the GL
// leaves them none (fewer than five texture units, or no uniform room beside the batch's arrays),
// their shadowed lights are drawn one by one as the tutorial's scissored quads, through the light
// program's shadow form, after the others. Only in frames with shadowed lights; a scene without
// them never builds this.
class ShadowedAsQuads : public LightGeometryPass {
public:
    ShadowedAsQuads(std::unique_ptr<LightGeometryPass> inner, ProgramSet& programs, bool depth_bounds)
        : inner_(std::move(inner)), quads_(programs, depth_bounds, true), depth_bounds_(depth_bounds) {}

    bool prepare(const FrameDef& f, RenderTargets& t, FrameStats& stats) override {
        inner_index_.clear();
        if (f.shadowed_lights == 0) return inner_->prepare(f, t, stats);
        int n = 0;
        for (const LightDraw& l : f.lights) inner_index_.push_back(l.shadow < 0 ? n++ : -1);
        const bool inner = inner_->prepare(unshadowed(f), t, stats);
        return inner || depth_bounds_;
    }

    // A shadowed light is a quad of its own; the others are the inner geometry's, by their index
    // among the unshadowed.
    bool own_pass(size_t i) const override {
        if (inner_index_.empty()) return inner_->own_pass(i);
        return i >= inner_index_.size() || inner_index_[i] < 0 || inner_->own_pass(size_t(inner_index_[i]));
    }

    void drop(size_t i) override {
        if (inner_index_.empty()) return inner_->drop(i);
        if (i < inner_index_.size() && inner_index_[i] >= 0) inner_->drop(size_t(inner_index_[i]));
    }

    void draw(const FrameDef& f, RenderTargets& t, LightQueries& q, FrameStats& stats) override {
        if (f.shadowed_lights == 0) return inner_->draw(f, t, q, stats);
        inner_->draw(unshadowed(f), t, q, stats);
        quads_.begin(f);
        for (const LightDraw& l : f.lights)
            if (l.shadow >= 0) {
                quads_.draw(f, l, q);
                ++stats.lights.passes;
            }
    }

    void resize(int width, int height) override { inner_->resize(width, height); }

private:
    std::unique_ptr<LightGeometryPass> inner_;
    std::vector<int> inner_index_;  // prepare()'s frame: each light's index among the unshadowed, -1 if shadowed
    LightQuads quads_;
    bool depth_bounds_;
};

std::unique_ptr<LightGeometryPass> make_geometry(const ShaderConfig& c, ProgramSet& programs, int width, int height);

}  // namespace

std::unique_ptr<LightGeometryPass> make_light_geometry(const ShaderConfig& c, ProgramSet& programs, int width,
                                                       int height) {
    std::unique_ptr<LightGeometryPass> g = make_geometry(c, programs, width, height);
    const LightGeometry k = c.paths.light_geometry;
    const bool batched = draws_tiles(k) || k == LightGeometry::screen;
    if (c.opts.shadow_lights && batched && c.shadow_slots < 1)
        g = std::make_unique<ShadowedAsQuads>(std::move(g), programs, c.paths.depth_bounds);
    return g;
}

namespace {

std::unique_ptr<LightGeometryPass> make_geometry(const ShaderConfig& c, ProgramSet& programs, int width, int height) {
    switch (c.paths.light_geometry) {
        case LightGeometry::quad: return make_quad_geometry(c, programs);
        case LightGeometry::volume: return make_volume_geometry(c, programs);
        case LightGeometry::stencil: return make_stencil_geometry(c, programs);
        case LightGeometry::tiles: return make_tiles_geometry(c, programs, width, height);
        case LightGeometry::automatic: return make_auto_geometry(c, programs, width, height);
        case LightGeometry::screen: return make_screen_geometry(c, programs);
    }
    return nullptr;
}

}  // namespace

}  // namespace dsr
