// pDeferredShader: buffers (Listing 6), shader table, and the frame (Appendix A).
#include "deferred/deferred_shader.h"

#include <algorithm>

#include "deferred/gpu_scene.h"
#include "deferred/tile_plan.h"
#include "dsr_clock.h"
#include "dsr_error.h"
#include "forward/transparent_pass.h"
#include "gl/check.h"
#include "gl/readback.h"
#include "gl/rounding_probe.h"

namespace dsr {

DeferredShader::DeferredShader(const Caps& caps, int width, int height, const ShaderOptions& opts,
                               const std::string& shader_dir)
    : caps_(caps), w_(width), h_(height), opts_(opts), shader_dir_(shader_dir) {
    // Each capability decides one path (choose_paths; info and --stats name them).
    paths_ = choose_paths(caps, opts);
    if (!paths_.refused.empty()) throw Error(paths_.refused);
    opts_.depth = paths_.depth_path;
    opts_.tile_size = paths_.tile_size, opts_.tile_lights = paths_.tile_lights;  // auto resolved
    const int bs = opts.post.bloom_scale;
    if (bs != 2 && bs != 4) throw Error("bloom scale must be 2 or 4, got " + std::to_string(bs));
    if (opts.post.bloom_taps < 3 || opts.post.bloom_taps > 15 || opts.post.bloom_taps % 2 == 0)
        throw Error("bloom kernel must be odd, 3..15 taps, got " + std::to_string(opts.post.bloom_taps));
    targets_ = std::make_unique<RenderTargets>(paths_, opts_, width, height);

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
            if (paths_.mrt) {
                material_progs_[MaterialKey{nm == 1, ns == 1, -1}] =
                    Program(shader_dir, "material.vert", "material.frag", defs);
            } else {  // §3.2: without MRT, one pass per G-buffer target
                for (int t = 0; t < paths_.gbuffer_targets; ++t) {
                    auto d = defs;
                    d.push_back("TARGET_" + std::to_string(t));
                    material_progs_[MaterialKey{nm == 1, ns == 1, t}] =
                        Program(shader_dir, "material.vert", "material.frag", d);
                }
            }
        }
    auto ldefs = depth_defs;
    if (opts.listing2_literal) ldefs.push_back("LISTING2_LITERAL");
    if (opts.skip.light_depth_test) ldefs.push_back("LIGHT_DEPTH_TEST");
    if (opts.skip.light_sphere_test) ldefs.push_back("LIGHT_SPHERE_TEST");
    light_any_prog_ = Program(shader_dir, "light.vert", "light.frag", ldefs);
    ldefs.push_back("LIGHT_POINT_ONLY");
    light_prog_ = Program(shader_dir, "light.vert", "light.frag", ldefs);
    ldefs.pop_back();  // the geometries' programs shade any light type
    // Light geometries (issue 12): each builds only the programs it draws with.
    const LightGeometry lg = paths_.light_geometry;
    if (lg == LightGeometry::volume || lg == LightGeometry::stencil) {
        auto vdefs = ldefs;
        vdefs.push_back("VOLUME");
        light_volume_prog_ = Program(shader_dir, "light.vert", "light.frag", vdefs);
        if (lg == LightGeometry::stencil) {
            // Behind the stencil test the in-shader rejections are redundant (the stencil marks
            // surfaces inside the volume) and harmful: a shader that may discard, in a pass that
            // writes the stencil (zeroing it for the next light), makes the GPU test the stencil
            // after the shader instead of before it (the H200 ran the shader for 2.40x the ideal
            // count with them). Without them a pixel just outside the sphere adds att = 0.
            std::vector<std::string> sdefs;
            for (const std::string& d : vdefs)
                if (d != "LIGHT_DEPTH_TEST" && d != "LIGHT_SPHERE_TEST") sdefs.push_back(d);
            light_stencil_prog_ = Program(shader_dir, "light.vert", "light.frag", sdefs);
        }
        build_volume_mesh();
    }
    if (lg == LightGeometry::tiles) {
        auto tdefs = ldefs;
        tdefs.push_back("MAX_LIGHTS " + std::to_string(opts_.tile_lights));
        if (opts.tile_plan == TileGrouping::lists)  // groups: the light count is a uniform instead
            tdefs.push_back("ID_VECS " + std::to_string(tile_id_vecs(opts_.tile_lights)));
        // The batch the uniform arrays hold: five vec4s a light within the fragment stage's
        // uniform budget (GL 2.0 guarantees 64 vec4s; llvmpipe and NVIDIA give 1024), a few vec4s
        // kept for the other uniforms, and below tile_plan's empty-slot index 255.
        GLint comps = 0;
        glGetIntegerv(GL_MAX_FRAGMENT_UNIFORM_COMPONENTS, &comps);
        tile_batch_ = opts.tile_plan == TileGrouping::groups ? opts_.tile_lights : std::clamp((comps / 4 - 8) / 5, 1, 128);
        tdefs.push_back("BATCH " + std::to_string(tile_batch_));
        // P-buffer 0 is RGBA8: several lights summed in one pass are each rounded as their own
        // pass would be. One light a pass needs no emulation: the blend rounds it as quad's does.
        if (!opts.float_accum && opts_.tile_lights > 1) {
            tdefs.push_back("QUANTIZE_8BIT");
            // Rounded as this GL rounds into RGBA8, measured once (gl/rounding_probe.h): llvmpipe
            // rounds t x 255 to nearest, an exact tie to even; the H200 truncates t to 12 bits
            // first, which rounds up later than the half by as much as 0.06 of a step, and over the
            // dozens of lights a pixel of 1024-overlap gets the difference reached 16 LSB.
            if (paths_.fbo) {
                const Unorm8Rounding& r = unorm8_rounding();
                const int bits = unorm8_truncate_bits(r);
                if (bits > 0) tdefs.push_back("QUANTIZE_TRUNCATE " + std::to_string(1 << bits) + ".0");
                if (bits == 0) tdefs.push_back("QUANTIZE_TIES_EVEN");  // the model that fits (predicted_threshold)
                if (bits < 0) tile_round_ = unorm8_round_offset(r);  // the fallback's quantize_round
            }
        }
        light_tiles_any_prog_ = Program(shader_dir, "light.vert", "light_tiles.frag", tdefs);
        tdefs.push_back("LIGHT_POINT_ONLY");  // frames of tutorial point lights only, as quad's light_prog_
        light_tiles_prog_ = Program(shader_dir, "light.vert", "light_tiles.frag", tdefs);
        make_tile_depth_buf();  // and its program (tile_depth.cpp)
    }
    if (opts.ssao.on) build_ssao_programs();
    build_depth_handoff();
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
    timer_.set_source(choose_timing(caps, width, height).source);
    check_gl("creating the deferred shader");
}

