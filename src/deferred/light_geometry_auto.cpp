// Light geometry `auto` (the default): each light of a frame by the cheapest of quad, volume and
// tiles, as the cost model prices them (light_cost.h), mixed in one frame. The three add the same
// 8-bit steps into P-buffer 0 (docs/light_geometry.md: every geometry is quad's image to the
// byte), so which light took which path changes the time, never the image.
// A frame: prepare() prices every light without tiles; where the lights would cost enough for
// tiles to pay, it measures the tiles' depth spans and prices the tiles with the exact tiles each
// light keeps; then it chooses (choose_light_paths). draw() draws each path's lights, the quads in
// batches (LightQuadBatch: a few draws, not one per light). Each path's passes are timed (see
// timed()) and the model's scale for that path follows what they took.
// Shadowed lights take any path (the model prices their lookups, LightCostModel::shadow_mpx_ms):
// the tiles hold them in their batches, a volume is drawn by its shadow form, and a quad, whose
// batches cannot bind a map per light, alone through the light program's shadow form.
#include <cmath>
#include <cstdlib>
#include <optional>

#include "deferred/ambient_fold.h"
#include "deferred/light_cost.h"
#include "deferred/light_geometry.h"
#include "deferred/light_geometry_tiles.h"
#include "deferred/light_mesh.h"
#include "deferred/light_pass.h"
#include "dsr_clock.h"
#include "gl/gl.h"
#include "gl/gpu_stamps.h"

namespace dsr {

namespace {

class AutoGeometry final : public LightGeometryPass {
public:
    AutoGeometry(const ShaderConfig& c, ProgramSet& programs, int width, int height)
        : quads_(programs, c.tile_batch),
          shadow_quads_(programs, false, true),  // no depth bounds: the hand-off is only for volumes here
          volume_progs_(programs, "light_volume"),
          volume_batch_(programs, c.tile_batch, meshes_),
          tiles_(make_tiles_pass(c, programs, width, height)),
          model_(default_light_costs(c.caps.software_rasterizer)),
          calib_(start_calibration()),
          volume_ok_(c.paths.accum_depth),
          handoff_takes_ambient_(c.paths.ambient_in_handoff && !c.paths.ambient_target),
          quad_depth_(c.paths.accum_depth && c.opts.skip.light_depth_test),
          calibrate_(c.caps.software_rasterizer),
          gpu_calibrate_(gpu_timestamps(c.caps)) {
        model_.handoff_pass = c.paths.depth_handoff == DepthHandoff::pass;  // else a blit
    }

    void resize(int width, int height) override { tiles_->resize(width, height); }

    // A kept frame measures the spans where it keeps the tiles, not where it keeps the quads; a
    // priced one may, unless the spans rest (spans_rest_). Where it cannot, the ambient pass keeps
    // its place before the plan.
    bool prepare_reads_back(const FrameDef& f) const override {
        if (!tiles_->depth_culling()) return false;
        if (keeps(f)) return kept_path_ == int(LightPath::tiles);
        return spans_rest_ == 0;
    }

