// Light geometry `tiles` (§3.4.3: the light pass "can be used to create more complex shaders which
// could process multiple lights per pass"): the screen is cut into tile_size x tile_size tiles, each
// tile lists the lights whose scissor rectangle (Listing 16) overlaps it, and light_tiles.frag reads
// a tile's G-buffer once and loops over up to tile_lights of them, summing their light and blending
// once. The plan (tile_plan.h, pure) batches the work: a batch of lights sits in the shader's
// uniform arrays, and one draw per batch and layer covers every tile with lights in that layer,
// each quad's vertices carrying its lights' indices (two per float, in texture coordinates 2..5).
// With --tile-depth on, each tile's span of surface depth (tile_depth.h: a small pass read back,
// a stall on a GPU) drops the tile's lights whose sphere misses its surfaces.
// Shadowed lights: a batch holds up to ShaderConfig::shadow_slots of them (the plan cuts it where
// one more would enter), their maps copied into the batch's atlas on unit 4 (or, without framebuffer
// objects, bound on units 4..) for its draws (ShadowSlots) and each light's slot in lightspot.z,
// drawn by the program's shadow form (light_tiles.frag SHADOW; SHADOW_ATLAS for the atlas).
// A frame is: cull (the depth spans and the tiles' boxes), then per batch plan, upload and draw.
// A batch of point lights with the attenuation law that all have the same constants (LearnOpenGL's
// lights do) is drawn by the form that reads them once, as a uniform (light_tiles.frag
// ATT_SHARED): a CPU rasteriser reads an array at an index from the vertices lane by lane, so the
// shared form is the faster there (docs/light_loop_cpu.md, "Smaller choices in the shaders").
// With the vertex fetch (Paths::tile_fetch_vertex, --tile-fetch), a batch of point lights of the
// linear law or of one attenuation is drawn by light_tiles_flat.vert/.frag instead: a tile's
// vertices carry its slots one a float, the vertex shader reads its lights out of the arrays once
// and the fragment shader takes them flat, by programs built for each count of lights (a tile's
// draws are split by count: the terms are written out in a row, none masked off).
#include <algorithm>
#include <array>
#include <optional>

#include "deferred/light_geometry_tiles.h"
#include "deferred/light_pass.h"
#include "deferred/main_buffer_map.h"
#include "deferred/tile_depth.h"
#include "dsr_clock.h"
#include "gl/stream_buffer.h"