void DeferredShader::resize(int width, int height) {
    if (width == w_ && height == h_) return;
    targets_->resize(width, height);
    w_ = width;
    h_ = height;
    position_buf_.reset();  // rebuilt at the new size on next use
    if (tile_depth_buf_) make_tile_depth_buf();
    check_gl("resizing the deferred buffers");
}

DeferredShader::~DeferredShader() = default;

std::vector<std::string> DeferredShader::depth_defines() const {
    if (opts_.depth == DepthPath::position16) return {"POSITION_TARGET", "POSITION16"};
    if (opts_.depth == DepthPath::position32) return {"POSITION_TARGET"};
    if (opts_.depth != DepthPath::packed) return {};
    std::vector<std::string> d = {"PACKED_DEPTH"};
    if (opts_.encoding == DepthEncoding::literal) d.push_back("ENC_LITERAL");
    if (opts_.encoding == DepthEncoding::linear) d.push_back("ENC_LINEAR");
    if (opts_.encoding == DepthEncoding::log) d.push_back("ENC_LOG");
    return d;
}

void DeferredShader::build_depth_handoff() {
    if (paths_.accum_depth && paths_.depth_handoff == DepthHandoff::pass && !depth_copy_prog_.id())
        depth_copy_prog_ = Program(shader_dir_, "post.vert", "depth_copy.frag", depth_defines());
}

void DeferredShader::set_scene(const Scene& scene) {
    gpu_ = std::make_unique<GpuScene>(scene, !caps_.npot);
    bounds_ = object_bounds(scene);
    // Transparent materials (issue 13) are drawn by the forward stage, which needs the scene's
    // depth in P-buffer 0: where the options did not foresee them (RenderOptions::resolved does),
    // the paths are chosen again and the buffers reallocated; no other shader is rebuilt.
    if (!gpu_->transparent_objects().empty()) {
        if (!opts_.forward_surfaces) {
            opts_.forward_surfaces = true;
            const bool had_depth = paths_.accum_depth;
            paths_ = choose_paths(caps_, opts_);
            if (!paths_.refused.empty()) throw Error(paths_.refused);
            if (!had_depth) targets_ = std::make_unique<RenderTargets>(paths_, opts_, w_, h_);
            build_depth_handoff();
        }
        if (!transparent_) transparent_ = std::make_unique<TransparentPass>(shader_dir_, opts_.listing2_literal);
    }
}

