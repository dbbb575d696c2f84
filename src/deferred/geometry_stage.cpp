// The geometry stage (geometry_stage.h).
#include "deferred/geometry_stage.h"

#include "deferred/depth_codec.h"
#include "dsr_error.h"
#include "gl/check.h"
#include "gl/texture.h"

namespace dsr {

namespace {
// The table's material rows by variant (shader_table.cpp).
const char* material_row(bool normal_map, bool no_specular) {
    return normal_map ? (no_specular ? "material_no_specular" : "material")
                      : (no_specular ? "material_flat_no_specular" : "material_flat");
}
}  // namespace

GeometryStage::GeometryStage(const ShaderConfig& c, ProgramSet& programs)
    : sources_(programs.sources("material")),
      mrt_(c.paths.mrt),
      variants_(c.opts.skip.material_variants),
      quantize_round_(c.tile_round),
      depth_(c.opts.depth),
      encoding_(c.opts.encoding),
      skip_prepass_(c.opts.skip.depth_prepass && c.paths.count_fragments) {
    if (skip_prepass_) glGenQueries(2, queries_);
    // The table's material rows by variant; without MRT one program per G-buffer target.
    for (const bool normal_map : {true, false})
        for (const bool no_specular : {false, true}) {
            const char* name = material_row(normal_map, no_specular);
            if (mrt_ && programs.has(name)) programs_[MaterialKey{normal_map, no_specular, -1}] = programs.take(name);
            for (int t = 0; !mrt_ && t < c.paths.gbuffer_targets; ++t) {
                const std::string n = std::string(name) + "/" + std::to_string(t);
                if (programs.has(n)) programs_[MaterialKey{normal_map, no_specular, t}] = programs.take(n);
            }
        }
}

GeometryStage::~GeometryStage() {
    if (queries_[0]) glDeleteQueries(2, queries_);
}

void GeometryStage::collect_counts() {
    if (pending_ == 0) return;
    GLuint n[2] = {0, 0};
    for (int i = 2 - pending_; i < 2; ++i) glGetQueryObjectuiv(queries_[i], GL_QUERY_RESULT, &n[i]);
    if (pending_ == 2) choice_.measured_with_prepass(n[0], n[1]);
    else choice_.measured_without(n[1]);
    pending_ = 0;
}

void GeometryStage::draw(const FrameDef& f, GpuScene& gpu, RenderTargets& t, FrameStats& stats,
                         const AmbientTerm* ambient, GbufferClears clears) {
    if (ambient && !t.ambient_target()) throw Error("geometry stage: this GL takes no ambient target beside the G-buffer");
    collect_counts();
    const bool prepass = !skip_prepass_ || choice_.run_next();
    stats.passes.depth_prepass = prepass;
    if (skip_prepass_) stats.passes.depth_complexity = choice_.complexity();
    t.mrt_bind_render();  // Listing 7 line 3
    gl_state().set_camera(f.proj, f.view);  // set_perspective_camera() (line 5)
    // Each draw loads its object's modelview, view * model composed in double (camera-relative).
    gpu.set_view(f.camera.view_d());
    glColor4f(1, 1, 1, 1);
    // Listing 7 clears every target to the background colour with one glClear; here each
    // target gets its own "no surface" value (docs/errata.md): a zero normal (0.5 grey,
    // which Listing 20's len > 0.1 test leaves unlit), zero diffuse with alpha 0 (the
    // ambient pass skips it), zero specular, and the packed depth (or position) of the far plane.
    // The position paths' target holds the far plane's eye z there (x = y = 0, alpha 0), so the
    // light pass's depth test and the depth hand-off see the background where the depth paths do.
    const Camera& cam = f.camera;
    const glm::vec4 far_code = is_position_path(depth_)
                                   ? glm::vec4(0, 0, -cam.far_plane, 0)
                                   : glm::vec4(encode_eye_z(encoding_, -cam.far_plane, cam.near_plane, cam.far_plane), 0);
    const glm::vec4 clear[4] = {{0.5f, 0.5f, 0.5f, 0.0f}, {0, 0, 0, 0}, {0, 0, 0, 0}, far_code};
    if (!t.gbuffer_written()) clears = GbufferClears{};  // new targets: nothing written yet
    const bool cleared[4] = {true, clears.diffuse, clears.specular, true};
    t.set_gbuffer_written();
    gl_state().apply(depth_pass_state());  // the clear writes depth: depth writes on, no scissor
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    check_gl_stage("geometry stage: set-up");
    if (prepass) {
        if (skip_prepass_) glBeginQuery(GL_SAMPLES_PASSED, queries_[0]);
        draw_depth(gpu);  // line 20
        if (skip_prepass_) glEndQuery(GL_SAMPLES_PASSED);
        check_gl_stage("geometry stage: depth pass");
    }
    // Without the pre-pass the first material pass writes depth with GL_LEQUAL: of surfaces at
    // equal depth the last drawn stays, as behind the pre-pass. Its samples passed are the
    // fragments shaded (behind the pre-pass: the pixels covered).
    auto material = [&](int target, bool first) {
        const bool count = skip_prepass_ && first;
        if (count) glBeginQuery(GL_SAMPLES_PASSED, queries_[1]);
        draw_material(f, gpu, target, !prepass && first, ambient ? ambient->ambient : glm::vec3(0));
        if (count) glEndQuery(GL_SAMPLES_PASSED);
    };
    pending_ = !skip_prepass_ ? 0 : prepass ? 2 : 1;
    // Each target is cleared to its own value; without MRT (§3.2, "rendering one pass per
    // buffer") each is also drawn right away, the depth the first pass (or the pre-pass) laid
    // down keeping every later pass to the visible fragments like the single MRT pass.
    gl_state().apply(material_pass_state(false));  // the clears write colour
    PBuffer& g = t.gbuffer();
    std::vector<int> all;
    for (int i = 0; i < g.color_targets(); ++i) {
        g.set_draw_targets({i});
        if (cleared[i]) {
            glClearColor(clear[i].r, clear[i].g, clear[i].b, clear[i].a);
            glClear(GL_COLOR_BUFFER_BIT);
            ++stats.passes.gbuffer_clears;
        }
        if (!mrt_) material(i, i == 0);
        all.push_back(i);
    }
    // P-buffer 0 after the G-buffer's targets: cleared as Listing 15's pass clears it, and the
    // material pass writes the ambient term where it finds a surface (material.frag AMBIENT_TARGET).
    if (ambient) {
        t.mrt_attach_accum(true);
        g.set_draw_targets({g.color_targets()});
        glClearColor(ambient->background.r, ambient->background.g, ambient->background.b, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        all.push_back(g.color_targets());
    }
    if (mrt_) {
        g.set_draw_targets(all);
        material(-1, true);  // line 22: all targets in one pass (ARB_draw_buffers)
    }
    if (ambient) t.mrt_attach_accum(false);
    check_gl_stage("geometry stage: material pass");
    t.mrt_unbind_render();  // line 24
}

// Render states of Listing 7 lines 7-17: back faces culled, GL_LEQUAL, no blending, no
// scissor, no alpha test, no fixed-function texturing.
RenderState GeometryStage::depth_pass_state() {
    RenderState s = opaque_geometry();
    s.color_write = false;  // Listing 8: depth only
    return s;
}

// The material pass: the same, colour on and depth writes off (the pre-pass laid it down,
// so only the visible fragment passes GL_LEQUAL: early Z, §3.3.1), or on without the pre-pass.
RenderState GeometryStage::material_pass_state(bool write_depth) {
    RenderState s = depth_pass_state();
    s.color_write = true;
    s.depth_write = write_depth;
    return s;
}

// Listing 8: raw positions, no shader, colour writes off; two-sided surfaces without culling.
// Cut-out surfaces are left out (GpuScene::draw_all): positions alone cannot tell where they are
// cut. The material pass lays their depth down itself, after every other surface (draw_material),
// which needs nothing the no-MRT and packed-depth paths lack, where an alpha test here would need
// the diffuse maps, texture coordinates and vertex colours in a fixed-function pass that matches
// the shader's coverage to the bit.
void GeometryStage::draw_depth(const GpuScene& gpu) {
    gl_state().apply(depth_pass_state());
    gpu.bind_positions();
    gpu.draw_all();
    gpu.unbind();
}

Program& GeometryStage::material_program(const GpuMaterial& m, int target, int surface) {
    // Without the variants skip, every material takes the full shader (normal map and
    // specular map read), as a single-shader renderer would.
    const MaterialKey key{m.normal_map || !variants_, variants_ && !m.has_specular, target, surface};
    auto it = programs_.find(key);
    if (it != programs_.end()) return it->second;
    if (surface == 0) throw Error("no material program for this material and target");
    // A surface form: the row as the table built it, with the surface's defines after.
    std::string name = material_row(key.normal_map, key.no_specular);
    if (target >= 0) name += "/" + std::to_string(target);
    return programs_[key] = sources_.build(name, surface_defines(surface));
}

// Listing 9 (target -1: all targets at once; t: only G-buffer target t), with its test un-inverted
// (docs/errata.md): materials with a normal map use the tangent-space shader, the others a variant
// that skips the normal map. Two-sided surfaces are drawn without culling. Cut-out surfaces come
// last with depth writes on (GL_LEQUAL): the pre-pass left them out, so each lays down its own depth
// where it is not discarded and hides what was drawn behind it; in the passes of the no-MRT path
// after the first, that depth passes exactly the same fragments again.
void GeometryStage::draw_material(const FrameDef& f, const GpuScene& gpu, int target, bool write_depth,
                                  glm::vec3 ambient) {
    const RenderState pass = material_pass_state(write_depth), cut_out = material_pass_state(true);
    gl_state().apply(pass);
    gpu.bind_all();
    int bound = -1;
    for (const DrawRange& r : gpu.ranges()) {
        const GpuMaterial& m = gpu.material(r.material);
        const int surface = r.surface() | (m.metal_rough ? kMaterialMetalRough : 0);
        Program& prog = material_program(m, target, surface);
        // The pass's state, or a surface's (nothing changes where no surface brings one).
        RenderState s = faces_state(r.cut_out ? cut_out : pass, r);
        s.program = gl_state().current().program;
        gl_state().apply(s);
        if (bound != int(prog.id())) {
            prog.use();
            prog.set("normaltex", 0);
            prog.set("colortex", 1);
            prog.set("speculartex", 2);
            if (surface & kMaterialMetalRough) {
                prog.set("occlusiontex", 3);
                prog.set("emissivetex", 4);
            }
            prog.set("planes", f.planes);
            prog.set("zrange", f.zrange);
            prog.set("ambient", ambient);  // where the program writes the ambient target
            prog.set("quantize_round", quantize_round_);
            bound = int(prog.id());
        }
        // set_material_shader_params (Listing 9 line 13)
        prog.set("diffuse", m.diffuse);
        prog.set("specular", m.specular);
        prog.set("shininess_code", m.shininess_code);
        prog.set("tile", m.tile);
        if (r.cut_out) prog.set("alpha_cutoff", m.alpha_cutoff);
        if (m.metal_rough) prog.set("emissive", m.emissive);
        const GLuint tex[5] = {m.normal_map || variants_ ? m.normal_tex : gpu.flat_normal(), m.diffuse_tex,
                               m.specular_tex, m.occlusion_tex, m.emissive_tex};
        bind_texture_units(tex, m.metal_rough ? 5 : 3);
        gpu.draw(r);
    }
    unbind_texture_units(5);
    gpu.unbind();
}

}  // namespace dsr
