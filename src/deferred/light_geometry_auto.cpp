// Light geometry `auto` (the default): each light of a frame by the cheapest of quad, volume and
// tiles, as the cost model prices them (light_cost.h), mixed in one frame. The three add the same
// 8-bit steps into P-buffer 0 (docs/light_geometry.md: every geometry is quad's image to the
// byte), so which light took which path changes the time, never the image.
// A frame: prepare() prices every light without tiles; where the lights would cost enough for
// tiles to pay, it measures the tiles' depth spans and prices the tiles with the exact tiles each
// light keeps; then it chooses (choose_light_paths). draw() draws each path's lights, the quads in
// batches (LightQuadBatch: a few draws, not one per light). Which frames keep, explore, rest the
// spans and time a path is AutoPolicy's (auto_policy.h); the timing is PathTimer's
// (path_timer.h), and each path's scale in the model follows what its passes took.
// Shadowed lights take any path (the model prices their lookups, LightCostModel::shadow_mpx_ms):
// the tiles hold them in their batches, a volume is drawn by its shadow form, and a quad, whose
// batches cannot bind a map per light, alone through the light program's shadow form.
#include <optional>

#include "deferred/ambient_fold.h"
#include "deferred/auto_policy.h"
#include "deferred/light_cost.h"
#include "deferred/light_geometry.h"
#include "deferred/light_geometry_tiles.h"
#include "deferred/light_mesh.h"
#include "deferred/light_pass.h"
#include "deferred/path_timer.h"
#include "dsr_clock.h"

namespace dsr {

namespace {

// The frame's plan, from prepare() to draw().
struct AutoFrame {
    bool planned = false;  // prepare() planned this frame (draw() clears it)
    bool priced = false;   // its lights were priced (else it keeps the last priced frame's choice)
    std::optional<LightPath> exploring;  // the path it explores
    std::vector<LightFeature> features;  // per light (a priced frame's hold the tiles each keeps)
    TileGrid grid;
    LightPrices raw;  // each light's prices, unscaled
    LightPathPlan plan;
    TileDepth depth;
    const TileDepth* cull = nullptr;  // the tiles' boxes, where the frame measured the spans
    // Whether the last priced frame's quads test the handed-off depth, and what that saves them
    // (choose_quad_depth; a kept frame keeps it).
    QuadDepthChoice quad_depth;
    bool quads_test_depth = false;  // this frame's quads are drawn against the handed-off depth
    double predicted_ms = 0;        // the frame's prediction
};

// What a kept frame is predicted and calibrated against: the priced frame's lights' unscaled
// prices on the kept path, summed, and what the path added once (its state, the spans, the
// hand-off less what it saves the quads). The choice assumes the lights are much as they were.
struct KeptPrices {
    double raw_ms = 0;
    double once_ms = 0;
};

class AutoGeometry final : public LightGeometryPass {
public:
    AutoGeometry(const ShaderConfig& c, ProgramSet& programs, int width, int height)
        : quads_(programs, c.tile_batch),
          shadow_quads_(programs, false, true),  // no depth bounds: the hand-off is only for volumes here
          volume_progs_(programs, "light_volume"),
          volume_batch_(programs, c.tile_batch, meshes_),
          tiles_(make_tiles_pass(c, programs, width, height)),
          model_(default_light_costs(c.caps.software_rasterizer)),
          calib_(c.opts.light_cost_scale ? LightCostCalibration(*c.opts.light_cost_scale) : LightCostCalibration()),
          volumes_ok_(c.paths.accum_depth),
          handoff_takes_ambient_(c.paths.ambient_in_handoff && !c.paths.ambient_target),
          quads_may_test_depth_(c.paths.accum_depth && c.opts.skip.light_depth_test),
          policy_(path_clock(c.caps)),
          timer_(path_clock(c.caps)) {
        model_.handoff_pass = c.paths.depth_handoff == DepthHandoff::pass;  // else a blit
    }

    void resize(int width, int height) override { tiles_->resize(width, height); }