// --- Listing 6 -------------------------------------------------------------------------
void DeferredShader::mrt_bind_render() { gbuf().bind_render(); }
void DeferredShader::mrt_unbind_render() { gbuf().unbind_render(); }
void DeferredShader::mrt_bind_texture(int target, int unit) { gbuf().bind_texture(target, unit); }
void DeferredShader::mrt_unbind_texture(int target, int unit) { gbuf().unbind_texture(target, unit); }
void DeferredShader::fb_bind_render(int b) { pbuf(b).bind_render(); }
void DeferredShader::fb_unbind_render(int b) { pbuf(b).unbind_render(); }
void DeferredShader::fb_bind_texture(int b, int unit) { pbuf(b).bind_texture(0, unit); }
void DeferredShader::fb_unbind_texture(int b, int unit) { pbuf(b).unbind_texture(0, unit); }

void DeferredShader::set_ortho(int w, int h) {
    // Image-space stages use an orthographic camera in pixels (§3.1, Listing 14 lines 5-9).
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

glm::vec3 DeferredShader::view_ray_at(float x, float y) const {
    const float u = x / float(w_), v = y / float(h_);
    return (1 - v) * ((1 - u) * corner_rays_[0] + u * corner_rays_[1]) +
           v * ((1 - u) * corner_rays_[3] + u * corner_rays_[2]);
}

glm::vec4 DeferredShader::ray_map() const {
    const glm::vec3 lo = corner_rays_[0], hi = corner_rays_[2];
    return glm::vec4((hi.x - lo.x) / float(w_), (hi.y - lo.y) / float(h_), lo.x, lo.y);
}

glm::vec2 DeferredShader::gbuffer_uv_scale() const {
    return glm::vec2(gbuf().tex_scale_x() / float(w_), gbuf().tex_scale_y() / float(h_));
}

void DeferredShader::draw_rect(float x0, float y0, float x1, float y1, bool rays) {
    const float xs[4] = {x0, x1, x1, x0}, ys[4] = {y0, y0, y1, y1};
    // The G-buffer's content may be padded to powers of two: scale into its extent.
    const glm::vec2 uv = gbuffer_uv_scale();
    const float sx = uv.x, sy = uv.y;
    glBegin(GL_QUADS);
    for (int i = 0; i < 4; ++i) {
        glMultiTexCoord2f(GL_TEXTURE0, xs[i] * sx, ys[i] * sy);
        if (rays) {
            // The view ray is affine in window coordinates: bilinear in the screen's corner rays
            // (exactly the corner's ray at a screen corner; a tile's corner otherwise).
            const glm::vec3 r = view_ray_at(xs[i], ys[i]);
            glMultiTexCoord3f(GL_TEXTURE1, r.x, r.y, r.z);
        }
        glVertex2f(xs[i], ys[i]);
    }
    glEnd();
}

FrameStats DeferredShader::render(const Scene& scene, int out_w, int out_h) {
    if (!gpu_) throw Error("DeferredShader::render before set_scene");
    FrameStats st;
    const double cpu0 = thread_cpu_ms();
    timer_.begin_frame(S_COUNT);
    timer_.begin(S_GEOMETRY);
    geometry_stage(scene);
    timer_.end();
    draw_lights(scene, opts_.scissor, st);  // times S_AMBIENT and S_LIGHTS
    post_stage(st);                          // times S_BLOOM and S_AA
    timer_.begin(S_FINAL);
    final_stage(out_w, out_h);
    timer_.end();
    std::vector<double> ms;
    st.ms.cpu = thread_cpu_ms() - cpu0;
    st.ms.frame = timer_.end_frame(ms);
    st.ms.geometry = ms[S_GEOMETRY];
    st.ms.ambient = ms[S_AMBIENT];
    st.ms.lights = ms[S_LIGHTS];
    st.ms.bloom = ms[S_BLOOM];
    st.ms.aa = ms[S_AA];
    st.ms.final = ms[S_FINAL];
    st.ms.depth_copy = ms[S_DEPTH_COPY];
    st.ms.ssao = ms[S_SSAO];
    st.ms.forward = ms[S_FORWARD];
    st.timing = timer_.source();
    check_gl("frame");  // per stage too with --debug-gl (check_gl_stage)
    return st;
}

// --- read-back ---------------------------------------------------------------------------
Image DeferredShader::read_gbuffer(int target) {
    return read_texture(gbuf().texture(target), w_, h_, gbuf().texture_width(), gbuf().texture_height(),
                        target == PBuffer::DEPTH);
}

std::vector<uint32_t> DeferredShader::read_gbuffer_depth_codes() {
    if (opts_.depth != DepthPath::texture) throw Error(std::string("read_gbuffer_depth_codes: the ") + depth_path_name(opts_.depth) +
                                                  " path has no depth texture");
    return read_depth_codes(gbuf().texture(PBuffer::DEPTH), w_, h_, gbuf().texture_width(), gbuf().texture_height());
}

Image DeferredShader::read_pbuffer(int fb) {
    const PBuffer& b = pbuf(fb);
    return read_texture(b.texture(0), b.width(), b.height(), b.texture_width(), b.texture_height(), false);
}

}  // namespace dsr