    bool prepare(const FrameDef& f, RenderTargets& targets, FrameStats& stats) override {
        collect_gpu_times();
        quads_depth_now_ = false;
        // The hand-off writes the ambient term unless a full-screen light's pass takes it (the fold).
        model_.handoff_writes_ambient = handoff_takes_ambient_ && !full_screen_light(f);
        if (const std::optional<bool> kept = keep_choice(f, targets, stats)) return *kept;
        const double screen_px = double(f.width) * double(f.height);
        features_.assign(f.lights.size(), LightFeature{});
        std::vector<ScissorRect> rects(f.lights.size());
        for (size_t i = 0; i < f.lights.size(); ++i) {
            const LightDraw& l = f.lights[i];
            rects[i] = l.full ? ScissorRect{0, 0, f.width, f.height} : l.rect;
            features_[i].rect_px = double(rects[i].x1 - rects[i].x0) * double(rects[i].y1 - rects[i].y0);
            features_[i].volume_ok = volume_ok_ && !meshes_.past_far(f, l);
            features_[i].shadowed = l.shadow >= 0;
        }
        const std::array<double, kLightPaths>& scale = calib_.scale();
        grid_ = TileGrid{};
        grid_.lights_per_pass = tiles_->lights_per_pass();
        // The quads may test the handed-off depth: the plans weigh that against the volumes.
        const std::vector<double> savings = quad_depth_ ? quad_depth_savings(features_, model_) : std::vector<double>{};
        const std::vector<double>* depth_saving = quad_depth_ ? &savings : nullptr;
        raw_ = price_lights(features_, grid_, model_);
        plan_ = choose_light_paths(raw_, screen_px, model_, scale, {true, volume_ok_, false}, true, depth_saving);
        depth_ = TileDepth{};
        cull_ = nullptr;
        bool spans = false;
        // Spans that gave the tiles no light are not measured again for a few frames (a scene
        // whose lights stay as they are would pay for them every frame to learn the same).
        bool tiles_pay = !tiles_->depth_culling() ||
                         spans_worth_measuring(plan_.predicted_total_ms, screen_px, model_);
        if (tiles_pay && tiles_->depth_culling() && spans_rest_ > 0) {
            --spans_rest_;
            tiles_pay = false;
        }
        if (tiles_pay) {
            if (tiles_->depth_culling()) {
                spans = true;
                cull_ = tiles_->tile_boxes(f, tiles_->depth_spans(f, targets, stats), depth_);
            }
            tile_cover(rects, f.width, f.height, tiles_->tile_size(), cull_, features_, grid_);
            raw_ = price_lights(features_, grid_, model_);
            plan_ = choose_light_paths(raw_, screen_px, model_, scale, {true, volume_ok_, true}, true, depth_saving);
            if (spans) plan_.predicted_ms[2] += model_.spans_mpx_ms * screen_px * 1e-6;
            // Not while a path the plan took is still being measured: its scale may yet show the
            // tiles cheaper (the default scene's three lights went by volumes at a starting scale
            // of 1, measured 1.7-2.1 the next frame, and the tiles went unpriced for 8 frames).
            if (spans && plan_.count[int(LightPath::tiles)] == 0 && plan_settled()) spans_rest_ = kSpansRest;
        }
        // A path the constants may overprice is drawn to be measured (its first draw compiles,
        // the next two are timed), where its plan is predicted close to the best: the image is
        // the same whichever path a light takes. The tiles only where they were priced.
        std::array<bool, kLightPaths> explore{};
        for (int p = 0; p < kLightPaths; ++p)
            explore[size_t(p)] =
                explore_left_[p] > 0 && calib_.samples(LightPath(p)) < LightCostCalibration::kExploreSamples;
        explore[int(LightPath::volume)] = explore[int(LightPath::volume)] && volume_ok_;
        explore[int(LightPath::tiles)] = explore[int(LightPath::tiles)] && tiles_pay;
        exploring_ = -1;
        if (std::optional<LightExploration> e = exploration_plan(raw_, plan_, screen_px, model_, scale, explore, true)) {
            exploring_ = int(e->path);
            --explore_left_[exploring_];
            plan_ = std::move(e->plan);
            if (spans) {  // as above: the spans measured, paid by the tiles' prediction
                plan_.predicted_ms[2] += model_.spans_mpx_ms * screen_px * 1e-6;
                spans_rest_ = 0;
            }
        }
        // The quads against the scene's depth where the plan priced them so, or (an exploring
        // plan's) where what it saves them pays for the hand-off.
        quad_depth_choice_ = quad_depth_ ? choose_quad_depth(plan_, features_, screen_px, model_, scale[0]) : QuadDepthChoice{};
        quads_depth_now_ = quad_depth_choice_.on;
        if (quads_depth_now_ && !plan_.quads_depth)
            plan_.predicted_ms[0] += quad_depth_choice_.handoff_ms - quad_depth_choice_.raw_saving_ms * scale[0];
        planned_ = true;
        priced_ = true;
        stats.auto_kept = false;
        stats.auto_explored = exploring_;
        // Every light by the tiles, or every light by quads: the next frames keep that choice
        // unpriced (keep_choice); not an exploring frame's choice.
        kept_path_ = -1;
        for (const LightPath p : {LightPath::quad, LightPath::tiles})
            if (exploring_ < 0 && !f.lights.empty() && plan_.count[size_t(p)] == int(f.lights.size())) kept_path_ = int(p);
        keep_rest_ = kept_path_ >= 0 ? kKeepFrames : 0;
        priced_lights_ = f.lights.size();
        predicted_ms_ = plan_.predicted_ms[0] + plan_.predicted_ms[1] + plan_.predicted_ms[2];
        if (kept_path_ >= 0) {
            // What a kept frame is predicted and calibrated against: this frame's lights' unscaled
            // prices on the path, and what the path adds once (its state, the spans, the hand-off
            // less what it saves the quads).
            kept_raw_ = 0;
            for (const auto& r : raw_) kept_raw_ += r[size_t(kept_path_)];
            kept_once_ms_ = plan_.predicted_ms[size_t(kept_path_)] - kept_raw_ * scale[size_t(kept_path_)];
        }
        report(stats, spans, screen_px);
        return plan_.count[int(LightPath::volume)] > 0 || quads_depth_now_;
    }