    // A kept frame measures the spans where it keeps the tiles, not where it keeps the quads; a
    // priced one may, unless the spans rest. Where it cannot, the ambient pass keeps its place
    // before the plan.
    bool prepare_reads_back(const FrameDef& f) const override {
        if (!tiles_->depth_culling()) return false;
        if (policy_.keeps(f.lights.size(), true)) return policy_.kept_path() == LightPath::tiles;
        return policy_.spans_awake();
    }

    bool prepare(const FrameDef& f, RenderTargets& targets, FrameStats& stats) override {
        timer_.collect(calib_);
        frame_.quads_test_depth = false;
        // The hand-off writes the ambient term unless a full-screen light's pass takes it (the fold).
        model_.handoff_writes_ambient = handoff_takes_ambient_ && !full_screen_light(f);
        if (policy_.keeps(f.lights.size(), tiles_->depth_culling())) return keep_choice(f, targets, stats);
        const double screen_px = double(f.width) * double(f.height);
        const Priced priced = price(f, targets, stats, screen_px);
        explore(priced, screen_px);
        choose_quads_depth(screen_px);
        frame_.planned = true;
        frame_.priced = true;
        stats.auto_geometry.kept = false;
        stats.auto_geometry.explored = frame_.exploring;
        const std::array<double, kLightPaths>& predicted = frame_.plan.predicted_ms;
        frame_.predicted_ms = predicted[at(LightPath::quad)] + predicted[at(LightPath::volume)] + predicted[at(LightPath::tiles)];
        if (const std::optional<LightPath> kept =
                policy_.priced(frame_.plan.count, f.lights.size(), frame_.exploring.has_value())) {
            kept_.raw_ms = 0;
            for (const auto& r : frame_.raw) kept_.raw_ms += r[at(*kept)];
            kept_.once_ms = predicted[at(*kept)] - kept_.raw_ms * calib_.scale()[at(*kept)];
        }
        report(stats, priced.spans, screen_px);
        return frame_.plan.count[at(LightPath::volume)] > 0 || frame_.quads_test_depth;
    }

    // A full-screen light sent by quad or volume is a pass of its own; by the tiles, one more light
    // in their batches.
    bool own_pass(size_t i) const override {
        return frame_.planned && i < frame_.plan.path.size() && frame_.plan.path[i] != LightPath::tiles;
    }

    void drop(size_t i) override {
        if (!frame_.planned || i >= frame_.plan.path.size()) return;
        --frame_.plan.count[at(frame_.plan.path[i])];
        frame_.plan.path.erase(frame_.plan.path.begin() + std::ptrdiff_t(i));
        frame_.raw.erase(frame_.raw.begin() + std::ptrdiff_t(i));
        frame_.features.erase(frame_.features.begin() + std::ptrdiff_t(i));
        if (i < frame_.depth.lights.size()) frame_.depth.lights.erase(frame_.depth.lights.begin() + std::ptrdiff_t(i));
    }

    void draw(const FrameDef& f, RenderTargets& targets, LightQueries& q, FrameStats& stats) override {
        if (!frame_.planned || frame_.plan.path.size() != f.lights.size()) {
            prepare(f, targets, stats);       // (prepare() saw another frame)
            frame_.quads_test_depth = false;  // and no hand-off followed this one
        }
        frame_.planned = false;
        const LightPathPlan& plan = frame_.plan;
        for (const LightPath p : kAllLightPaths) stats.auto_geometry.lights[at(p)] = plan.count[at(p)];  // less a light drop() took
        std::array<std::vector<const LightDraw*>, kLightPaths> by_path;
        for (const LightPath p : kAllLightPaths) by_path[at(p)].reserve(size_t(plan.count[at(p)]));
        std::array<double, kLightPaths> raw = {0, 0, 0};  // the model's ms for each path's lights, unscaled
        for (size_t i = 0; i < f.lights.size(); ++i) {
            const LightPath p = plan.path[i];
            by_path[at(p)].push_back(&f.lights[i]);
            raw[at(p)] += frame_.raw[i][at(p)];
        }
        if (!frame_.priced) raw[at(*policy_.kept_path())] = kept_.raw_ms;
        if (frame_.quads_test_depth) raw[at(LightPath::quad)] -= frame_.quad_depth.raw_saving_ms;
        if (!by_path[at(LightPath::tiles)].empty())
            timed(LightPath::tiles, raw, [&] { draw_tiles(f, q, stats); });
        if (!by_path[at(LightPath::volume)].empty())
            timed(LightPath::volume, raw, [&] {
                meshes_.shade_volumes(f, by_path[at(LightPath::volume)], volume_batch_, volume_progs_, q, stats);
            });
        if (!by_path[at(LightPath::quad)].empty())
            timed(LightPath::quad, raw, [&] { draw_quads(f, by_path[at(LightPath::quad)], q, stats); });
    }

private:
    struct Priced {
        bool tiles = false;  // the tiles were priced (they pay, and the spans did not rest)
        bool spans = false;  // and the spans measured for them
    };

