// pDeferredShader: buffers (Listing 6), shader table, and the frame (Appendix A).
#include "dsr_clock.h"
#include "deferred/deferred_shader.h"

#include <algorithm>

#include "deferred/gpu_scene.h"
#include "dsr_error.h"
#include "gl/check.h"

namespace dsr {

DeferredShader::DeferredShader(const Caps& caps, int width, int height, const ShaderOptions& opts,
                               const std::string& shader_dir)
    : caps_(caps), w_(width), h_(height), opts_(opts), shader_dir_(shader_dir) {
    if (!caps.glsl120)
        throw Error("GLSL 1.20 is required and this GL offers " +
                    (caps.glsl_version.empty() ? std::string("none") : caps.glsl_version) + " (GL " + caps.version + ")");
    if (opts.float_accum && !(caps.texture_float && caps.fbo))
        throw Error("float accumulation needs ARB_texture_float and EXT_framebuffer_object");
    if (opts.depth == DepthPath::texture && !caps.depth_texture)
        throw Error("--depth texture needs ARB_depth_texture, which is missing (use --depth packed)");

    // Each capability decides one path (info and --stats name them).
    const int targets = opts.depth == DepthPath::packed ? 4 : 3;
    mrt_path_ = caps.fbo && caps.draw_buffers && caps.max_draw_buffers >= targets;
    paths_.depth = opts.depth == DepthPath::texture ? "texture" : "packed";
    paths_.gbuffer = mrt_path_ ? "mrt" : "per-target";
    paths_.render_target = caps.fbo ? "fbo" : "copy";
    paths_.textures = caps.npot ? "npot" : "pow2";

    // Figure 3: normal, diffuse, specular+shininess, and packed depth only when that path runs.
    PBufferDesc g;
    g.width = width;
    g.height = height;
    g.use_fbo = caps.fbo;
    g.pow2 = !caps.npot;
    if (opts.gbuffer_half && !(caps.half_float && caps.texture_float))
        throw Error("half-float G-buffer targets need ARB_texture_float and ARB_half_float_pixel");
    // EXT_framebuffer_object wants one format for every colour attachment, so the half-float
    // option makes all targets half; the packed depth keeps its byte codes (exact in half).
    const GLenum gfmt = opts.gbuffer_half ? GLenum(GL_RGBA16F_ARB) : GLenum(GL_RGBA8);
    g.color_formats = {gfmt, gfmt, gfmt};
    if (opts.depth == DepthPath::packed) {
        g.color_formats.push_back(gfmt);
        g.depth = DepthAttachment::renderbuffer;
    } else {
        g.depth = DepthAttachment::texture;
    }
    mrt_ = std::make_unique<PBuffer>("G-buffer", g);
    // P-buffers 0-3 (§3.2): 0 accumulates lighting, 1 is the anti-alias swap partner,
    // 2 and 3 hold the bloom blurs. Bilinear, so the final pass can scale (§3.6).
    const int bs = opts.post.bloom_scale;
    if (bs != 2 && bs != 4) throw Error("bloom scale must be 2 or 4, got " + std::to_string(bs));
    if (opts.post.bloom_taps < 3 || opts.post.bloom_taps > 15 || opts.post.bloom_taps % 2 == 0)
        throw Error("bloom kernel must be odd, 3..15 taps, got " + std::to_string(opts.post.bloom_taps));
    for (int i = 0; i < 4; ++i) {
        PBufferDesc p;
        p.width = i < 2 ? width : std::max(1, width / bs);   // 2 and 3: reduced (§3.5.2)
        p.height = i < 2 ? height : std::max(1, height / bs);
        // P-buffers 0 and 1 in float for stress runs, so NaN and Inf survive to be counted.
        p.color_formats = {opts.float_accum && i < 2 ? GLenum(GL_RGBA32F_ARB) : GLenum(GL_RGBA8)};
        p.filter = GL_LINEAR;
        p.use_fbo = caps.fbo;
        p.pow2 = !caps.npot;
        fb_[i] = std::make_unique<PBuffer>("P-buffer " + std::to_string(i), p);
    }

    // Shader table: every program this configuration uses is compiled now (STYLE lesson 5).
    const std::vector<std::string> depth_defs = depth_defines();
    // Material variants: [normal map][no specular]. Without the skip, every material takes the
    // full shader (normal map and specular map read), as a single-shader renderer would.
    for (int nm = 0; nm < 2; ++nm)
        for (int ns = 0; ns < 2; ++ns) {
            if (!opts.skip.material_variants && (nm == 0 || ns == 1)) continue;
            auto defs = depth_defs;
            if (nm) defs.push_back("NORMAL_MAP");
            if (ns) defs.push_back("NO_SPECULAR");
            if (mrt_path_) {
                material_prog_[nm][ns][0] = Program(shader_dir, "material.vert", "material.frag", defs);
            } else {  // §3.2: without MRT, one pass per G-buffer target
                for (int t = 0; t < targets; ++t) {
                    auto d = defs;
                    d.push_back("TARGET_" + std::to_string(t));
                    material_prog_[nm][ns][1 + t] = Program(shader_dir, "material.vert", "material.frag", d);
                }
            }
        }
    auto ldefs = depth_defs;
    if (opts.listing2_literal) ldefs.push_back("LISTING2_LITERAL");
    if (opts.skip.light_depth_test) ldefs.push_back("LIGHT_DEPTH_TEST");
    if (opts.skip.light_sphere_test) ldefs.push_back("LIGHT_SPHERE_TEST");
    light_prog_ = Program(shader_dir, "light.vert", "light.frag", ldefs);
    // Post programs are built only when their pass can run (the post stage costs nothing off).
    const PostOptions& p = opts.post;
    if (p.bloom) {
        for (int sel = 0; sel < 2; ++sel) {
            std::vector<std::string> d = {"NUMPOINTS " + std::to_string(p.bloom_taps)};
            if (p.bloom_listing) d.push_back("LISTING");
            else if (sel) d.push_back("SELECT");
            blur_prog_[sel] = Program(shader_dir, "post.vert", "blur.frag", d);
        }
    }
    for (int fo = 0; fo < 2; ++fo) {
        auto d = depth_defs;
        if (p.aa_source != AaSource::depth) d.push_back("SOURCE_NORMAL");
        if (p.aa_source != AaSource::normal) d.push_back("SOURCE_DEPTH");
        if (p.aa_kernel == AaKernel::listing) d.push_back("LISTING_KERNEL");
        if (fo) d.push_back("FACTOR_ONLY");
        aa_prog_[fo] = Program(shader_dir, "post.vert", "anti_alias.frag", d);
    }
    check_gl("creating the deferred shader");
}

DeferredShader::~DeferredShader() = default;

std::vector<std::string> DeferredShader::depth_defines() const {
    if (opts_.depth != DepthPath::packed) return {};
    std::vector<std::string> d = {"PACKED_DEPTH"};
    if (opts_.encoding == DepthEncoding::literal) d.push_back("ENC_LITERAL");
    if (opts_.encoding == DepthEncoding::linear) d.push_back("ENC_LINEAR");
    if (opts_.encoding == DepthEncoding::log) d.push_back("ENC_LOG");
    return d;
}

void DeferredShader::set_scene(const Scene& scene) { gpu_ = std::make_unique<GpuScene>(scene, !caps_.npot); }

// --- Listing 6 -------------------------------------------------------------------------
void DeferredShader::mrt_bind_render() { mrt_->bind_render(); }
void DeferredShader::mrt_unbind_render() { mrt_->unbind_render(); }
void DeferredShader::mrt_bind_texture(int target, int unit) { mrt_->bind_texture(target, unit); }
void DeferredShader::mrt_unbind_texture(int target, int unit) { mrt_->unbind_texture(target, unit); }
void DeferredShader::fb_bind_render(int b) { fb_[b]->bind_render(); }
void DeferredShader::fb_unbind_render(int b) { fb_[b]->unbind_render(); }
void DeferredShader::fb_bind_texture(int b, int unit) { fb_[b]->bind_texture(0, unit); }
void DeferredShader::fb_unbind_texture(int b, int unit) { fb_[b]->unbind_texture(0, unit); }

void DeferredShader::set_ortho(int w, int h) {
    // Image-space stages use an orthographic camera in pixels (§3.1, Listing 14 lines 5-9).
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

void DeferredShader::draw_rect(float x0, float y0, float x1, float y1, bool rays) {
    const float xs[4] = {x0, x1, x1, x0}, ys[4] = {y0, y0, y1, y1};
    // The G-buffer's content may be padded to powers of two: scale into its extent.
    const float sx = mrt_->tex_scale_x() / float(w_), sy = mrt_->tex_scale_y() / float(h_);
    glBegin(GL_QUADS);
    for (int i = 0; i < 4; ++i) {
        glMultiTexCoord2f(GL_TEXTURE0, xs[i] * sx, ys[i] * sy);
        if (rays) glMultiTexCoord3f(GL_TEXTURE1, corner_rays_[i].x, corner_rays_[i].y, corner_rays_[i].z);
        glVertex2f(xs[i], ys[i]);
    }
    glEnd();
}

FrameStats DeferredShader::render(const Scene& scene, int out_w, int out_h) {
    if (!gpu_) throw Error("DeferredShader::render before set_scene");
    FrameStats st;
    double t0 = now_ms();
    geometry_stage(scene);
    glFinish();
    double t1 = now_ms();
    st.ms.geometry = t1 - t0;
    draw_lights(scene, opts_.scissor, st);  // fills ms.ambient and ms.lights
    post_stage(st);                          // fills ms.bloom and ms.aa
    double t2 = now_ms();
    final_stage(out_w, out_h);
    glFinish();
    double t3 = now_ms();
    st.ms.final = t3 - t2;
    st.ms.frame = t3 - t0;
    check_gl("frame");
    return st;
}

// --- read-back ---------------------------------------------------------------------------
// The w x h content of a texture of tw x th (larger when padded to powers of two).
static Image read_texture(GLuint tex, int w, int h, int tw, int th, bool depth) {
    Image img;
    img.width = w;
    img.height = h;
    img.rgba.assign(size_t(w) * h * 4, 1.0f);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    std::vector<float> all(size_t(tw) * th * (depth ? 1 : 4));
    glGetTexImage(GL_TEXTURE_2D, 0, depth ? GL_DEPTH_COMPONENT : GL_RGBA, GL_FLOAT, all.data());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* q = img.at(x, y);
            if (depth) {
                q[0] = q[1] = q[2] = all[size_t(y) * tw + x];
            } else {
                const float* p = &all[(size_t(y) * tw + x) * 4];
                for (int c = 0; c < 4; ++c) q[c] = p[c];
            }
        }
    glBindTexture(GL_TEXTURE_2D, 0);
    check_gl("reading a buffer back");
    return img;
}

Image DeferredShader::read_gbuffer(int target) {
    return read_texture(mrt_->texture(target), w_, h_, mrt_->texture_width(), mrt_->texture_height(),
                        target == PBuffer::DEPTH);
}

Image DeferredShader::read_pbuffer(int fb) {
    const PBuffer& b = *fb_[fb];
    return read_texture(b.texture(0), b.width(), b.height(), b.texture_width(), b.texture_height(), false);
}

}  // namespace dsr