namespace dsr {

namespace {

constexpr float kNoLight = 255.0f;  // an empty slot; batch indices stay below it

// A tile quad's vertex, as floats: window position (2), then id_vecs vec4s of packed light slots
// (pairs: slot[2j] * 256 + slot[2j + 1]), or with the vertex fetch flat_vecs vec4s of slots one a
// float, in texture coordinates 2... The shader takes the G-buffer
// coordinates and the view ray from gl_FragCoord (the ray as light.frag does).
constexpr int kFixedFloats = 2;

// A run of a batch's uploaded vertices that one glDrawArrays takes (TilesGeometry::upload): lights,
// with the vertex fetch, the count of lights its program takes (0: the batch's one program);
// mean_lights, the lights its fragments evaluate, their lists' lengths weighted by pixels
// (LightQueries::begin; the groups' draws evaluate the group instead).
struct TileRange {
    GLenum mode;
    size_t first, count;
    int lights;
    double mean_lights;
};

// Wall-clock milliseconds of f(): the tiles' two wall timings (TileStats::depth_ms, plan_ms).
template <class F>
double wall_ms(F&& f) {
    const double t = now_ms();
    f();
    return now_ms() - t;
}

// The rendering thread's CPU milliseconds in f(): the tiles' steps (TileStats::*_cpu_ms).
template <class F>
double cpu_ms(F&& f) {
    const double t = thread_cpu_ms();
    f();
    return thread_cpu_ms() - t;
}

class TilesGeometry final : public TilesPass {
public:
    TilesGeometry(const ShaderConfig& c, ProgramSet& programs, int width, int height)
        : sources_(programs.sources("light_tiles")),
          progs_(programs, "light_tiles", false, c.shadow_slots),
          shadow_slots_(c.shadow_slots),
          shadows_(shadow_maps_packed(c.caps)),
          tile_size_(c.opts.tile_size),
          tile_lights_(c.opts.tile_lights),
          batch_(c.tile_batch),
          groups_(c.opts.tile_plan == TileGrouping::groups),
          points_(c.paths.tile_points),
          id_vecs_(groups_ ? 0 : tile_id_vecs(c.opts.tile_lights)),
          stride_(kFixedFloats + 4 * id_vecs_),
          vertex_fetch_(c.paths.tile_fetch_vertex && !groups_),
          flat_vecs_(vertex_fetch_ ? (c.opts.tile_lights + 3) / 4 : 0),
          flat_stride_(kFixedFloats + 4 * flat_vecs_),
          xy_slack_(c.opts.depth == DepthPath::position16 ? 1.0f / 1024.0f : 0.0f),
          round_(c.tile_round),
          timeline_(gpu_timestamps(c.caps)) {
        if (tile_depth_culling(c)) depth_ = std::make_unique<TileDepthPass>(c, programs, width, height);
        if (vertex_fetch_) {
            flat_sources_ = std::make_unique<ProgramSources>(programs.sources("light_tiles_flat"));
            flat_[0][size_t(tile_lights_)] = programs.take("light_tiles_flat_point");
            flat_[1][size_t(tile_lights_)] = programs.take("light_tiles_flat_point_inverse");
        }
    }

    void resize(int width, int height) override {
        if (depth_) depth_->resize(width, height);
    }

    bool own_pass(size_t) const override { return false; }  // one more light in the tiles' batches

    // The depth spans, read back here (before the ambient pass: prepare_reads_back) for draw().
    bool prepare(const FrameDef& f, RenderTargets& targets, FrameStats& stats) override {
        spans_ = depth_spans(f, targets, stats);
        prepared_ = true;
        return LightGeometryPass::prepare(f, targets, stats);
    }

    bool prepare_reads_back(const FrameDef&) const override { return depth_culling(); }

    void draw(const FrameDef& f, RenderTargets& targets, LightQueries& q, FrameStats& stats) override {
        // The spans depend on the G-buffer alone, not on f's lights: prepare()'s, or measured now.
        const std::vector<DepthSpan> spans = prepared_ ? std::move(spans_) : depth_spans(f, targets, stats);
        prepared_ = false;
        TileDepth depth;
        const TileDepth* cull = nullptr;
        stats.tiles.plan_ms += wall_ms([&] { stats.tiles.cull_cpu_ms += cpu_ms([&] { cull = tile_boxes(f, spans, depth); }); });
        draw_lights(f, cull, q, stats, nullptr);
    }

    bool depth_culling() const override { return depth_ != nullptr; }
    int tile_size() const override { return tile_size_; }
    int lights_per_pass() const override { return tile_lights_; }

    std::vector<DepthSpan> depth_spans(const FrameDef& f, RenderTargets& targets, FrameStats& stats) override {
        // The spans' passes draw into buffers of their own: P-buffer 0 unbound around them (it
        // keeps its contents: the spans need framebuffer objects).
        std::vector<DepthSpan> spans;
        if (!depth_) return spans;
        const double waited = stats.tiles.wait_cpu_ms;
        const double cpu = cpu_ms([&] {
            stats.tiles.depth_ms += wall_ms([&] {
                targets.fb_unbind_render(P_ACCUM);
                timeline_.mark(TileTimeline::spans_begin);
                spans = depth_->spans(f, targets.gbuffer(), &timeline_, &stats.tiles);
                targets.fb_bind_render(P_ACCUM);
            });
        });
        stats.tiles.spans_cpu_ms += cpu - (stats.tiles.wait_cpu_ms - waited);  // the wait apart
        return spans;
    }

