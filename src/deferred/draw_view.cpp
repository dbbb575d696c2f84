// Debug views of every buffer, with the same names everywhere (`--view`, the viewer's keys),
// drawn into the main frame buffer by the final stage's fixed-function pass: the G-buffer targets
// of Figure 4, the blur factor of Figure 8, the bloom blur of Figure 10, the SSAO buffer, a shadow map.
#include "deferred/deferred_shader.h"
#include "deferred/depth_codec.h"
#include "deferred/geometry_stage.h"
#include "deferred/post_stage.h"
#include "deferred/shadow_stage.h"
#include "dsr_error.h"
#include "gl/check.h"
#include "gl/texture.h"

namespace dsr {

void DeferredShader::draw_view(View view, const Camera& camera, int out_w, int out_h) {
    const PBuffer& g = targets_->gbuffer();
    const glm::vec2 g_extent = targets_->gbuffer_extent();
    auto show = [&](const PBuffer& b) {
        final_.draw_texture(b.texture(0), out_w, out_h, {b.tex_scale_x(), b.tex_scale_y()});
    };
    switch (view) {
        case View::final:
            final_stage(out_w, out_h);
            return;
        case View::normal:
        case View::diffuse:
        case View::specular: {
            const int t = view == View::normal ? G_NORMAL : view == View::diffuse ? G_DIFFUSE : G_SPECULAR;
            // A target whose clear the frame left out shows, at the background, what an earlier
            // frame's surfaces left there: the G-buffer drawn again with every clear, the same
            // values elsewhere (the view is not timed).
            if (!gbuffer_clears_.all() && t != G_NORMAL && gpu_) {
                FrameStats st;
                geometry_->draw(frame_of(camera), *gpu_, *targets_, st);
                gbuffer_clears_ = GbufferClears{};
            }
            final_.draw_texture(g.texture(t), out_w, out_h, g_extent);
            return;
        }
        case View::depth: {
            const DepthPath depth = config_.opts.depth;
            if (depth == DepthPath::packed) {
                final_.draw_texture(g.texture(G_DEPTH_PACKED), out_w, out_h, g_extent);
                return;
            }
            // The depth texture, encoded with the packed path's codec so every path shows the
            // same picture (Figure 4d); on the position paths the stored eye z mapped to window
            // depth first, as the depth hand-off does (§3.4.3).
            const bool position = is_position_path(depth);
            const glm::vec2 planes = frame_of(camera).planes;
            Image d = read_gbuffer(position ? G_POSITION : PBuffer::DEPTH);
            for (size_t i = 0; i < d.rgba.size(); i += 4) {
                const float z = d.rgba[i + 2];
                const float w = position ? glm::clamp((planes.x * z + planes.y) / -z, 0.0f, 1.0f) : d.rgba[i];
                const glm::vec3 c = pack_depth(w);
                d.rgba[i] = c.r, d.rgba[i + 1] = c.g, d.rgba[i + 2] = c.b, d.rgba[i + 3] = 1.0f;
            }
            // Same extent as the G-buffer's textures (padded on the pow2 path).
            Texture tex(g.texture_width(), g.texture_height(), GL_RGBA8, GL_RGBA, GL_FLOAT, nullptr);
            glBindTexture(GL_TEXTURE_2D, tex.id());
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, d.width, d.height, GL_RGBA, GL_FLOAT, d.rgba.data());
            glBindTexture(GL_TEXTURE_2D, 0);
            final_.draw_texture(tex.id(), out_w, out_h, g_extent);
            return;
        }
        case View::blur_factor:
            draw_anti_alias(camera, true);  // factor into P-buffer 1, no swap
            show(targets_->pbuffer(P_AA));
            return;
        case View::bloom:
            if (!post_->bloom()) throw Error("the bloom view needs bloom enabled");
            show(targets_->pbuffer(P_BLOOM_V));
            return;
        case View::shadow_map: {  // the first shadowed light's map, depth as grey (white: far)
            const ShadowLookup* m = shadows_ ? shadows_->last_first() : nullptr;
            if (!m) throw Error("the shadow-map view needs a visible light with `shadow` (and --shadows on)");
            const Image d = shadows_->read_map(*m);
            Texture tex(d.width, d.height, GL_RGBA8, GL_RGBA, GL_FLOAT, d.rgba.data());
            final_.draw_texture(tex.id(), out_w, out_h, glm::vec2(1, 1));
            return;
        }
        case View::ssao:  // the blurred AO buffer the ambient pass multiplies by (docs/ssao.md)
            if (!config_.opts.ssao.on) throw Error("the ssao view needs --ssao");
            show(targets_->ssao(SSAO_BLURRED));
            return;
    }
    check_gl("view");
}

}  // namespace dsr