    // Where the last priced frame sent every light through the tiles, or every light by quads, the
    // next kKeepFrames frames with as many lights keep that choice without pricing; the tiles'
    // spans are measured (the tiles cull by them), and the planner culls each light's tiles itself,
    // as the tiles geometry does; the quads keep the last choice of the scene's depth. On a GPU the
    // tiles' pricing runs after the spans' read-back while the GPU waits (1024-overlap at
    // 1920x1080: auto's light stage 5.7 ms against the tiles geometry's 4.7 with the same passes);
    // 4096 lights by quads cost the H200's CPU 0.06-0.10 ms a frame to price (docs/gpu.md). The
    // image is the same whatever the choice; a kept frame is predicted and calibrated against the
    // last priced frame's prices (the choice assumes its lights are much as they were). Volumes are
    // not kept: a light the camera has since put past the far plane cannot take one.
    // Whether frame f keeps the last priced frame's choice (keep_choice).
    bool keeps(const FrameDef& f) const {
        return kept_path_ >= 0 && keep_rest_ > 0 && f.lights.size() == priced_lights_ &&
               (kept_path_ != int(LightPath::tiles) || tiles_->depth_culling());
    }

    // Whether every path the plan sends a light by has been measured (LightCostCalibration::samples).
    bool plan_settled() const {
        for (int p = 0; p < kLightPaths; ++p)
            if (plan_.count[size_t(p)] > 0 && calib_.samples(LightPath(p)) < LightCostCalibration::kExploreSamples)
                return false;
        return true;
    }

    // The hand-off's answer for a kept frame; nullopt where the frame is to be priced.
    std::optional<bool> keep_choice(const FrameDef& f, RenderTargets& targets, FrameStats& stats) {
        if (!keeps(f)) return std::nullopt;
        const LightPath p = LightPath(kept_path_);
        --keep_rest_;
        features_.assign(f.lights.size(), LightFeature{});
        depth_ = TileDepth{};
        cull_ = p == LightPath::tiles ? tiles_->tile_boxes(f, tiles_->depth_spans(f, targets, stats), depth_) : nullptr;
        plan_.path.assign(f.lights.size(), p);
        plan_.count = {0, 0, 0};
        plan_.count[size_t(p)] = int(f.lights.size());
        raw_.assign(f.lights.size(), {0, 0, 0});
        quads_depth_now_ = p == LightPath::quad && quad_depth_choice_.on;
        planned_ = true;
        priced_ = false;
        stats.auto_kept = true;
        stats.auto_explored = exploring_ = -1;
        predicted_ms_ = kept_raw_ * calib_.scale()[size_t(p)] + kept_once_ms_;
        report(stats, p == LightPath::tiles, double(f.width) * double(f.height));
        return quads_depth_now_;
    }

    // The plan's figures for --stats; the lights on each path are counted in draw(), after any drop().
    void report(FrameStats& stats, bool spans, double screen_px) const {
        stats.auto_geometry = true;
        stats.auto_spans = spans;
        stats.auto_handoff_ms = handoff_ms(model_, screen_px);
        for (int p = 0; p < kLightPaths; ++p) stats.auto_scale[p] = calib_.scale()[size_t(p)];
        stats.auto_predicted_ms = predicted_ms_;
    }

    // A full-screen light sent by quad or volume is a pass of its own; by the tiles, one more light
    // in their batches.
    bool own_pass(size_t i) const override {
        return planned_ && i < plan_.path.size() && plan_.path[i] != LightPath::tiles;
    }

    void drop(size_t i) override {
        if (!planned_ || i >= plan_.path.size()) return;
        --plan_.count[size_t(plan_.path[i])];
        plan_.path.erase(plan_.path.begin() + std::ptrdiff_t(i));
        raw_.erase(raw_.begin() + std::ptrdiff_t(i));
        features_.erase(features_.begin() + std::ptrdiff_t(i));
        if (i < depth_.lights.size()) depth_.lights.erase(depth_.lights.begin() + std::ptrdiff_t(i));
    }