    // The frame's lights' features and prices, the tiles' where they pay, and the cheapest plan.
    Priced price(const FrameDef& f, RenderTargets& targets, FrameStats& stats, double screen_px) {
        std::vector<LightFeature>& features = frame_.features;
        features.assign(f.lights.size(), LightFeature{});
        std::vector<ScissorRect> rects(f.lights.size());
        for (size_t i = 0; i < f.lights.size(); ++i) {
            const LightDraw& l = f.lights[i];
            rects[i] = l.full ? ScissorRect{0, 0, f.width, f.height} : l.rect;
            features[i].rect_px = double(rects[i].x1 - rects[i].x0) * double(rects[i].y1 - rects[i].y0);
            features[i].volume_ok = volumes_ok_ && !meshes_.past_far(f, l);
            features[i].shadowed = l.shadow >= 0;
        }
        const std::array<double, kLightPaths>& scale = calib_.scale();
        frame_.grid = TileGrid{};
        frame_.grid.lights_per_pass = tiles_->lights_per_pass();
        // The quads may test the handed-off depth: the plans weigh that against the volumes.
        const std::vector<double> savings = quads_may_test_depth_ ? quad_depth_savings(features, model_) : std::vector<double>{};
        const std::vector<double>* depth_saving = quads_may_test_depth_ ? &savings : nullptr;
        frame_.raw = price_lights(features, frame_.grid, model_);
        frame_.plan = choose_light_paths(frame_.raw, screen_px, model_, scale, {true, volumes_ok_, false}, true, depth_saving);
        frame_.depth = TileDepth{};
        frame_.cull = nullptr;
        Priced priced;
        const bool culling = tiles_->depth_culling();
        priced.tiles = !culling || spans_worth_measuring(frame_.plan.predicted_total_ms, screen_px, model_);
        if (priced.tiles && culling) priced.tiles = policy_.measure_spans();
        if (!priced.tiles) return priced;
        const std::vector<DepthSpan> spans = culling ? tiles_->depth_spans(f, targets, stats) : std::vector<DepthSpan>{};
        priced.spans = culling;
        const double cpu0 = thread_cpu_ms();  // the tiles' culling (TileStats::cull_cpu_ms)
        if (culling) frame_.cull = tiles_->tile_boxes(f, spans, frame_.depth);
        tile_cover(rects, f.width, f.height, tiles_->tile_size(), frame_.cull, features, frame_.grid);
        stats.tiles.cull_cpu_ms += thread_cpu_ms() - cpu0;
        frame_.raw = price_lights(features, frame_.grid, model_);
        frame_.plan = choose_light_paths(frame_.raw, screen_px, model_, scale, {true, volumes_ok_, true}, true, depth_saving);
        if (priced.spans) frame_.plan.predicted_ms[at(LightPath::tiles)] += spans_ms(screen_px);
        // Not while a path the plan took is still being measured: its scale may yet show the
        // tiles cheaper.
        if (priced.spans && frame_.plan.count[at(LightPath::tiles)] == 0 && plan_measured()) policy_.rest_spans();
        return priced;
    }