    // Depth culling: most of a tile's rectangle-overlapping lights lie in front of or behind all of
    // its surfaces (1024-overlap at 256x256: 6.6M tile-pixel-light pairs from the rectangles, 0.6M
    // pixel-light pairs inside a sphere). Null without spans.
    const TileDepth* tile_boxes(const FrameDef& f, const std::vector<DepthSpan>& spans, TileDepth& depth) const override {
        if (spans.empty()) return nullptr;
        const int ts = tile_size_, tx = (f.width + ts - 1) / ts;
        for (size_t t = 0; t < spans.size(); ++t) {
            const int x = int(t) % tx, y = int(t) / tx;
            depth.tiles.push_back(tile_box(spans[t], float(x * ts), float(y * ts), float(std::min(f.width, (x + 1) * ts)),
                                           float(std::min(f.height, (y + 1) * ts)), f.ray_map, xy_slack_));
        }
        depth.lights.resize(f.lights.size());
        for (size_t i = 0; i < f.lights.size(); ++i) {
            const LightParams& p = f.lights[i].params;
            if (p.color.w < 1.5f) depth.lights[i] = LightBound{glm::vec3(p.pos), p.pos.w};  // directional: unbounded
        }
        return &depth;
    }

    void draw_lights(const FrameDef& f, const TileDepth* cull, LightQueries& q, FrameStats& stats,
                     const std::vector<std::vector<int>>* kept) override {
        double plan_ms = 0;
        stats.tiles.depth = cull != nullptr;
        shadows_.begin_frame();
        std::vector<ScissorRect> rects(f.lights.size());
        for (size_t i = 0; i < f.lights.size(); ++i) rects[i] = f.lights[i].rect;

        // The shadowed lights, for the plans' cuts (none: the plans as without shadows).
        std::vector<bool> shadowed;
        if (f.shadowed_lights > 0 && shadow_slots_ > 0)
            for (const LightDraw& l : f.lights) shadowed.push_back(l.shadow >= 0);
        const std::vector<bool>* cut = shadowed.empty() ? nullptr : &shadowed;

        begin_draws(f);
        buffers_.begin_frame();
        stats.tiles.light_pairs = 0;
        if (groups_) {
            TilePlan plan;
            plan_ms += wall_ms([&] {
                stats.tiles.plan_cpu_ms += cpu_ms(
                    [&] { plan = plan_tile_groups(rects, f.width, f.height, tile_size_, tile_lights_, cull, cut, shadow_slots_); });
            });
            for (const TileDraw& d : plan.draws) {
                plan_ms += wall_ms([&] { stats.tiles.upload_cpu_ms += cpu_ms([&] { upload(&d, 1, false); }); });
                if (&d == &plan.draws.front()) timeline_.mark(TileTimeline::draws_begin);
                draw_batch(f, plan.batches[size_t(d.batch)], q, stats);
            }
            stats.tiles.light_pairs = plan.tile_light_pairs;
        } else {
            // Batch by batch (tile_plan.h TilePlanner): the GL shades a batch while the CPU plans the
            // next; the flush after each hands the batch over instead of holding it until the
            // buffer fills.
            // Each light's tiles culled once, apart from the plan (or as auto culled them to price
            // them), so that the planner only lists and merges.
            std::vector<std::vector<int>> own_kept;
            if (!kept)
                plan_ms += wall_ms([&] {
                    stats.tiles.cull_cpu_ms +=
                        cpu_ms([&] { own_kept = tiles_kept(rects, f.width, f.height, tile_size_, cull); });
                });
            std::unique_ptr<TilePlanner> planner;
            plan_ms += wall_ms([&] {
                stats.tiles.plan_cpu_ms += cpu_ms([&] {
                    planner = std::make_unique<TilePlanner>(rects, f.width, f.height, tile_size_, tile_lights_, batch_, nullptr,
                                                            kept ? kept : &own_kept, cut, shadow_slots_);
                });
            });
            for (int b = 0; b < int(planner->batches().size()); ++b) {
                const std::vector<int>& batch = planner->batches()[size_t(b)];
                const FlatForm flat = flat_form(f, batch);
                plan_ms += wall_ms([&] {
                    draws_.clear();
                    stats.tiles.plan_cpu_ms += cpu_ms([&] { stats.tiles.light_pairs += planner->plan_batch(b, draws_); });
                    stats.tiles.upload_cpu_ms += cpu_ms([&] { upload(draws_.data(), draws_.size(), flat.form >= 0); });
                });
                if (b == 0) timeline_.mark(TileTimeline::draws_begin);
                if (flat.form >= 0)
                    draw_flat(f, batch, flat, q, stats);
                else
                    draw_batch(f, batch, q, stats);
                glFlush();
            }
        }
        end_draws();
        timeline_.mark(TileTimeline::draws_end);
        timeline_.end_frame(stats.tiles);
        stats.tiles.plan_ms += plan_ms;
    }

private:
    // The programs' frame uniforms, the pixel camera and client arrays for the draws. Each batch
    // is drawn by the form of the light program its lights allow (LightPrograms::common): the
    // general one evaluates every type's terms for every light.
    void begin_draws(const FrameDef& f) {
        gl_state().set_camera(f.pixels());
        progs_.begin(f);
        for (LightShader k : {LightShader::point_linear, LightShader::point_inverse, LightShader::any}) {
            progs_[k].use();
            progs_[k].set("quantize_round", round_);  // ignored (optimised away) without QUANTIZE_8BIT
        }
        for (Program* p : {&progs_.shadow(), &progs_.shadow_atlas()})
            if (p->id()) {
                p->use();
                p->set("quantize_round", round_);
            }
        if (att_shared_.id()) begin_att_shared(f);
        for (auto& form : flat_)
            for (Program& p : form)
                if (p.id()) begin_flat(p, f);
        glEnableClientState(GL_VERTEX_ARRAY);
    }

