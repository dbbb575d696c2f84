// Debug views of every buffer (STYLE lesson 7), drawn into the main frame buffer by the
// final stage's fixed-function pass: the G-buffer targets of Figure 4, the blur factor of
// Figure 8, the bloom blur of Figure 10.
#include "deferred/depth_codec.h"
#include "deferred/reconstruct.h"
#include "deferred/deferred_shader.h"
#include "dsr_error.h"
#include "gl/check.h"
#include "gl/readback.h"
#include "gl/state.h"

namespace dsr {

void DeferredShader::draw_view(View view, int out_w, int out_h) {
    switch (view) {
        case View::final:
            final_stage(out_w, out_h);
            return;
        case View::normal:
        case View::diffuse:
        case View::specular: {
            int t = view == View::normal ? G_NORMAL : view == View::diffuse ? G_DIFFUSE : G_SPECULAR;
            draw_texture_to_main(gbuf().texture(t), out_w, out_h, {gbuf().tex_scale_x(), gbuf().tex_scale_y()});
            return;
        }
        case View::depth: {
            if (opts_.depth == DepthPath::packed) {
                draw_texture_to_main(gbuf().texture(G_DEPTH_PACKED), out_w, out_h,
                                     {gbuf().tex_scale_x(), gbuf().tex_scale_y()});
                return;
            }
            // The depth texture, encoded with the packed path's codec so every path shows the
            // same picture (Figure 4d); on the position paths the stored eye z mapped to window
            // depth first, as the depth hand-off does (§3.4.3).
            const bool position = is_position_path(opts_.depth);
            Image d = read_gbuffer(position ? G_POSITION : PBuffer::DEPTH);
            for (size_t i = 0; i < d.rgba.size(); i += 4) {
                const float z = d.rgba[i + 2];
                const float depth = position ? glm::clamp((planes_.x * z + planes_.y) / -z, 0.0f, 1.0f) : d.rgba[i];
                glm::vec3 c = pack_depth(depth);
                d.rgba[i] = c.r, d.rgba[i + 1] = c.g, d.rgba[i + 2] = c.b, d.rgba[i + 3] = 1.0f;
            }
            // Same extent as the G-buffer's textures (padded on the pow2 path).
            Texture tex(gbuf().texture_width(), gbuf().texture_height(), GL_RGBA8, GL_RGBA, GL_FLOAT, nullptr);
            glBindTexture(GL_TEXTURE_2D, tex.id());
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, d.width, d.height, GL_RGBA, GL_FLOAT, d.rgba.data());
            glBindTexture(GL_TEXTURE_2D, 0);
            draw_texture_to_main(tex.id(), out_w, out_h, {gbuf().tex_scale_x(), gbuf().tex_scale_y()});
            return;
        }
        case View::blur_factor:
            draw_anti_alias(true);  // factor into P-buffer 1, no swap
            draw_texture_to_main(pbuf(P_AA).texture(0), out_w, out_h, {pbuf(P_AA).tex_scale_x(), pbuf(P_AA).tex_scale_y()});
            return;
        case View::bloom:
            if (!blur_prog_[0].id()) throw Error("the bloom view needs bloom enabled");
            draw_texture_to_main(pbuf(P_BLOOM_V).texture(0), out_w, out_h,
                                 {pbuf(P_BLOOM_V).tex_scale_x(), pbuf(P_BLOOM_V).tex_scale_y()});
            return;
        case View::ssao: {  // the blurred AO buffer the ambient pass multiplies by (issue 13)
            if (!opts_.ssao.on) throw Error("the ssao view needs --ssao");
            const PBuffer& ao = targets_->ssao(SSAO_BLURRED);
            draw_texture_to_main(ao.texture(0), out_w, out_h, {ao.tex_scale_x(), ao.tex_scale_y()});
            return;
        }
    }
    check_gl("view");
}

}  // namespace dsr

namespace dsr {

Image DeferredShader::reconstructed_positions() {
    if (!caps_.fbo || !caps_.texture_float)
        throw Error("position read-back needs EXT_framebuffer_object and ARB_texture_float");
    if (!position_buf_) {
        PBufferDesc d;
        d.width = w_;
        d.height = h_;
        d.color_formats = {GL_RGBA32F_ARB};
        d.pow2 = !caps_.npot;
        position_buf_ = std::make_unique<PBuffer>("position read-back", d);
        std::vector<std::string> defs = depth_defines();
        defs.push_back("OUTPUT_POSITION");
        position_prog_ = Program(shader_dir_, "light.vert", "light.frag", defs);
    }
    const auto rays = corner_rays(proj_[0][0], proj_[1][1]);
    for (int i = 0; i < 4; ++i) corner_rays_[i] = rays[i];
    position_buf_->bind_render();
    set_ortho(w_, h_);
    RenderState s = fixed_function_2d();  // the light shader's arithmetic, written, not blended
    s.program = position_prog_.id();
    gl_state().apply(s);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    set_light_uniforms(position_prog_);  // light.frag's: samplers, planes, uv_scale and ray_map
    mrt_bind_texture(G_NORMAL, 0);
    mrt_bind_texture(depth_target(), 3);
    draw_rect(0, 0, float(w_), float(h_), true);
    mrt_unbind_texture(depth_target(), 3);
    mrt_unbind_texture(G_NORMAL, 0);
    position_buf_->unbind_render();
    check_gl("position read-back");
    const PBuffer& pb = *position_buf_;
    return read_texture(pb.texture(0), w_, h_, pb.texture_width(), pb.texture_height(), false);
}

}  // namespace dsr
