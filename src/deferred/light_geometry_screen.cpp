// Light geometry `screen`: LearnOpenGL's deferred shading demo (5.8.1 "deferred_shading"), whose
// lighting pass is one full-screen quad evaluating every light at every pixel, with no light
// volume, scissor, depth or sphere test: the peer's algorithm, measured beside dsr's on the same
// context (`dsr bench`'s screen rows, the goal `demo`). The lights sit in uniform arrays as the
// tiles geometry holds a batch (lighting.glsl's five vec4s a light); light_screen.frag reads the
// G-buffer once, sums every light of the batch and blends the sum once, so where the demo's 32
// lights fit one batch a frame is one draw. The sum is rounded to 8 bits once, as the demo's
// is, not per light as quad's passes are: its image is within a few LSB of quad's, not equal.
// The demo's loop runs to a constant (`const int NR_LIGHTS = 32`), and so does this one: each
// batch is drawn by programs compiled for its light count (LIGHTS n, on first use, kept), as the
// demo's shader is compiled for its lights. A loop to BATCH that breaks at a uniform count is
// slower than the demo's own loop form on llvmpipe (docs/light_loop_cpu.md, "Smaller choices in
// the shaders"), a handicap the peer's algorithm does not have.
// Shadowed lights ride in the batches too, up to ShaderConfig::shadow_slots a batch (a batch is cut
// where one more would enter), their maps in the batch's atlas on unit 4, or without framebuffer
// objects on units 4.. (light_screen.frag SHADOW; ShadowSlots).
#include <algorithm>
#include <map>
#include <memory>

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
        : sources_(programs.sources("light_screen")),
          batch_(c.tile_batch),
          shadow_slots_(c.shadow_slots),
          shadows_(shadow_maps_packed(c.caps)) {
        // The table's programs: a full batch (light_screen.frag's LIGHTS defaults to BATCH).
        by_count_[batch_].progs = std::make_unique<LightPrograms>(programs, "light_screen", false, c.shadow_slots);
    }

    bool own_pass(size_t) const override { return false; }  // one more light in a batch

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
        ++frame_;
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
            LightPrograms& progs = programs_for(f, int(batch.size()));
            const BatchForm form = load_batch_form(f, batch, arrays_, shadows_, progs, stats, [&]() -> Program& {
                return att_shared_program(f, int(batch.size()));
            });
            Program& prog = form.prog;
            RenderState s = light_pass_state(prog.id(), false);  // additive, the whole screen
            s.blend = !base;
            gl_state().apply(s);
            arrays_.set(prog, LightArrays::kLight);
            shadows_.set(prog);
            form.set_shared();
            prog.set("with_ambient", base ? 1.0f : 0.0f);
            if (base) {
                prog.set("background", base->background);
                prog.set("ambient", base->ambient);
            }
            base = nullptr;  // the next batches add
            q.begin(double(batch.size()));  // every pixel evaluates the batch's every light
            draw_rect(f, 0, 0, float(f.width), float(f.height), false);
            q.end();
            shadows_.unbind();
            ++stats.lights.passes;
        }
    }

    // The programs for batches of n lights, compiled on first use, their frame uniforms set once a
    // frame.
    LightPrograms& programs_for(const FrameDef& f, int n) {
        Compiled& c = by_count_[n];
        if (!c.progs) c.progs = std::make_unique<LightPrograms>(sources_, "light_screen", shadow_slots_,
                                                                Defines{"LIGHTS " + std::to_string(n)});
        if (c.frame != frame_) {
            c.progs->begin(f);
            if (c.att_shared.id()) set_light_uniforms(c.att_shared, f);
            c.frame = frame_;
        }
        return *c.progs;
    }

    // The point-inverse form for n lights with ATT_SHARED (light_screen.frag), compiled on first
    // use: the demo's lights share one set of constants, and reading them from the array at each
    // light's index costs llvmpipe a load per lane (docs/light_loop_cpu.md, "Smaller choices in the
    // shaders"), a handicap the demo's shader does not have on a GPU. programs_for(f, n) came first
    // this frame.
    Program& att_shared_program(const FrameDef& f, int n) {
        Compiled& c = by_count_[n];
        if (!c.att_shared.id()) {
            c.att_shared = sources_.build("light_screen_point_inverse", Defines{"LIGHTS " + std::to_string(n), "ATT_SHARED"});
            set_light_uniforms(c.att_shared, f);
        }
        return c.att_shared;
    }

    struct Compiled {
        std::unique_ptr<LightPrograms> progs;
        Program att_shared;  // the point-inverse form with ATT_SHARED, once a batch needs it
        unsigned frame = 0;  // the frame its uniforms were set for
    };
    ProgramSources sources_;
    std::map<int, Compiled> by_count_;
    unsigned frame_ = 0;
    int batch_, shadow_slots_;
    LightArrays arrays_;
    ShadowSlots shadows_;
};

}  // namespace

std::unique_ptr<LightGeometryPass> make_screen_geometry(const ShaderConfig& c, ProgramSet& programs) {
    return std::make_unique<ScreenGeometry>(c, programs);
}

}  // namespace dsr
