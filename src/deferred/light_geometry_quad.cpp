// Light geometry `quad` (§3.4.2, Listings 16-17): the tutorial's screen-aligned quad per light,
// limited to the light's scissor rectangle; every pixel of the rectangle enters the light
// shader. With EXT_depth_bounds_test (`--depth-bounds on`), pixels whose scene depth (handed to
// P-buffer 0 by the depth hand-off) lies outside the sphere's depth span are rejected before the
// shader runs (light_pass.cpp).
#include "deferred/light_geometry.h"
#include "deferred/light_pass.h"

namespace dsr {

namespace {

class QuadGeometry final : public LightGeometryPass {
public:
    QuadGeometry(const ShaderConfig& c, ProgramSet& programs) : quads_(programs, c.paths.depth_bounds) {}

    void draw(const FrameDef& f, RenderTargets&, LightQueries& q, FrameStats& stats) override {
        quads_.begin(f);
        for (const LightDraw& l : f.lights) {
            quads_.draw(f, l, q);
            ++stats.lights.passes;
        }
    }

private:
    LightQuads quads_;
};

}  // namespace

std::unique_ptr<LightGeometryPass> make_quad_geometry(const ShaderConfig& c, ProgramSet& programs) {
    return std::make_unique<QuadGeometry>(c, programs);
}

}  // namespace dsr
