// Light geometry `screen`: LearnOpenGL's deferred shading demo (5.8.1 "deferred_shading"), whose
// lighting pass is one full-screen quad evaluating every light at every pixel, with no light
// volume, scissor, depth or sphere test: the peer's algorithm, measured beside dsr's on the same
// context (`dsr bench`'s screen rows, the goal `demo`). The lights sit in uniform arrays as the
// tiles geometry holds a batch (lighting.glsl's five vec4s a light); light_screen.frag reads the
// G-buffer once, sums every light of the batch and blends the sum once, so where the demo's 32
// lights fit one batch a frame is one draw. The sum is rounded to 8 bits once, as the demo's
// is, not per light as quad's passes are: its image is within a few LSB of quad's, not equal.
#include <algorithm>

#include "deferred/light_geometry.h"
#include "deferred/light_pass.h"
#include "deferred/screen_quad.h"

namespace dsr {

namespace {

class ScreenGeometry final : public LightGeometryPass {
public:
    ScreenGeometry(const ShaderConfig& c, ProgramSet& programs) : progs_(programs, "light_screen"), batch_(c.tile_batch) {}

    void draw(const FrameDef& f, RenderTargets&, LightQueries& q, FrameStats& stats) override {
        gl_state().set_camera(f.pixels());
        progs_.begin(f);
        std::vector<int> batch;
        for (size_t first = 0; first < f.lights.size(); first += size_t(batch_)) {
            const size_t last = std::min(f.lights.size(), first + size_t(batch_));
            batch.clear();
            arrays_.clear();
            for (size_t i = first; i < last; ++i) {
                batch.push_back(int(i));
                arrays_.add(f.lights[i].params);
            }
            // The form the batch's lights allow, as the demo's shader is written for its one kind
            // of light (its lights take the attenuation law's point-light form).
            Program& prog = progs_[LightPrograms::common(f, batch)];
            gl_state().apply(light_pass_state(prog.id(), false));  // additive, the whole screen
            arrays_.set(prog, LightArrays::kLight);
            prog.set("light_count", arrays_.size());
            q.begin();
            draw_rect(f, 0, 0, float(f.width), float(f.height), false);
            q.end();
            ++stats.light_passes;
        }
    }

private:
    LightPrograms progs_;
    int batch_;
    LightArrays arrays_;
};

}  // namespace

std::unique_ptr<LightGeometryPass> make_screen_geometry(const ShaderConfig& c, ProgramSet& programs) {
    return std::make_unique<ScreenGeometry>(c, programs);
}

}  // namespace dsr
