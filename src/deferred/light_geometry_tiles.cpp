// Light geometry `tiles` (§3.4.3: the light pass "can be used to create more complex shaders which
// could process multiple lights per pass"): the screen is cut into tile_size x tile_size tiles,
// each tile lists the lights whose scissor rectangle (Listing 16) overlaps it, and one quad per
// tile and group of up to tile_lights lights runs light_tiles.frag, which reads the tile's
// G-buffer once and loops over the group (uniform arrays, a constant loop bound). The group's
// light is summed in the shader and blended once, so each pixel's G-buffer is read and its
// accumulation blended once per group instead of once per light.
// The tile's depth range is not used: on GL 2.x it needs a reduction pass read back to the CPU
// (a stall) or another pass per tile; the in-shader depth and sphere tests reject instead.
#include <algorithm>

#include "deferred/deferred_shader.h"
#include "deferred/light_queries.h"
#include "gl/state.h"

namespace dsr {

void DeferredShader::draw_lights_tiles(const std::vector<LightDraw>& lights, FrameStats& stats) {
    const int ts = opts_.tile_size, n = opts_.tile_lights;
    const int tx = (w_ + ts - 1) / ts, ty = (h_ + ts - 1) / ts;
    // Bin: each light into the tiles its rectangle overlaps.
    std::vector<std::vector<int>> bins(size_t(tx) * ty);
    for (int i = 0; i < int(lights.size()); ++i) {
        const ScissorRect& r = lights[i].rect;
        for (int y = r.y0 / ts; y <= (r.y1 - 1) / ts && y < ty; ++y)
            for (int x = r.x0 / ts; x <= (r.x1 - 1) / ts && x < tx; ++x) bins[size_t(y) * tx + x].push_back(i);
    }
    set_light_uniforms(light_tiles_prog_);
    gl_state().apply(light_pass_state(light_tiles_prog_.id(), false));
    LightQueries q(paths_.count_fragments, caps_.pipeline_statistics);
    // lighting.glsl's five vec4s per light, one uniform array each (light_params.h).
    const size_t slots = size_t(n);
    std::vector<glm::vec4> pos(slots), color(slots), dir(slots), spot(slots), att(slots);
    int passes = 0;
    for (int y = 0; y < ty; ++y)
        for (int x = 0; x < tx; ++x) {
            const std::vector<int>& bin = bins[size_t(y) * tx + x];
            for (size_t g = 0; g < bin.size(); g += size_t(n)) {
                const int count = int(std::min(bin.size() - g, size_t(n)));
                for (int k = 0; k < count; ++k) {
                    const LightParams& p = lights[size_t(bin[g + k])].params;
                    pos[size_t(k)] = p.pos;
                    color[size_t(k)] = p.color;
                    dir[size_t(k)] = p.dir;
                    spot[size_t(k)] = p.spot;
                    att[size_t(k)] = p.att;
                }
                light_tiles_prog_.set_array("lightpos", pos.data(), count);
                light_tiles_prog_.set_array("lightcolor", color.data(), count);
                light_tiles_prog_.set_array("lightdir", dir.data(), count);
                light_tiles_prog_.set_array("lightspot", spot.data(), count);
                light_tiles_prog_.set_array("lightatt", att.data(), count);
                light_tiles_prog_.set("light_count", count);
                q.begin();
                draw_rect(float(x * ts), float(y * ts), float(std::min(w_, (x + 1) * ts)),
                          float(std::min(h_, (y + 1) * ts)), true);
                q.end();
                ++passes;
            }
        }
    q.collect(stats);
    stats.light_passes = passes;
}

}  // namespace dsr