    // A path the constants may overprice drawn to be measured, where its plan is predicted close
    // to the best (exploration_plan): the image is the same whichever path a light takes.
    void explore(const Priced& priced, double screen_px) {
        const std::array<bool, kLightPaths> drawable = {true, volumes_ok_, priced.tiles};
        frame_.exploring.reset();
        std::optional<LightExploration> e = exploration_plan(frame_.raw, frame_.plan, screen_px, model_, calib_.scale(),
                                                             policy_.may_explore(paths_measured(calib_), drawable), true);
        if (!e) return;
        frame_.exploring = e->path;
        policy_.explored(e->path);
        frame_.plan = std::move(e->plan);
        if (priced.spans) {  // as in price(): the spans measured, paid by the tiles' prediction
            frame_.plan.predicted_ms[at(LightPath::tiles)] += spans_ms(screen_px);
            policy_.wake_spans();
        }
    }

    // The quads against the scene's depth where the plan priced them so, or (an exploring plan's)
    // where what it saves them pays for the hand-off.
    void choose_quads_depth(double screen_px) {
        const double quad_scale = calib_.scale()[at(LightPath::quad)];
        frame_.quad_depth = quads_may_test_depth_
                                ? choose_quad_depth(frame_.plan, frame_.features, screen_px, model_, quad_scale)
                                : QuadDepthChoice{};
        frame_.quads_test_depth = frame_.quad_depth.on;
        if (frame_.quads_test_depth && !frame_.plan.quads_depth)
            frame_.plan.predicted_ms[at(LightPath::quad)] +=
                frame_.quad_depth.handoff_ms - frame_.quad_depth.raw_saving_ms * quad_scale;
    }

    // A frame that keeps the last priced frame's choice (AutoPolicy::keeps): every light by the
    // kept path, unpriced. Kept tiles measure the spans (they cull by them) and their planner
    // culls each light's tiles itself, as the tiles geometry does; kept quads keep the priced
    // frame's choice of the scene's depth. Volumes are not kept: a light the camera has since put
    // past the far plane cannot take one. Returns the hand-off's answer.
    bool keep_choice(const FrameDef& f, RenderTargets& targets, FrameStats& stats) {
        const LightPath p = policy_.keep_frame();
        frame_.features.assign(f.lights.size(), LightFeature{});
        frame_.depth = TileDepth{};
        if (p == LightPath::tiles) {
            const std::vector<DepthSpan> spans = tiles_->depth_spans(f, targets, stats);
            const double cpu0 = thread_cpu_ms();
            frame_.cull = tiles_->tile_boxes(f, spans, frame_.depth);
            stats.tiles.cull_cpu_ms += thread_cpu_ms() - cpu0;
        } else {
            frame_.cull = nullptr;
        }
        frame_.plan.path.assign(f.lights.size(), p);
        frame_.plan.count = {0, 0, 0};
        frame_.plan.count[at(p)] = int(f.lights.size());
        frame_.raw.assign(f.lights.size(), {0, 0, 0});
        frame_.quads_test_depth = p == LightPath::quad && frame_.quad_depth.on;
        frame_.planned = true;
        frame_.priced = false;
        frame_.exploring.reset();
        stats.auto_geometry.kept = true;
        stats.auto_geometry.explored.reset();
        frame_.predicted_ms = kept_.raw_ms * calib_.scale()[at(p)] + kept_.once_ms;
        report(stats, p == LightPath::tiles, double(f.width) * double(f.height));
        return frame_.quads_test_depth;
    }

    // Whether every path the plan sends a light by has been measured (LightCostCalibration::samples).
    bool plan_measured() const {
        const std::array<bool, kLightPaths> measured = paths_measured(calib_);
        for (const LightPath p : kAllLightPaths)
            if (frame_.plan.count[at(p)] > 0 && !measured[at(p)]) return false;
        return true;
    }

    double spans_ms(double screen_px) const { return model_.spans_mpx_ms * screen_px * 1e-6; }