    // The uploaded batch's vertex arrays in its buffer: vertices of `stride` floats, the window
    // position, then `vecs` vec4s in texture coordinates 2..; the arrays past those off, so that
    // none left on by a batch of the other layout reads past this batch's buffer.
    void vertex_arrays(int stride, int vecs) const {
        const GLsizei bytes = GLsizei(stride * sizeof(float));
        auto at = [](int fl) { return reinterpret_cast<const void*>(size_t(fl) * sizeof(float)); };  // buffer offsets
        glVertexPointer(2, GL_FLOAT, bytes, at(0));
        for (int k = 0; k < std::max(id_vecs_, flat_vecs_); ++k) {
            glClientActiveTexture(GLenum(GL_TEXTURE2 + k));
            if (k < vecs) {
                glEnableClientState(GL_TEXTURE_COORD_ARRAY);
                glTexCoordPointer(4, GL_FLOAT, bytes, at(kFixedFloats + 4 * k));
            } else {
                glDisableClientState(GL_TEXTURE_COORD_ARRAY);
            }
        }
    }

    void end_draws() {
        for (int k = std::max(id_vecs_, flat_vecs_) - 1; k >= 0; --k) {
            glClientActiveTexture(GLenum(GL_TEXTURE2 + k));
            glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        }
        glClientActiveTexture(GL_TEXTURE0);
        glDisableClientState(GL_VERTEX_ARRAY);
        StreamBuffer::unbind();
    }

