// Light geometry `tiles` (§3.4.3: the light pass "can be used to create more complex shaders which
// could process multiple lights per pass"): the screen is cut into tile_size x tile_size tiles, each
// tile lists the lights whose scissor rectangle (Listing 16) overlaps it, and light_tiles.frag reads
// a tile's G-buffer once and loops over up to tile_lights of them, summing their light and blending
// once. The plan (tile_plan.h, pure) batches the work: a batch of lights sits in the shader's
// uniform arrays, and one draw per batch and layer covers every tile with lights in that layer,
// each quad's vertices carrying its lights' indices (two per float, in texture coordinates 2..5).
// With --tile-depth on, each tile's span of surface depth (tile_depth.cpp: a small pass read back,
// a stall on a GPU) drops the tile's lights whose sphere misses its surfaces.
#include <algorithm>

#include "deferred/deferred_shader.h"
#include "dsr_clock.h"
#include "deferred/light_queries.h"
#include "deferred/tile_plan.h"
#include "gl/state.h"

namespace dsr {

namespace {

constexpr float kNoLight = 255.0f;  // an empty slot; batch indices stay below it

// A tile quad's vertex, as floats: window position (2), then id_vecs vec4s of packed light slots
// (pairs: slot[2j] * 256 + slot[2j + 1]) in texture coordinates 2... The shader takes the G-buffer
// coordinates and the view ray from gl_FragCoord (the ray as light.frag does).
constexpr int kFixedFloats = 2;

}  // namespace

void DeferredShader::draw_lights_tiles(const std::vector<LightDraw>& lights, FrameStats& stats) {
    std::vector<ScissorRect> rects(lights.size());
    for (size_t i = 0; i < lights.size(); ++i) rects[i] = lights[i].rect;
    const bool groups = opts_.tile_plan == TileGrouping::groups;
    // Depth culling (tile_depth.cpp): most of a tile's rectangle-overlapping lights lie in front of
    // or behind all of its surfaces (1024-overlap at 256x256: 6.6M tile-pixel-light pairs from the
    // rectangles, 0.6M pixel-light pairs inside a sphere).
    TileDepth depth;
    const double t0 = now_ms();
    const std::vector<DepthSpan> spans = opts_.tile_depth ? tile_depth_spans() : std::vector<DepthSpan>{};
    const double t1 = now_ms();
    stats.tile_depth_ms = t1 - t0;
    const TileDepth* cull = spans.empty() ? nullptr : &depth;
    if (cull) {
        const int ts = opts_.tile_size, tx = (w_ + ts - 1) / ts;
        const glm::vec4 rays = ray_map();  // light.frag's
        // position16 stores x and y as half floats, up to 2^-11 off the ray, relative: two such steps.
        const float slack = opts_.depth == DepthPath::position16 ? 1.0f / 1024.0f : 0.0f;
        for (size_t t = 0; t < spans.size(); ++t) {
            const int x = int(t) % tx, y = int(t) / tx;
            depth.tiles.push_back(tile_box(spans[t], float(x * ts), float(y * ts), float(std::min(w_, (x + 1) * ts)),
                                           float(std::min(h_, (y + 1) * ts)), rays, slack));
        }
        depth.lights.resize(lights.size());
        for (size_t i = 0; i < lights.size(); ++i) {
            const LightParams& p = lights[i].params;
            if (p.color.w < 1.5f) depth.lights[i] = LightBound{glm::vec3(p.pos), p.pos.w};  // directional: unbounded
        }
    }
    stats.tile_depth = cull != nullptr;

    // The tutorial's cheaper point-light shader where every light of the frame allows it (as quad
    // picks per light): the general one evaluates every type's terms for every light.
    const bool point_only = std::all_of(lights.begin(), lights.end(), [](const LightDraw& l) { return tutorial_light(*l.light); });
    Program& prog = point_only ? light_tiles_prog_ : light_tiles_any_prog_;
    set_light_uniforms(prog);
    prog.set("quantize_round", tile_round_);  // ignored (optimised away) without QUANTIZE_8BIT
    gl_state().apply(light_pass_state(prog.id(), false));
    LightQueries q(counting_ && paths_.count_fragments, counting_ && caps_.pipeline_statistics);
    const int id_vecs = groups ? 0 : tile_id_vecs(opts_.tile_lights);
    const int stride = kFixedFloats + 4 * id_vecs;
    glEnableClientState(GL_VERTEX_ARRAY);
    for (int k = 0; k < id_vecs; ++k) {
        glClientActiveTexture(GLenum(GL_TEXTURE2 + k));
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    }
    std::vector<glm::vec4> pos, color, dir, spot, att;
    double plan_ms = now_ms() - t1;  // the tile boxes; then each batch's plan, vertices and upload

    // One batch: its lights into the uniform arrays, its draws' vertices into the stream buffer
    // (uploaded once for the batch; each draw points at its own range), one draw per layer.
    int uploads = 0;
    auto draw_batch = [&](const std::vector<int>& batch, const TileDraw* draws, size_t n_draws) {
        const double t = now_ms();
        size_t quads = 0;
        for (size_t di = 0; di < n_draws; ++di) quads += draws[di].quads.size();
        // A member, so its storage is reused: a fresh multi-megabyte vector each frame cost page
        // faults (at 1920x1080 on llvmpipe, building these vertices took 1.5-2.9 ms a frame that way).
        std::vector<float>& verts = tile_verts_;
        verts.resize(quads * 4 * size_t(stride));
        std::vector<size_t> first(n_draws + 1, 0);
        float* out = verts.data();
        for (size_t di = 0; di < n_draws; ++di) {
            for (const TileQuad& tq : draws[di].quads) {
                float ids[16];
                auto slot = [&](size_t k) { return k < tq.slots.size() ? float(tq.slots[k]) : kNoLight; };
                for (int j = 0; j < 4 * id_vecs; ++j) ids[j] = slot(2 * size_t(j)) * 256.0f + slot(2 * size_t(j) + 1);
                const float xs[4] = {float(tq.x0), float(tq.x1), float(tq.x1), float(tq.x0)};
                const float ys[4] = {float(tq.y0), float(tq.y0), float(tq.y1), float(tq.y1)};
                for (int c = 0; c < 4; ++c) {
                    *out++ = xs[c], *out++ = ys[c];
                    out = std::copy(ids, ids + 4 * id_vecs, out);
                }
            }
            first[di + 1] = size_t(out - verts.data()) / size_t(stride);
        }
        // A buffer object per batch of the frame: refilling the one the previous batch's draws
        // still read made llvmpipe finish them first (the plan's time went from 0.4 to 3 ms).
        if (size_t(uploads) == tile_vertices_.size()) tile_vertices_.push_back(std::make_unique<StreamBuffer>());
        tile_vertices_[size_t(uploads++)]->upload(verts.data(), verts.size() * sizeof(float));
        plan_ms += now_ms() - t;
        const GLsizei bytes = GLsizei(stride * sizeof(float));
        auto at = [](int f) { return reinterpret_cast<const void*>(size_t(f) * sizeof(float)); };  // buffer offsets
        glVertexPointer(2, GL_FLOAT, bytes, at(0));
        for (int k = 0; k < id_vecs; ++k) {
            glClientActiveTexture(GLenum(GL_TEXTURE2 + k));
            glTexCoordPointer(4, GL_FLOAT, bytes, at(kFixedFloats + 4 * k));
        }
        pos.clear(), color.clear(), dir.clear(), spot.clear(), att.clear();
        for (int l : batch) {  // lighting.glsl's five vec4s per light, one uniform array each
            const LightParams& p = lights[size_t(l)].params;
            pos.push_back(p.pos), color.push_back(p.color), dir.push_back(p.dir);
            spot.push_back(p.spot), att.push_back(p.att);
        }
        const int count = int(batch.size());
        prog.set_array("lightpos", pos.data(), count);
        prog.set_array("lightcolor", color.data(), count);
        prog.set_array("lightdir", dir.data(), count);
        prog.set_array("lightspot", spot.data(), count);
        prog.set_array("lightatt", att.data(), count);
        if (groups) prog.set("light_count", count);
        for (size_t di = 0; di < n_draws; ++di) {
            q.begin();
            glDrawArrays(GL_QUADS, GLint(first[di]), GLsizei(first[di + 1] - first[di]));
            q.end();
        }
        stats.light_passes += int(n_draws);
    };

    stats.light_passes = 0;
    stats.tile_light_pairs = 0;
    if (groups) {
        const double t = now_ms();
        const TilePlan plan = plan_tile_groups(rects, w_, h_, opts_.tile_size, opts_.tile_lights, cull);
        plan_ms += now_ms() - t;
        for (const TileDraw& d : plan.draws) draw_batch(plan.batches[size_t(d.batch)], &d, 1);
        stats.tile_light_pairs = plan.tile_light_pairs;
    } else {
        // Batch by batch (tile_plan.h TilePlanner): the GL shades a batch while the CPU plans the
        // next; the flush after each hands the batch over instead of holding it until the buffer fills.
        double t = now_ms();
        TilePlanner planner(rects, w_, h_, opts_.tile_size, opts_.tile_lights, tile_batch_, cull);
        std::vector<TileDraw> draws;
        for (int b = 0; b < int(planner.batches().size()); ++b) {
            if (b) t = now_ms();
            draws.clear();
            stats.tile_light_pairs += planner.plan_batch(b, draws);
            plan_ms += now_ms() - t;
            draw_batch(planner.batches()[size_t(b)], draws.data(), draws.size());
            glFlush();
        }
    }
    for (int k = id_vecs - 1; k >= 0; --k) {
        glClientActiveTexture(GLenum(GL_TEXTURE2 + k));
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    }
    glClientActiveTexture(GL_TEXTURE0);
    glDisableClientState(GL_VERTEX_ARRAY);
    StreamBuffer::unbind();
    q.collect(stats);
    stats.tile_plan_ms = plan_ms;
}

}  // namespace dsr