    // The plan's figures for --stats; the lights on each path are counted in draw(), after any drop().
    void report(FrameStats& stats, bool spans, double screen_px) const {
        stats.auto_geometry.on = true;
        stats.auto_geometry.spans = spans;
        stats.auto_geometry.handoff_ms = handoff_ms(model_, screen_px);
        for (const LightPath p : kAllLightPaths) stats.auto_geometry.scale[at(p)] = calib_.scale()[at(p)];
        stats.auto_geometry.predicted_ms = frame_.predicted_ms;
    }

    // Path p's passes, timed where the policy says, its scale updated from what they took.
    template <class F>
    void timed(LightPath p, const std::array<double, kLightPaths>& raw, F&& draw) {
        const bool measure = policy_.time_draw(p, raw[at(p)] > 0, frame_.exploring == p);
        timer_.draw(p, measure, raw[at(p)], calib_, draw);
    }

    // The tiles' lights alone, with their bounds; a priced frame hands over the tiles each light
    // keeps (tile_cover's), so the planner does not cull again; a kept frame's planner culls.
    // Where every light takes the tiles, the frame and its culling go as they are, uncopied.
    void draw_tiles(const FrameDef& f, LightQueries& q, FrameStats& stats) {
        std::vector<std::vector<int>> kept;
        if (frame_.plan.count[at(LightPath::tiles)] == int(f.lights.size())) {
            if (frame_.priced)
                for (LightFeature& l : frame_.features) kept.push_back(std::move(l.tiles));
            tiles_->draw_lights(f, frame_.cull, q, stats, frame_.priced ? &kept : nullptr);
            return;
        }
        FrameDef sub = f;
        sub.lights.clear();
        TileDepth depth;
        if (frame_.cull) depth.tiles = frame_.cull->tiles;
        for (size_t i = 0; i < f.lights.size(); ++i)
            if (frame_.plan.path[i] == LightPath::tiles) {
                sub.lights.push_back(f.lights[i]);
                kept.push_back(std::move(frame_.features[i].tiles));
                if (frame_.cull) depth.lights.push_back(frame_.cull->lights[i]);
            }
        tiles_->draw_lights(sub, frame_.cull ? &depth : nullptr, q, stats, frame_.priced ? &kept : nullptr);
    }

    // The quads in batches, a shadowed light's alone through the light program's shadow form.
    void draw_quads(const FrameDef& f, const std::vector<const LightDraw*>& lights, LightQueries& q, FrameStats& stats) {
        std::vector<const LightDraw*> batched;
        batched.reserve(lights.size());
        for (const LightDraw* l : lights)
            if (l->shadow < 0) batched.push_back(l);
        quads_.draw(f, batched, q, stats, frame_.quads_test_depth);
        stats.auto_geometry.quad_depth = frame_.quads_test_depth && !batched.empty();
        if (batched.size() == lights.size()) return;
        shadow_quads_.begin(f);
        for (const LightDraw* l : lights)
            if (l->shadow >= 0) {
                shadow_quads_.draw(f, *l, q);
                ++stats.lights.passes;
            }
    }

    // The drawers.
    LightQuadBatch quads_;
    LightQuads shadow_quads_;  // the quad path's shadowed lights, one by one
    LightMeshes meshes_;
    LightPrograms volume_progs_;
    LightVolumeBatch volume_batch_;  // its point lights' meshes in batches
    std::unique_ptr<TilesPass> tiles_;
    // The model and what the frames measured of it.
    LightCostModel model_;
    LightCostCalibration calib_;
    // What the paths allow.
    bool volumes_ok_;             // the paths give P-buffer 0 the scene's depth (the hand-off)
    bool handoff_takes_ambient_;  // the hand-off's pass writes the ambient term (Paths::ambient_in_handoff)
    bool quads_may_test_depth_;   // and the light shaders reject surfaces outside a light's depth span: so may GL
    AutoPolicy policy_;
    PathTimer timer_;
    KeptPrices kept_;
    AutoFrame frame_;
};

}  // namespace

std::unique_ptr<LightGeometryPass> make_auto_geometry(const ShaderConfig& c, ProgramSet& programs, int width,
                                                      int height) {
    return std::make_unique<AutoGeometry>(c, programs, width, height);
}

}  // namespace dsr