    // A batch's draws as vertices into a buffer object of its own (StreamBuffers), left bound, and
    // ranges_, the runs of vertices each glDrawArrays takes, in draw order: within a draw, quads
    // (four vertices each), then, with points_, one vertex a whole tile at its centre (a quad the
    // plan merged from several tiles gives a point for each; a partial tile at the frame's edge
    // stays a quad, as a point with its centre outside the viewport would be clipped whole). With
    // the vertex fetch (flat) the slots go one a float and a draw's tiles are split by their count
    // of lights, a program each; else two a float (hi * 256 + lo), all in one range of each shape.
    void upload(const TileDraw* draws, size_t n_draws, bool flat) {
        const int stride = flat ? flat_stride_ : stride_;
        const int n_ids = 4 * (flat ? flat_vecs_ : id_vecs_);
        begin_vertices(draws, n_draws, stride);
        ranges_.clear();
        float* out = verts_.data();
        const int counts = flat ? tile_lights_ + 1 : 1;  // runs by count of lights (flat), else one
        for (size_t di = 0; di < n_draws; ++di) {
            // The draw's quads in run order, (count, quads before points), each run in plan order:
            // one pass to bucket them, not one scan of the draw per run (up to 2 x 32).
            run_first_.assign(size_t(2 * counts) + 1, 0);
            auto run_of = [&](const TileQuad& tq) { return 2 * (flat ? int(tq.slots.size()) : 0) + int(whole(tq)); };
            for (const TileQuad& tq : draws[di].quads) ++run_first_[size_t(run_of(tq)) + 1];
            for (size_t r = 1; r < run_first_.size(); ++r) run_first_[r] += run_first_[r - 1];
            order_.resize(draws[di].quads.size());
            run_next_.assign(run_first_.begin(), run_first_.end() - 1);
            for (size_t q = 0; q < draws[di].quads.size(); ++q) order_[size_t(run_next_[size_t(run_of(draws[di].quads[q]))]++)] = q;
            for (int run = flat ? 2 : 0; run < 2 * counts; ++run) {  // (flat: a tile has a light at least)
                const size_t first = vertex_at(out, stride);
                double pixels = 0, pairs = 0;
                for (int k = run_first_[size_t(run)]; k < run_first_[size_t(run) + 1]; ++k) {
                    const TileQuad& tq = draws[di].quads[order_[size_t(k)]];
                    const double area = double(tq.x1 - tq.x0) * double(tq.y1 - tq.y0);
                    pixels += area;
                    pairs += area * double(tq.slots.size());
                    float ids[16];
                    auto slot = [&](size_t j) { return j < tq.slots.size() ? float(tq.slots[j]) : kNoLight; };
                    for (int j = 0; j < n_ids; ++j)
                        ids[j] = flat ? slot(size_t(j)) : slot(2 * size_t(j)) * 256.0f + slot(2 * size_t(j) + 1);
                    out = emit_tile(tq, ids, n_ids, out);
                }
                const size_t end = vertex_at(out, stride);
                if (end > first)
                    ranges_.push_back({run % 2 == 1 ? GLenum(GL_POINTS) : GLenum(GL_QUADS), first, end - first, run / 2,
                                       pixels > 0 ? pairs / pixels : 0.0});
            }
        }
        buffers_.upload_next(verts_.data(), verts_.size() * sizeof(float));
    }

    // Whether a tile quad is drawn as points, one a tile: with points_, where it is whole tiles.
    bool whole(const TileQuad& tq) const {
        return points_ && (tq.x1 - tq.x0) % tile_size_ == 0 && (tq.y1 - tq.y0) % tile_size_ == 0;
    }

    // verts_ sized for the draws' vertices of `stride` floats. A member, so its storage is reused:
    // a fresh multi-megabyte vector each frame costs page faults (docs/tiles.md, "The plan").
    void begin_vertices(const TileDraw* draws, size_t n_draws, int stride) {
        const int ts = tile_size_;
        size_t verts = 0;
        for (size_t di = 0; di < n_draws; ++di)
            for (const TileQuad& tq : draws[di].quads)
                verts += whole(tq) ? size_t((tq.x1 - tq.x0) / ts) * size_t((tq.y1 - tq.y0) / ts) : 4;
        verts_.resize(verts * size_t(stride));
    }

    size_t vertex_at(const float* out, int stride) const { return size_t(out - verts_.data()) / size_t(stride); }

