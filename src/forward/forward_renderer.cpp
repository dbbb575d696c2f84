// Forward renderers of §2.4.1 (Listings 3 and 4), the reference for the deferred renderer's error.
#include "dsr_clock.h"
#include "forward/forward_renderer.h"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

#include "deferred/culling.h"
#include "deferred/frame_stats.h"
#include "deferred/gpu_scene.h"
#include "deferred/light_pass.h"
#include "deferred/light_volume.h"
#include "deferred/shader_table.h"
#include "deferred/shadow_stage.h"
#include "dsr_error.h"
#include "gl/blit.h"
#include "gl/check.h"
#include "deferred/forward_material.h"
#include "deferred/transparent_pass.h"
#include "gl/state.h"
#include "scene/bounds.h"

namespace dsr {

ForwardRenderer::ForwardRenderer(const Caps& caps, int width, int height, ForwardMode mode,
                                 const std::string& shader_dir, bool listing2_literal)
    : ForwardRenderer(caps, width, height,
                      [&] {
                          ForwardOptions o;
                          o.mode = mode;
                          o.listing2_literal = listing2_literal;
                          return o;
                      }(),
                      shader_dir) {}

ForwardRenderer::ForwardRenderer(const Caps& caps, int width, int height, const ForwardOptions& opts,
                                 const std::string& shader_dir)
    : caps_(caps), w_(width), h_(height), opts_(opts), shader_dir_(shader_dir) {
    if (!caps.glsl120) throw Error("forward: GLSL 1.20 is required and this GL offers " + caps.glsl_version);
    if (width <= 0 || height <= 0) throw Error("forward: bad size");
    if (opts.float_target) {
        if (!caps.fbo) throw Error("forward: the float target needs EXT_framebuffer_object, which is missing");
        if (!caps.texture_float) throw Error("forward: the float target needs ARB_texture_float, which is missing");
        PBufferDesc d;
        d.width = width;
        d.height = height;
        d.color_formats = {GL_RGBA32F_ARB};
        d.depth = DepthAttachment::renderbuffer;
        d.filter = GL_NEAREST;  // copied 1:1
        target_ = std::make_unique<PBuffer>("forward float target", d);
    }

    // Lights per pass: Listing 3 keeps every light of an object in one shader. The arrays
    // (five vec4s a light, light_params.h) must fit the fragment uniform space, with
    // room left for the material uniforms; GL 2.0 promises only 64 components.
    batch_ = 1;
    if (opts.mode == ForwardMode::single) {
        GLint comps = 0;
        glGetIntegerv(GL_MAX_FRAGMENT_UNIFORM_COMPONENTS, &comps);
        batch_ = std::clamp((int(comps) - 64) / 20, 1, std::max(1, opts.max_lights_per_pass));
    }
    build_programs(false);
    check_gl("forward: creating the renderer");
}

ForwardRenderer::~ForwardRenderer() = default;

// The tutorial's point lights take forward.frag with LIGHT_POINT_ONLY (lighting.glsl: no type or
// law selection, the cost the forward rows always had); a scene with any other light the general
// shader (with VIEW_PER_LIGHT on a GPU). Rebuilt only when a scene needs the other kind.
std::vector<std::string> ForwardRenderer::program_defines(bool normal_map, int surface) const {
    std::vector<std::string> defs = {"MAX_LIGHTS " + std::to_string(batch_)};
    if (normal_map) defs.push_back("NORMAL_MAP");
    if (opts_.listing2_literal) defs.push_back("LISTING2_LITERAL");
    if (!any_light_) defs.push_back("LIGHT_POINT_ONLY");
    // lighting.glsl: the view vector per light, the form each compiler ran fastest (forward
    // single-pass is the baseline the deferred rows are held against, so it gets its best).
    if (any_light_ && !caps_.software_rasterizer) defs.push_back("VIEW_PER_LIGHT");
    for (const std::string& d : surface_defines(surface)) defs.push_back(d);
    return defs;
}

void ForwardRenderer::build_programs(bool any_light) {
    any_light_ = any_light;
    for (int nm = 0; nm < 2; ++nm) {
        prog_[nm] = Program(shader_dir_, "forward.vert", "forward.frag", program_defines(nm, 0));
        prog_[nm].use();
        prog_[nm].set("normaltex", 0);
        prog_[nm].set("colortex", 1);
        prog_[nm].set("speculartex", 2);
        static const char* names[5] = {"lightpos[0]", "lightcolor[0]", "lightdir[0]", "lightspot[0]", "lightatt[0]"};
        for (int k = 0; k < 5; ++k) loc_light_[nm][k] = glGetUniformLocation(prog_[nm].id(), names[k]);
    }
    surface_progs_.clear();  // built again with the new light defines when drawn
    surface_locs_.clear();
    gl_state().use_program(0);
}

Program& ForwardRenderer::surface_program(bool normal_map, int surface) {
    Program& p = surface_progs_[int(normal_map) + 2 * surface];
    if (!p.id()) {
        p = Program(shader_dir_, "forward.vert", "forward.frag", program_defines(normal_map, surface));
        p.use();
        p.set("normaltex", 0);
        p.set("colortex", 1);
        p.set("speculartex", 2);
        static const char* names[5] = {"lightpos[0]", "lightcolor[0]", "lightdir[0]", "lightspot[0]", "lightatt[0]"};
        std::array<GLint, 5>& loc = surface_locs_[p.id()];
        for (int k = 0; k < 5; ++k) loc[size_t(k)] = glGetUniformLocation(p.id(), names[k]);
    }
    return p;
}

const GLint* ForwardRenderer::light_locations(const Program& prog) {
    if (&prog == &prog_[0]) return loc_light_[0];
    if (&prog == &prog_[1]) return loc_light_[1];
    return surface_locs_.at(prog.id()).data();
}

bool ForwardRenderer::needs_any_light(const Scene& scene) {
    for (const Light& l : scene.lights)
        if (l.type != Light::Type::point || l.attenuation || l.physical) return true;
    return false;
}

void ForwardRenderer::set_scene(const Scene& scene) {
    if (needs_any_light(scene) != any_light_) build_programs(!any_light_);
    gpu_ = std::make_unique<GpuScene>(scene);
    bounds_ = object_bounds(scene);  // per object, world space (scene/bounds.h)
    update_shadow_stage(scene);
    if (shadow_stage_) shadow_stage_->set_scene(scene);
    transparent_.reset();
    if (!gpu_->transparent_objects().empty())
        transparent_ = std::make_unique<TransparentPass>(shader_dir_, opts_.listing2_literal);
    check_gl("forward: uploading the scene");
}

bool ForwardRenderer::wants_shadows(const Scene& scene) const {
    for (const Light& l : scene.lights)
        if (opts_.shadows.on && l.shadow.on) return true;
    return false;
}

// The deferred renderer's shadow stage, built as DeferredShader builds it (its caster program from
// the shader table, the map format from the capabilities: depth textures compared by ARB_shadow,
// else RGB8 packed) while the scene has a light with `shadow` and ShadowOptions::on; and
// forward.frag's SHADOW form with the same lookup defines the transparent pass compiles.
void ForwardRenderer::update_shadow_stage(const Scene& scene) {
    if (!wants_shadows(scene)) {
        shadow_stage_.reset();
        return;
    }
    if (shadow_stage_) return;
    ShaderConfig c;
    c.caps = caps_;
    c.opts.shadows = opts_.shadows;
    c.opts.shadow_lights = true;
    ProgramSet programs(shader_dir_, c, {"shadow_caster"});
    shadow_stage_ = std::make_unique<ShadowStage>(c, programs);
    for (int nm = 0; nm < 2; ++nm) {
        if (shadow_prog_[nm].id()) continue;
        std::vector<std::string> defs = {"MAX_LIGHTS 1"};
        if (nm) defs.push_back("NORMAL_MAP");
        if (opts_.listing2_literal) defs.push_back("LISTING2_LITERAL");
        for (const std::string& d : shadow_lookup_defines(shadow_stage_->packed(), opts_.shadows.filter))
            defs.push_back(d);
        shadow_prog_[nm] = Program(shader_dir_, "forward.vert", "forward.frag", defs);
        shadow_prog_[nm].use();
        shadow_prog_[nm].set("normaltex", 0);
        shadow_prog_[nm].set("colortex", 1);
        shadow_prog_[nm].set("speculartex", 2);
        shadow_prog_[nm].set("shadow_map", 4);
    }
    gl_state().use_program(0);
}

// The maps of the frame's visible shadowed lights, drawn by the shadow stage from the frame the
// deferred renderer would make (make_frame with shadows: the same culling and skips, so the same
// lights get maps). A shadowed light that frame leaves out (it adds nothing, or its volume reaches
// no pixel) is not drawn, as the deferred renderer does not draw it.
void ForwardRenderer::draw_shadow_maps(const Scene& scene, ForwardStats& st) {
    maps_.clear();
    light_map_.clear();
    if (!shadow_stage_) return;
    FrameSetup setup;
    setup.width = w_;
    setup.height = h_;
    setup.shadows = true;
    const FrameDef f = make_frame(scene.camera, scene.lights, setup);
    if (f.shadowed_lights == 0) return;
    ShadowCounts fs;
    maps_ = shadow_stage_->draw(f, scene, *gpu_, fs);
    st.shadow_maps = fs.maps;
    st.shadow_triangles = fs.triangles;
    light_map_.assign(scene.lights.size(), nullptr);
    for (const LightDraw& l : f.lights)
        if (l.shadow >= 0) light_map_[l.index] = &maps_[size_t(l.shadow)];
    for (size_t i = 0; i < scene.lights.size(); ++i)
        if (scene.lights[i].shadow.on && !light_map_[i] && light_visible_[i]) {
            light_visible_[i] = 0;
            ++st.lights_culled;
        }
}

// Equation 2 (and the attenuation cut, and a spot's cone) makes a light's contribution exactly
// zero outside its volume, so skipping an object whose bounding sphere the volume's bounding
// sphere does not reach changes no pixel. A directional light reaches everything.
bool ForwardRenderer::touches(size_t object, const Light& light) const {
    return volume_reaches(light_volume(light), bounds_[object].centre, bounds_[object].radius);
}

Program& ForwardRenderer::use_material(const Scene& scene, size_t object) {
    const DrawRange& r = gpu_->object_range(object);
    const int mi = r.material;
    const GpuMaterial& m = gpu_->material(mi);
    Program& prog = r.surface() ? surface_program(m.normal_map, r.surface()) : prog_[m.normal_map ? 1 : 0];
    prog.use();
    set_forward_material(prog, m, scene.materials[mi].shininess);  // exact, not GpuMaterial's 8-bit code
    if (r.cut_out) prog.set("alpha_cutoff", m.alpha_cutoff);
    return prog;
}

Program& ForwardRenderer::use_shadowed(const Scene& scene, size_t object, size_t light) {
    const DrawRange& r = gpu_->object_range(object);
    const int mi = r.material;
    const GpuMaterial& m = gpu_->material(mi);
    Program* p = &shadow_prog_[m.normal_map ? 1 : 0];
    if (r.surface()) {  // the SHADOW form of the surface, built on first use
        Program& sp = surface_shadow_progs_[int(m.normal_map) + 2 * r.surface()];
        if (!sp.id()) {
            std::vector<std::string> defs = {"MAX_LIGHTS 1"};
            if (m.normal_map) defs.push_back("NORMAL_MAP");
            if (opts_.listing2_literal) defs.push_back("LISTING2_LITERAL");
            for (const std::string& d : shadow_lookup_defines(shadow_stage_->packed(), opts_.shadows.filter))
                defs.push_back(d);
            for (const std::string& d : surface_defines(r.surface())) defs.push_back(d);
            sp = Program(shader_dir_, "forward.vert", "forward.frag", defs);
            sp.use();
            sp.set("normaltex", 0);
            sp.set("colortex", 1);
            sp.set("speculartex", 2);
            sp.set("shadow_map", 4);
        }
        p = &sp;
    }
    Program& prog = *p;
    prog.use();
    set_forward_material(prog, m, scene.materials[mi].shininess);
    if (r.cut_out) prog.set("alpha_cutoff", m.alpha_cutoff);
    prog.set("nlights", 1);
    prog.set("ambient", glm::vec3(0));
    set_light_params(prog, light_params_[light]);  // element 0 of forward.frag's arrays
    bind_shadow_map(prog, *light_map_[light]);
    return prog;
}

void ForwardRenderer::set_lights(Program& prog, const std::vector<int>& lights, size_t first, size_t count,
                                 glm::vec3 ambient) {
    const GLint* loc = light_locations(prog);
    std::vector<glm::vec4> v[5];
    for (auto& a : v) a.resize(count);
    for (size_t i = 0; i < count; ++i) {
        const LightParams& lp = light_params_[lights[first + i]];
        v[0][i] = lp.pos, v[1][i] = lp.color, v[2][i] = lp.dir, v[3][i] = lp.spot, v[4][i] = lp.att;
    }
    prog.set("nlights", int(count));
    prog.set("ambient", ambient);
    if (count)
        for (int k = 0; k < 5; ++k)
            if (loc[k] >= 0) glUniform4fv(loc[k], GLsizei(count), glm::value_ptr(v[k][0]));
}

void ForwardRenderer::draw_object(size_t object, ForwardStats& st) {
    gpu_->draw(gpu_->object_range(object));
    ++st.passes;
}

ForwardStats ForwardRenderer::render(const Scene& scene) {
    if (!gpu_) throw Error("forward: render before set_scene");
    if (scene.objects.size() != bounds_.size()) throw Error("forward: render with a scene other than set_scene's");
    if (needs_any_light(scene) != any_light_) build_programs(!any_light_);  // not set_scene's lights
    if (wants_shadows(scene) != bool(shadow_stage_)) update_shadow_stage(scene);  // nor its `shadow`s
    ForwardStats st;
    const double t0 = now_ms(), cpu0 = thread_cpu_ms();
    const Camera& cam = scene.camera;
    view_ = cam.view();
    const glm::mat4 proj = cam.projection(float(w_) / float(h_));

    // Lights in eye space (Listing 2 works in view space); lights whose volume is outside the
    // frustum dropped (Listing 17's test: conservative, so no visible pixel loses light).
    const FrustumTest frustum(frustum_planes(proj * view_));
    light_params_.assign(scene.lights.size(), LightParams{});
    light_visible_.assign(scene.lights.size(), 0);
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& l = scene.lights[i];
        light_visible_[i] = !volume_outside(frustum, light_volume(l));
        if (!light_visible_[i]) ++st.lights_culled;
        light_params_[i] = light_params(l, cam);  // in double: see draw_lighting
    }
    // Before the target is bound: the shadow stage draws into framebuffer objects of its own.
    draw_shadow_maps(scene, st);

