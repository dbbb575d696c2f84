// The emission pass (emission_pass.h).
#include "deferred/emission_pass.h"

#include "gl/check.h"
#include "gl/texture.h"
#include "gl/state.h"

namespace dsr {

bool adds_to_ambient(const Material& m) {
    if (!m.metal_rough()) return false;
    const bool emits = m.emissive.r > 0 || m.emissive.g > 0 || m.emissive.b > 0;
    return emits || (m.occlusion_map >= 0 && m.occlusion_strength > 0);
}

namespace {
// material.frag's EMISSION_PASS form over the flat material row: no normal map is read.
ProgramSources emission_sources(const std::string& dir) {
    ProgramSpec s;
    s.name = "emission";
    s.vert = "material.vert";
    s.frag = "material.frag";
    s.role = "emission and occlusion into P-buffer 0";
    s.defines = {"EMISSION_PASS"};
    return ProgramSources(dir, {s});
}
}  // namespace

EmissionPass::EmissionPass(const std::string& shader_dir, const Scene& scene, const GpuScene& gpu)
    : sources_(emission_sources(shader_dir)) {
    for (const DrawRange& r : gpu.ranges())
        if (adds_to_ambient(scene.materials[size_t(r.material)])) ranges_.push_back(r);
}

Program& EmissionPass::program(int surface) {
    auto it = programs_.find(surface);
    if (it != programs_.end()) return it->second;
    return programs_[surface] = sources_.build("emission", surface_defines(surface | kMaterialMetalRough));
}

void EmissionPass::draw(const FrameDef& f, GpuScene& gpu, RenderTargets& t) {
    PBuffer& g = t.gbuffer();
    t.mrt_bind_render();
    t.mrt_attach_accum(true);
    g.set_draw_targets({g.color_targets()});
    gl_state().set_camera(f.proj, f.view);
    gpu.set_view(f.camera.view_d());
    // The material pass's state with its depth laid down: GL_LEQUAL, no depth writes; blended as
    // colour + P-buffer 0 x alpha (P-buffer 0's alpha, which no pass reads, takes the same sum).
    RenderState pass = opaque_geometry();
    pass.depth_write = false;
    pass.blend = true;
    pass.blend_src = GL_ONE;
    pass.blend_dst = GL_SRC_ALPHA;
    gpu.bind_all();
    for (const DrawRange& r : ranges_) {
        const GpuMaterial& m = gpu.material(r.material);
        Program& prog = program(r.surface());
        RenderState s = faces_state(pass, r);
        s.program = prog.id();
        gl_state().apply(s);
        prog.set("normaltex", 0);
        prog.set("colortex", 1);
        prog.set("speculartex", 2);
        prog.set("occlusiontex", 3);
        prog.set("emissivetex", 4);
        prog.set("diffuse", m.diffuse);
        prog.set("specular", m.specular);
        prog.set("tile", m.tile);
        prog.set("emissive", m.emissive);
        if (r.cut_out) prog.set("alpha_cutoff", m.alpha_cutoff);
        const GLuint tex[5] = {m.normal_tex, m.diffuse_tex, m.specular_tex, m.occlusion_tex, m.emissive_tex};
        bind_texture_units(tex, 5);
        gpu.draw(r);
    }
    unbind_texture_units(5);
    gpu.unbind();
    t.mrt_attach_accum(false);
    t.mrt_unbind_render();
    check_gl_stage("lighting stage: emission pass");
}

}  // namespace dsr