    // Tile quad tq's vertices at out, each its window position then the n floats `ids`: a point
    // at the centre of each of its tiles (whole()), else its four corners. Returns the end.
    float* emit_tile(const TileQuad& tq, const float* ids, int n, float* out) const {
        auto emit = [&](float x, float y) {
            *out++ = x, *out++ = y;
            out = std::copy(ids, ids + n, out);
        };
        const int ts = tile_size_;
        if (whole(tq)) {
            for (int y = tq.y0; y < tq.y1; y += ts)
                for (int x = tq.x0; x < tq.x1; x += ts) emit(float(x) + 0.5f * float(ts), float(y) + 0.5f * float(ts));
            return out;
        }
        const float xs[4] = {float(tq.x0), float(tq.x1), float(tq.x1), float(tq.x0)};
        const float ys[4] = {float(tq.y0), float(tq.y0), float(tq.y1), float(tq.y1)};
        for (int c = 0; c < 4; ++c) emit(xs[c], ys[c]);
        return out;
    }

    // The uploaded draws: the batch's lights into the uniform arrays (lighting.glsl's five vec4s
    // per light, one array each), then each uploaded range, quads and points of each layer.
    void draw_batch(const FrameDef& f, const std::vector<int>& batch, LightQueries& q, FrameStats& stats) {
        // A batch with shadow maps: each light's slot among them in lightspot.z (-1: none).
        const BatchForm form = load_batch_form(f, batch, arrays_, shadows_, progs_, stats,
                                               [&]() -> Program& { return att_shared_program(f); });
        Program& prog = form.prog;
        RenderState state = light_pass_state(prog.id(), false);
        if (points_) state.point_size = float(tile_size_);
        gl_state().apply(state);
        vertex_arrays(stride_, id_vecs_);
        arrays_.set(prog, LightArrays::kLight);
        form.set_shared();
        shadows_.set(prog);
        if (groups_) prog.set("light_count", arrays_.size());
        for (const TileRange& r : ranges_) draw_range(r, groups_ ? double(arrays_.size()) : r.mean_lights, q, stats);
        shadows_.unbind();
    }

    // The vertex fetch's form for a batch: 0 for point lights of the linear law, 1 for point lights
    // of the attenuation law that share its constants (att, shared_attenuation); -1
    // (light_tiles.frag draws it): no vertex fetch, another kind of light or law, differing
    // constants, or a shadowed light.
    struct FlatForm {
        int form = -1;
        std::optional<glm::vec3> att;
    };
    FlatForm flat_form(const FrameDef& f, const std::vector<int>& batch) const {
        if (!vertex_fetch_ || batch.empty()) return {};
        for (int i : batch)
            if (f.lights[size_t(i)].shadow >= 0) return {};
        const LightShader s = LightPrograms::common(f, batch);
        if (s == LightShader::point_linear) return {0, std::nullopt};
        if (s != LightShader::point_inverse) return {};
        const std::optional<glm::vec3> att = shared_attenuation(f, batch);
        return att ? FlatForm{1, att} : FlatForm{};
    }

    // The uploaded ranges, each by the form's program for its count of lights, the batch's lights
    // in its arrays (position and colour are all it reads; att_shared for the attenuation law).
    void draw_flat(const FrameDef& f, const std::vector<int>& batch, const FlatForm& form, LightQueries& q,
                   FrameStats& stats) {
        arrays_.clear();
        for (int i : batch) arrays_.add(f.lights[size_t(i)].params);
        if (form.att) ++stats.tiles.att_shared_batches;
        ++stats.tiles.vertex_batches;
        vertex_arrays(flat_stride_, flat_vecs_);
        int bound = 0;
        for (const TileRange& r : ranges_) {
            if (r.lights != bound) {
                Program& prog = flat_program(f, form.form, r.lights);
                RenderState state = light_pass_state(prog.id(), false);
                if (points_) state.point_size = float(tile_size_);
                gl_state().apply(state);
                arrays_.set(prog, LightArrays::kLight);
                if (form.att) prog.set("att_shared", *form.att);
                bound = r.lights;
            }
            draw_range(r, double(r.lights), q, stats);
        }
    }

