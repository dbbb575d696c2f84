// The G-buffer and the four P-buffers (§3.2, Listing 6), owned together so they can be
// reallocated on resize without touching a shader (bgfx 21-deferred: only size-dependent
// resources are rebuilt).
#pragma once
#include <memory>

#include <glm/glm.hpp>

#include "deferred/options.h"
#include "deferred/paths.h"
#include "gl/pbuffer.h"

namespace dsr {

// G-buffer targets (Figure 3); the position paths' eye-space position takes the packed depth's slot.
enum GTarget { G_NORMAL = 0, G_DIFFUSE = 1, G_SPECULAR = 2, G_DEPTH_PACKED = 3, G_POSITION = 3 };

// The G-buffer target the image-space passes read eye z or position from: the depth texture on the
// texture path, else the packed depth (or position) target.
inline int depth_target(DepthPath d) { return d == DepthPath::texture ? PBuffer::DEPTH : G_DEPTH_PACKED; }

// The GL internal format of a G-buffer target format (GL_RGBA8, GL_RGBA16F_ARB, GL_RGBA32F_ARB).
GLenum gl_format(TargetFormat f);
// The P-buffers' GL internal format for --accum (GL_RGBA8, GL_RGBA16F_ARB, GL_RGBA32F_ARB).
GLenum accum_gl_format(AccumFormat a);

// P-buffer roles (§3.2: "four P-buffers"); the values are the tutorial's buffer numbers.
enum PRole {
    P_ACCUM = 0,    // P-buffer 0: the ambient pass and every light add into it; the final pass reads it
    P_AA = 1,       // P-buffer 1: the anti-alias pass writes here, then swaps it with 0 (§3.5.1)
    P_BLOOM_H = 2,  // P-buffer 2: bloom's horizontal blur, at 1/bloom_scale size (§3.5.2)
    P_BLOOM_V = 3,  // P-buffer 3: bloom's vertical blur, added back to 0
};

// The ambient-occlusion buffers (docs/ssao.md), only with --ssao: at 1/ssao.scale of the frame.
enum SsaoBuffer { SSAO_RAW = 0, SSAO_BLURRED = 1 };

// The G-buffer's colour clears a frame needs (SkipOptions::gbuffer_clears). The normal target's and
// the packed depth's (or position's) are always made: every pass that tells the background from a
// surface reads one of them. The specular target's background is read only by the light shaders,
// which multiply it by the background's zero normal; the diffuse target's alpha by Listing 15's
// fixed-function ambient pass (ambient_writer.h ambient_pass_possible), its colour as the
// specular's. Without a clear a target keeps, at the background, a value a material pass wrote,
// finite: the first frame on new targets clears all (uninitialised half floats may hold NaN).
struct GbufferClears {
    bool diffuse = true, specular = true;
    bool all() const { return diffuse && specular; }
};

class RenderTargets {
public:
    // Needs a current context; the formats follow `paths` and `opts` (half-float G-buffer,
    // float accumulation, bloom scale).
    RenderTargets(const Paths& paths, const ShaderOptions& opts, int width, int height);
    // Reallocates every buffer at the new size (contents are lost).
    void resize(int width, int height);

    PBuffer& gbuffer() { return *g_; }
    const PBuffer& gbuffer() const { return *g_; }
    PBuffer& pbuffer(int role) { return *p_[role]; }
    const PBuffer& pbuffer(int role) const { return *p_[role]; }
    // The SSAO buffers; throws when --ssao is off (they are not allocated then).
    PBuffer& ssao(int which);
    // After the anti-alias pass: P-buffer 1 holds the result and becomes P-buffer 0.
    void swap_accumulation() { std::swap(p_[P_ACCUM], p_[P_AA]); }
    int width() const { return w_; }
    int height() const { return h_; }
    // The G-buffer's content extent in texture coordinates (below 1 where padded to powers of two).
    glm::vec2 gbuffer_extent() const { return {g_->tex_scale_x(), g_->tex_scale_y()}; }

    // Listing 6: the tutorial's names for binding them; mrt_ the G-buffer, fb_ P-buffer `b`.
    void mrt_bind_render() { g_->bind_render(); }
    void mrt_unbind_render() { g_->unbind_render(); }
    void mrt_bind_texture(int target, int unit) { g_->bind_texture(target, unit); }
    void mrt_unbind_texture(int target, int unit) { g_->unbind_texture(target, unit); }
    // Paths::ambient_target: P-buffer 0 as the G-buffer's render target after its own (index
    // gbuffer().color_targets()), attached (on) or detached by the material pass; whether this GL
    // takes it, checked at allocation with P-buffers 0 and 1 (the anti-alias pass swaps them).
    bool ambient_target() const { return ambient_target_; }
    void mrt_attach_accum(bool on) { g_->attach_extra(on ? p_[P_ACCUM]->texture(0) : 0); }
    // Whether this GL takes P-buffer 0 (and 1) as the G-buffer framebuffer's one more target, to
    // draw into alone (the emission pass, emission_pass.h): asked on first use, then kept.
    bool accum_attachable();
    void fb_bind_render(int b) { p_[b]->bind_render(); }
    void fb_unbind_render(int b) { p_[b]->unbind_render(); }
    void fb_bind_texture(int b, int unit) { p_[b]->bind_texture(0, unit); }
    void fb_unbind_texture(int b, int unit) { p_[b]->unbind_texture(0, unit); }

    // Whether a geometry stage has drawn into the G-buffer since it was allocated: until then its
    // targets hold uninitialised memory, which every clear must cover (GbufferClears).
    bool gbuffer_written() const { return gbuffer_written_; }
    void set_gbuffer_written() { gbuffer_written_ = true; }

private:
    void allocate();
    Paths paths_;
    ShaderOptions opts_;
    int w_, h_;
    std::unique_ptr<PBuffer> g_;
    std::unique_ptr<PBuffer> p_[4];
    std::unique_ptr<PBuffer> ao_[2];  // SsaoBuffer
    bool ambient_target_ = false;
    int accum_attachable_ = -1;  // unknown until asked
    bool gbuffer_written_ = false;
};

}  // namespace dsr