    if (target_) {
        target_->bind_render();
    } else {
        if (caps_.fbo) glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
        glDrawBuffer(GL_BACK);
        glViewport(0, 0, w_, h_);
    }
    gl_state().set_camera(proj, view_);
    gpu_->set_view(cam.view_d());  // each draw loads view * model, composed in double
    glColor4f(1, 1, 1, 1);
    gl_state().apply(surface_state());  // before the clear: depth and colour writes on
    glClearColor(scene.background.r, scene.background.g, scene.background.b, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    check_gl_stage("forward: set-up");

    gpu_->bind_all();
    if (opts_.mode == ForwardMode::single) {
        draw_single(scene, st);
    } else {
        draw_multi(scene, st);
    }
    gpu_->unbind();
    if (transparent_) {  // blended over the opaque surfaces, as the deferred renderer's forward stage
        const TransparentStats ts =
            transparent_->draw(scene, *gpu_, bounds_, light_params_, light_visible_, light_map_, opts_.shadows.filter);
        st.passes += ts.passes;
        st.light_object_pairs += int(ts.light_object_pairs);
    }

    for (int u = 2; u >= 0; --u) {
        glActiveTexture(GL_TEXTURE0 + u);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    check_gl_stage(opts_.mode == ForwardMode::single ? "forward: single-pass lighting" : "forward: multi-pass lighting");
    if (target_) {
        target_->unbind_render();
        copy_to_main();
    }
    st.ms_cpu = thread_cpu_ms() - cpu0;
    glFinish();
    st.ms_frame = now_ms() - t0;
    check_gl("forward: frame");
    return st;
}

// Listing 3: for each object, one pass with every light that reaches it. The first pass lays
// the surface down (ambient + up to batch_ lights, depth written, no blending); when more
// lights reach the object than the arrays hold, further passes add the rest on exactly the
// same fragments (GL_EQUAL, the vertex stage is the same program's). A shadowed light is one such
// pass of its own (GLSL 1.20 cannot index an array of samplers by a light's slot), through
// forward.frag's SHADOW form: the light's term times shadow_factor, after the object's other lights.
void ForwardRenderer::draw_single(const Scene& scene, ForwardStats& st) {
    std::vector<int> lights, shadowed;
    for (size_t m = 0; m < scene.objects.size(); ++m) {
        if (gpu_->transparent(m)) continue;  // after the opaque ones (transparent_pass.h)
        lights.clear();
        shadowed.clear();
        for (size_t i = 0; i < scene.lights.size(); ++i)
            if (light_visible_[i] && touches(m, scene.lights[i]))
                (light_map_.empty() || !light_map_[i] ? lights : shadowed).push_back(int(i));
        st.light_object_pairs += int(lights.size() + shadowed.size());
        Program& prog = use_material(scene, m);  // in render()'s surface state
        const DrawRange& range = gpu_->object_range(m);
        RenderState lay = surface_state();
        lay.program = prog.id();
        gl_state().apply(faces_state(lay, range));  // two-sided objects: no culling
        size_t first = std::min(lights.size(), size_t(batch_));
        set_lights(prog, lights, 0, first, scene.ambient);
        draw_object(m, st);
        if (first < lights.size() || !shadowed.empty()) {
            gl_state().apply(faces_state(add_state(prog.id()), range));
            for (size_t k = first; k < lights.size(); k += size_t(batch_)) {
                set_lights(prog, lights, k, std::min(size_t(batch_), lights.size() - k), glm::vec3(0));
                draw_object(m, st);
            }
            for (int i : shadowed) {
                Program& sp = use_shadowed(scene, m, size_t(i));
                gl_state().apply(faces_state(add_state(sp.id()), range));
                draw_object(m, st);
                unbind_shadow_map();
            }
            gl_state().apply(faces_state(lay, range));
        }
    }
}

// Listing 4: for each light, each object it affects, added to the frame buffer. The depth
// pre-pass leaves only the visible surface for GL_EQUAL, so hidden fragments are not shaded and
// each visible one gets each light once. It draws with the passes' own vertex stage
// (forward.vert, `invariant gl_Position`), colour writes off, not fixed function: GL_EQUAL needs
// the same depth bits in every pass. The ambient pass (Eq. 6, Listing 1) lays the surfaces down.
void ForwardRenderer::draw_multi(const Scene& scene, ForwardStats& st) {
    RenderState depth = surface_state();
    depth.color_write = false;
    depth.program = prog_[0].id();
    gl_state().apply(depth);
    gpu_->draw_all();  // two-sided objects without culling
    ++st.passes;
    // Cut-out objects discard in their own program's form, so the pre-pass keeps their cut parts out.
    for (size_t i = gpu_->solid_ranges(); i < gpu_->ranges().size(); ++i) {
        const DrawRange& r = gpu_->ranges()[i];
        RenderState d = depth;
        d.program = use_material(scene, r.object).id();
        gl_state().apply(faces_state(d, r));
        draw_object(r.object, st);
    }
    check_gl_stage("forward: depth pre-pass");

    RenderState ambient = add_state(0);
    ambient.blend = false;  // lays the surfaces down on the cleared buffer
    gl_state().apply(ambient);
    static const std::vector<int> none;
    for (size_t m = 0; m < scene.objects.size(); ++m) {
        if (gpu_->transparent(m)) continue;
        Program& prog = use_material(scene, m);
        RenderState a = ambient;
        a.program = prog.id();
        gl_state().apply(faces_state(a, gpu_->object_range(m)));
        set_lights(prog, none, 0, 0, scene.ambient);
        draw_object(m, st);
    }
    check_gl_stage("forward: ambient pass");

    // A shadowed light's passes take forward.frag's SHADOW form, its map on unit 4.
    gl_state().apply(add_state(0));
    std::vector<int> one(1);
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        if (!light_visible_[i]) continue;
        one[0] = int(i);
        const bool shadowed = !light_map_.empty() && light_map_[i];
        for (size_t m = 0; m < scene.objects.size(); ++m) {
            if (gpu_->transparent(m) || !touches(m, scene.lights[i])) continue;
            if (shadowed) {
                use_shadowed(scene, m, i);
            } else {
                Program& prog = use_material(scene, m);
                set_lights(prog, one, 0, 1, glm::vec3(0));
            }
            gl_state().apply(faces_state(add_state(gl_state().current().program), gpu_->object_range(m)));
            draw_object(m, st);
            ++st.light_object_pairs;
        }
        if (shadowed) unbind_shadow_map();
    }
}

// The surface pass: back faces culled, GL_LEQUAL, depth and colour written, no blending.
RenderState ForwardRenderer::surface_state() { return opaque_geometry(); }

// A further pass over the same fragments, added: GL_EQUAL against the laid-down depth, no
// depth writes, additive blending.
RenderState ForwardRenderer::add_state(GLuint program) {
    RenderState s = surface_state();
    s.depth_func = GL_EQUAL;
    s.depth_write = false;
    s.blend = true;
    s.blend_src = s.blend_dst = GL_ONE;
    s.program = program;
    return s;
}

// The float target to the main frame buffer, 1:1 with nearest sampling: the one rounding to
// 8 bits. Colours above 1 are clamped here; every term is >= 0, so clamping the sum once is
// what clamping after each additive pass gives too.
void ForwardRenderer::copy_to_main() {
    target_->bind_texture(0, 0);  // the P-buffer discipline: never a target and a texture at once
    draw_texture_to_framebuffer0(target_->texture(0), w_, h_, {1, 1}, true);
    target_->unbind_texture(0, 0);
    check_gl_stage("forward: copy to the main frame buffer");
}

}  // namespace dsr