    // One range of the uploaded vertices, counted, each of its fragments evaluating `lights` lights.
    static void draw_range(const TileRange& r, double lights, LightQueries& q, FrameStats& stats) {
        q.begin(lights);
        glDrawArrays(r.mode, GLint(r.first), GLsizei(r.count));
        q.end();
        ++stats.lights.passes;
    }

    // The form's program for `lights` lights: the table's for tile_lights, the others built on
    // first use (their frame uniforms set then, and by begin_draws in the frames after).
    Program& flat_program(const FrameDef& f, int form, int lights) {
        Program& p = flat_[size_t(form)][size_t(lights)];
        if (!p.id()) {
            p = flat_sources_->build(form == 0 ? "light_tiles_flat_point" : "light_tiles_flat_point_inverse",
                                     Defines{"LIGHTS " + std::to_string(lights)});
            begin_flat(p, f);
        }
        return p;
    }

    void begin_flat(Program& p, const FrameDef& f) {
        set_light_uniforms(p, f);  // makes it current
        p.set("quantize_round", round_);
    }

    // The point-inverse form with ATT_SHARED, compiled on first use; begin_draws sets its frame
    // uniforms in the frames after, as the table's forms'.
    Program& att_shared_program(const FrameDef& f) {
        if (!att_shared_.id()) {
            att_shared_ = sources_.build("light_tiles_point_inverse", Defines{"ATT_SHARED"});
            begin_att_shared(f);
        }
        return att_shared_;
    }

    void begin_att_shared(const FrameDef& f) {
        set_light_uniforms(att_shared_, f);  // makes it current
        att_shared_.set("quantize_round", round_);
    }

    ProgramSources sources_;
    LightPrograms progs_;
    Program att_shared_;  // light_tiles_point_inverse with ATT_SHARED, once a batch needs it
    int shadow_slots_;  // shadowed lights a batch holds (0: the tiles get none)
    ShadowSlots shadows_;
    int tile_size_, tile_lights_, batch_;
    bool groups_;
    bool points_;  // Paths::tile_points: whole tiles as points of the tile's size
    int id_vecs_, stride_;
    bool vertex_fetch_;          // Paths::tile_fetch_vertex (lists only)
    int flat_vecs_, flat_stride_;  // its vertices: slots one a float, in flat_vecs_ vec4s
    float xy_slack_;  // position16 stores x and y as half floats, up to 2^-11 off the ray, relative: two such steps
    float round_;     // light_tiles.frag's quantize_round (gl/rounding_probe.h)
    TileTimeline timeline_;  // the GPU's stamps of the light stage (on a GPU with timer queries)
    std::unique_ptr<TileDepthPass> depth_;  // null without depth culling
    std::vector<DepthSpan> spans_;  // prepare()'s, for this frame's draw()
    bool prepared_ = false;
    // Kept between frames for their storage only.
    StreamBuffers buffers_;  // one per batch of a frame
    std::vector<float> verts_;
    std::vector<TileDraw> draws_;
    LightArrays arrays_;
    std::vector<TileRange> ranges_;  // upload()'s
    std::vector<int> run_first_, run_next_;  // upload()'s buckets: each run's first quad in order_
    std::vector<size_t> order_;
    // The vertex fetch's programs by form (linear, shared attenuation) and count of lights (index
    // 0 unused).
    std::unique_ptr<ProgramSources> flat_sources_;
    std::array<std::array<Program, SlotList::kCapacity + 1>, 2> flat_;
};

}  // namespace

std::unique_ptr<TilesPass> make_tiles_pass(const ShaderConfig& c, ProgramSet& programs, int width, int height) {
    return std::make_unique<TilesGeometry>(c, programs, width, height);
}

std::unique_ptr<LightGeometryPass> make_tiles_geometry(const ShaderConfig& c, ProgramSet& programs, int width,
                                                       int height) {
    return make_tiles_pass(c, programs, width, height);
}

}  // namespace dsr