    void draw(const FrameDef& f, RenderTargets& targets, LightQueries& q, FrameStats& stats) override {
        if (!planned_ || plan_.path.size() != f.lights.size()) {
            prepare(f, targets, stats);  // (prepare() saw another frame)
            quads_depth_now_ = false;    // and no hand-off followed this one
        }
        planned_ = false;
        for (int p = 0; p < kLightPaths; ++p) stats.auto_lights[p] = plan_.count[size_t(p)];  // less a light drop() took
        std::vector<const LightDraw*> by_path[kLightPaths];
        for (int p = 0; p < kLightPaths; ++p) by_path[p].reserve(size_t(plan_.count[size_t(p)]));
        double raw[kLightPaths] = {0, 0, 0};  // the model's ms for each path's lights, unscaled
        for (size_t i = 0; i < f.lights.size(); ++i) {
            const int p = int(plan_.path[i]);
            by_path[p].push_back(&f.lights[i]);
            raw[p] += raw_[i][size_t(p)];
        }
        if (!priced_) raw[kept_path_] = kept_raw_;  // a kept frame: the last priced frame's
        if (quads_depth_now_) raw[int(LightPath::quad)] -= quad_depth_choice_.raw_saving_ms;
        if (!by_path[int(LightPath::tiles)].empty())
            timed(LightPath::tiles, raw, [&] {
                FrameDef sub = f;  // the tiles' lights alone, with their bounds
                sub.lights.clear();
                TileDepth depth;
                std::vector<std::vector<int>> kept;  // tile_cover's, so the planner does not cull again
                if (cull_) depth.tiles = cull_->tiles;
                for (size_t i = 0; i < f.lights.size(); ++i)
                    if (plan_.path[i] == LightPath::tiles) {
                        sub.lights.push_back(f.lights[i]);
                        kept.push_back(std::move(features_[i].tiles));
                        if (cull_) depth.lights.push_back(cull_->lights[i]);
                    }
                // A kept frame has no lists of its own: the planner culls (priced_ false).
                tiles_->draw_lights(sub, cull_ ? &depth : nullptr, q, stats, priced_ ? &kept : nullptr);
            });
        if (!by_path[int(LightPath::volume)].empty())
            timed(LightPath::volume, raw, [&] {
                meshes_.shade_volumes(f, by_path[int(LightPath::volume)], volume_batch_, volume_progs_, q, stats);
            });
        if (!by_path[int(LightPath::quad)].empty())
            timed(LightPath::quad, raw, [&] {
                std::vector<const LightDraw*> batched;
                batched.reserve(by_path[int(LightPath::quad)].size());
                for (const LightDraw* l : by_path[int(LightPath::quad)])
                    if (l->shadow < 0) batched.push_back(l);
                quads_.draw(f, batched, q, stats, quads_depth_now_);
                stats.auto_quad_depth = quads_depth_now_ && !batched.empty();
                if (batched.size() == by_path[int(LightPath::quad)].size()) return;
                shadow_quads_.begin(f);
                for (const LightDraw* l : by_path[int(LightPath::quad)])
                    if (l->shadow >= 0) {
                        shadow_quads_.draw(f, *l, q);
                        ++stats.light_passes;
                    }
            });
    }

private:
    // Each path's scale before any frame: 1 (a guess its first measurement replaces), or
    // DSR_LIGHT_COST_SCALE's (docs/light_geometry.md).
    static LightCostCalibration start_calibration() {
        const char* e = std::getenv("DSR_LIGHT_COST_SCALE");
        return e && *e ? LightCostCalibration(parse_cost_scale(e)) : LightCostCalibration();
    }

    // A path's passes, timed, and the path's scale updated: on a CPU rasteriser by glFinish and
    // the wall clock, as its stages are timed; on a GPU by two timestamp queries
    // (ARB_timer_query's glQueryCounter, which may sit inside the frame timer's elapsed-time
    // query), read at the next frame's prepare() where the GPU has finished them, never waited for.
    template <class F>
    void timed(LightPath p, const double* raw, F&& draw) {
        // A path's first frame is not measured: the GL compiles its programs' code on first use
        // (llvmpipe: tens of milliseconds).
        // On a CPU rasteriser one frame in kTimedEvery: the glFinish around a path's passes stops the
        // rasteriser's work overlapping the CPU's (1024 lights at 512x512: 0.7 ms a frame, timed every frame).
        // Counted per path, and only draws the model priced: with one counter for all, where two
        // paths took turns the second was never timed (256 lights at 512x512: the quad path's
        // scale stayed 1 over 48 frames, its prediction 2.8x what it took). The path's second
        // priced draw is the first timed (its first compiles), so the scale is measured by the
        // third frame instead of the sixth.
        // An exploring path's every draw after its first.
        const bool wall_now = calibrate_ && raw[int(p)] > 0 &&
                              (timed_draws_[int(p)]++ % kTimedEvery == 1 || (exploring_ == int(p) && drawn_before_[int(p)]));
        if (!drawn_before_[int(p)] || (!wall_now && !gpu_calibrate_)) {
            drawn_before_[int(p)] = true;
            draw();
            return;
        }
        if (gpu_calibrate_) {
            const GLuint begin = stamps_.stamp();
            draw();
            pending_.push_back(GpuTime{p, begin, stamps_.stamp(), raw[int(p)]});
            return;
        }
        glFinish();
        const double t0 = now_ms();
        draw();
        glFinish();
        calib_.add(p, now_ms() - t0, raw[int(p)]);
    }

