// Light geometry `screen`: LearnOpenGL's deferred shading demo (5.8.1 "deferred_shading"), whose
// lighting pass is one full-screen quad evaluating every light at every pixel, with no light
// volume, scissor, depth or sphere test: the peer's algorithm, measured beside dsr's on the same
// context (`dsr bench`'s screen rows, the goal `demo`). The lights sit in uniform arrays as the
// tiles geometry holds a batch (lighting.glsl's five vec4s a light); light_screen.frag reads the
// G-buffer once, sums every light of the batch and blends the sum once, so where the demo's 32
// lights fit one batch a frame is one draw. The sum is rounded to 8 bits once, as the demo's
// is, not per light as quad's passes are: its image is within a few LSB of quad's, not equal.
// Shadowed lights ride in the batches too, up to ShaderConfig::shadow_slots a batch (a batch is cut
// where one more would enter), their maps in the batch's atlas on unit 4, or without framebuffer
// objects on units 4.. (light_screen.frag SHADOW; ShadowSlots).
#include <algorithm>

#include "deferred/light_geometry.h"
#include "deferred/light_pass.h"
#include "deferred/main_buffer_map.h"
#include "deferred/screen_quad.h"
#include "deferred/tile_plan.h"

namespace dsr {

namespace {

class ScreenGeometry final : public LightGeometryPass {
public:
    ScreenGeometry(const ShaderConfig& c, ProgramSet& programs)
        : progs_(programs, "light_screen", false, c.shadow_slots),
          batch_(c.tile_batch),
          shadow_slots_(c.shadow_slots),
          shadows_(shadow_maps_packed(c.caps)) {}

    bool own_pass(size_t) const override { return false; }  // one more light in a batch
    bool draws_ambient() const override { return true; }  // where the fold may be made (LightingStage::may_fold)

    void draw(const FrameDef& f, RenderTargets&, LightQueries& q, FrameStats& stats) override {
        draw_batches(f, q, stats, nullptr);
    }

    // LearnOpenGL's lighting pass starts from its ambient term (Diffuse * 0.1): the first batch
    // writes, blending off, what the clear and the ambient pass would have left, with its lights on
    // top, so the demo's row pays no ambient pass it does not have.
    void draw_with_ambient(const FrameDef& f, RenderTargets&, LightQueries& q, FrameStats& stats,
                           const AmbientTerm& ambient) override {
        draw_batches(f, q, stats, &ambient);
    }

private:
    // base: the colours the first batch writes under its lights, or null.
    void draw_batches(const FrameDef& f, LightQueries& q, FrameStats& stats, const AmbientTerm* base) {
        gl_state().set_camera(f.pixels());
        progs_.begin(f);
        shadows_.begin_frame();
        std::vector<int> order(f.lights.size());
        std::vector<bool> shadowed;
        for (size_t i = 0; i < f.lights.size(); ++i) {
            order[i] = int(i);
            shadowed.push_back(f.lights[i].shadow >= 0);
        }
        const bool any_shadow = f.shadowed_lights > 0 && shadow_slots_ > 0;
        for (const std::vector<int>& batch : cut_batches(order, batch_, any_shadow ? &shadowed : nullptr, shadow_slots_)) {
            // The form the batch's lights allow, as the demo's shader is written for its one kind
            // of light (its lights take the attenuation law's point-light form); with shadow maps
            // the shadow form.
            Program& prog = load_batch(f, batch, arrays_, shadows_, progs_, stats);
            RenderState s = light_pass_state(prog.id(), false);  // additive, the whole screen
            s.blend = !base;
            gl_state().apply(s);
            arrays_.set(prog, LightArrays::kLight);
            shadows_.set(prog);
            prog.set("light_count", arrays_.size());
            prog.set("with_ambient", base ? 1.0f : 0.0f);
            if (base) {
                prog.set("background", base->background);
                prog.set("ambient", base->ambient);
            }
            base = nullptr;  // the next batches add
            q.begin();
            draw_rect(f, 0, 0, float(f.width), float(f.height), false);
            q.end();
            shadows_.unbind();
            ++stats.light_passes;
        }
    }

    LightPrograms progs_;
    int batch_, shadow_slots_;
    LightArrays arrays_;
    ShadowSlots shadows_;
};

}  // namespace

std::unique_ptr<LightGeometryPass> make_screen_geometry(const ShaderConfig& c, ProgramSet& programs) {
    return std::make_unique<ScreenGeometry>(c, programs);
}

}  // namespace dsr