    // The last frames' GPU measurements that are ready into the calibration; those not ready wait
    // for a later frame.
    void collect_gpu_times() {
        std::vector<GpuTime> busy;
        for (const GpuTime& t : pending_) {
            if (!GpuStamps::ready(t.end)) {
                busy.push_back(t);
                continue;
            }
            if (t.raw_ms > 0) calib_.add(t.path, GpuStamps::ms(t.end) - GpuStamps::ms(t.begin), t.raw_ms);
            release(t);
        }
        pending_.clear();
        // At most a few frames' worth wait; the rest are given up, their stamps back to the pool.
        for (const GpuTime& t : busy) {
            if (pending_.size() < 3 * kLightPaths)
                pending_.push_back(t);
            else
                release(t);
        }
    }

    LightQuadBatch quads_;
    LightQuads shadow_quads_;  // the quad path's shadowed lights, one by one
    LightMeshes meshes_;
    LightPrograms volume_progs_;
    LightVolumeBatch volume_batch_;  // its point lights' meshes in batches
    std::unique_ptr<TilesPass> tiles_;
    LightCostModel model_;
    LightCostCalibration calib_;
    bool volume_ok_;   // the paths give P-buffer 0 the scene's depth (the hand-off)
    bool handoff_takes_ambient_;  // the hand-off's pass writes the ambient term (Paths::ambient_in_handoff)
    bool quad_depth_;  // and the light shaders reject surfaces outside a light's depth span: so may GL
    QuadDepthChoice quad_depth_choice_;  // the frame's (choose_quad_depth)
    bool quads_depth_now_ = false;       // this frame's quads are drawn against the handed-off depth
    bool calibrate_;      // a CPU rasteriser: glFinish and the wall clock
    bool gpu_calibrate_;  // a GPU with ARB_timer_query: timestamps
    struct GpuTime {
        LightPath path;
        GLuint begin, end;
        double raw_ms;
    };
    GpuStamps stamps_;
    std::vector<GpuTime> pending_;
    // A measurement's two stamps back to the pool (collect_gpu_times).
    void release(const GpuTime& t) {
        stamps_.release(t.begin);
        stamps_.release(t.end);
    }
    bool drawn_before_[kLightPaths] = {false, false, false};
    static constexpr int kSpansRest = 8;
    // Frames each path may be explored in, at most (three draws measure it twice; a fourth where a
    // GPU's timestamps were not ready), and the path this frame explores (-1: none).
    int explore_left_[kLightPaths] = {4, 4, 4};
    int exploring_ = -1;
    static constexpr int kKeepFrames = 7;  // frames an all-tiles or all-quads choice is kept unpriced (one priced in 8)
    int kept_path_ = -1;      // the path every light of the last priced frame took (tiles or quad), else -1
    int keep_rest_ = 0;       // frames left to keep it
    size_t priced_lights_ = 0;  // the lights of the frame that chose it (before any drop())
    bool priced_ = false;     // this frame's lights were priced (features_ hold their kept tiles)
    double predicted_ms_ = 0; // the frame's prediction (a kept frame's from the last priced frame's prices)
    double kept_raw_ = 0;     // the last kept choice's priced frame: its unscaled prices on that path, summed
    double kept_once_ms_ = 0; // and what the path added once (state, spans, hand-off less the quads' saving)
    static constexpr int kTimedEvery = 4;
    unsigned timed_draws_[kLightPaths] = {0, 0, 0};  // priced draws of each path so far (one in kTimedEvery timed)
    int spans_rest_ = 0;  // frames left before the spans are measured again
    // The frame's plan, from prepare() to draw().
    bool planned_ = false;
    std::vector<LightFeature> features_;
    TileGrid grid_;
    LightPrices raw_;  // each light's prices, unscaled
    LightPathPlan plan_;
    TileDepth depth_;
    const TileDepth* cull_ = nullptr;
};

}  // namespace

std::unique_ptr<LightGeometryPass> make_auto_geometry(const ShaderConfig& c, ProgramSet& programs, int width,
                                                      int height) {
    return std::make_unique<AutoGeometry>(c, programs, width, height);
}

}  // namespace dsr
