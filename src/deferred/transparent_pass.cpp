#include "deferred/transparent_pass.h"

#include <algorithm>

#include "deferred/gpu_scene.h"
#include "deferred/light_pass.h"
#include "deferred/light_volume.h"
#include "deferred/shader_table.h"
#include "deferred/forward_material.h"
#include "deferred/transparent_order.h"
#include "gl/check.h"
#include "gl/state.h"

namespace dsr {

TransparentPass::TransparentPass(const std::string& shader_dir, bool listing2_literal)
    : shader_dir_(shader_dir), listing2_literal_(listing2_literal) {
    // Lights per pass as the forward single-pass renderer sizes them: five vec4s a light within
    // the fragment uniform space, room kept for the material's uniforms.
    GLint comps = 0;
    glGetIntegerv(GL_MAX_FRAGMENT_UNIFORM_COMPONENTS, &comps);
    batch_ = std::clamp((int(comps) - 64) / 20, 1, 64);
}

namespace {

// glTF's BRDF in forward.frag (METAL_ROUGH_FORWARD), lighting.glsl's brdf_metal_rough as the light
// passes use it; the occlusion and emissive maps on units 5 and 6 (4 holds a shadow map).
void add_metal_rough(std::vector<std::string>& defs, bool metal_rough) {
    if (metal_rough) defs.insert(defs.end(), {"METAL_ROUGH", "METAL_ROUGH_FORWARD"});
}

void set_metal_rough_units(Program& p, bool metal_rough) {
    if (!metal_rough) return;
    p.set("occlusiontex", 5);
    p.set("emissivetex", 6);
}

}  // namespace

Program& TransparentPass::program(bool normal_map, bool any_light, int surface, bool metal_rough) {
    Program& p = progs_[normal_map][any_light][surface][metal_rough];
    if (!p.id()) {
        std::vector<std::string> defs = {"MAX_LIGHTS " + std::to_string(batch_), "OPACITY"};
        if (normal_map) defs.push_back("NORMAL_MAP");
        if (listing2_literal_) defs.push_back("LISTING2_LITERAL");
        if (!any_light) defs.push_back("LIGHT_POINT_ONLY");
        for (const std::string& d : surface_defines(surface)) defs.push_back(d);
        add_metal_rough(defs, metal_rough);
        p = Program(shader_dir_, "forward.vert", "forward.frag", defs);
        p.use();
        p.set("normaltex", 0);
        p.set("colortex", 1);
        p.set("speculartex", 2);
        set_metal_rough_units(p, metal_rough);
    }
    return p;
}

Program& TransparentPass::shadow_program(bool normal_map, bool packed, ShadowFilter filter, int surface, bool metal_rough) {
    if (filter != shadow_filter_) {  // the forms of another filter are of no more use
        for (auto& row : shadow_progs_)
            for (auto& forms : row)
                for (auto& pair : forms)
                    for (Program& q : pair) q = Program();
        shadow_filter_ = filter;
    }
    Program& p = shadow_progs_[normal_map][packed][surface][metal_rough];
    if (!p.id()) {
        std::vector<std::string> defs = {"MAX_LIGHTS 1", "OPACITY"};
        if (normal_map) defs.push_back("NORMAL_MAP");
        if (listing2_literal_) defs.push_back("LISTING2_LITERAL");
        for (const std::string& d : shadow_lookup_defines(packed, filter)) defs.push_back(d);
        for (const std::string& d : surface_defines(surface)) defs.push_back(d);
        add_metal_rough(defs, metal_rough);
        p = Program(shader_dir_, "forward.vert", "forward.frag", defs);
        p.use();
        p.set("normaltex", 0);
        p.set("colortex", 1);
        p.set("speculartex", 2);
        set_metal_rough_units(p, metal_rough);
        p.set("shadow_map", 4);
    }
    return p;
}

namespace {

// The first pass of an object: blended over what lies behind it, a * colour + (1 - a) * dst.
// Later passes (more lights than one pass holds) add a * their lights on the same fragments: the
// depth test is against the opaque depth, unchanged, so they pass exactly where the first did.
// A two-sided object is drawn without culling.
RenderState transparent_state(GLuint program, bool first, const DrawRange& r) {
    RenderState s = faces_state(opaque_geometry(), r);
    s.depth_write = false;
    s.blend = true;
    s.blend_src = GL_SRC_ALPHA;
    s.blend_dst = first ? GL_ONE_MINUS_SRC_ALPHA : GL_ONE;
    s.program = program;
    return s;
}

}  // namespace

TransparentStats TransparentPass::draw(const Scene& scene, const GpuScene& gpu, const std::vector<ObjectBounds>& bounds,
                                       const std::vector<LightParams>& lights, const std::vector<char>& visible,
                                       const std::vector<const ShadowLookup*>& shadows, ShadowFilter filter) {
    TransparentStats st;
    const std::vector<size_t> order = transparent_order(gpu.transparent_objects(), bounds, glm::dvec3(scene.camera.pos));
    if (order.empty()) return st;
    gpu.bind_all();
    std::vector<int> reach, shadowed;
    LightArrays arrays;
    for (size_t o : order) {
        reach.clear();
        shadowed.clear();
        bool any_light = false;
        for (size_t i = 0; i < scene.lights.size(); ++i) {
            const Light& l = scene.lights[i];
            if (!visible[i] || !volume_reaches(light_volume(l), bounds[o].centre, bounds[o].radius)) continue;
            if (i < shadows.size() && shadows[i]) {  // a pass of its own, after the others
                shadowed.push_back(int(i));
                continue;
            }
            reach.push_back(int(i));
            any_light = any_light || l.type != Light::Type::point || l.attenuation || l.physical;
        }
        st.light_object_pairs += (long long)(reach.size() + shadowed.size());
        const DrawRange& range = gpu.object_range(o);
        const int mi = range.material;
        const GpuMaterial& m = gpu.material(mi);
        Program& prog = program(m.normal_map, any_light, range.surface(), m.metal_rough);
        gl_state().use_program(prog.id());
        set_forward_material(prog, m, scene.materials[size_t(mi)].shininess);  // as the forward renderers
        if (m.metal_rough) {
            glActiveTexture(GL_TEXTURE5);
            glBindTexture(GL_TEXTURE_2D, m.occlusion_tex);
            glActiveTexture(GL_TEXTURE6);
            glBindTexture(GL_TEXTURE_2D, m.emissive_tex);
            glActiveTexture(GL_TEXTURE0);
        }
        prog.set("opacity", m.opacity);
        if (range.cut_out) prog.set("alpha_cutoff", m.alpha_cutoff);
        // Ambient (Eq. 6) and the first batch_ lights blended over the background; the rest added.
        size_t k = 0;
        do {
            const size_t n = std::min(reach.size() - k, size_t(batch_));
            arrays.clear();
            for (size_t i = 0; i < n; ++i) arrays.add(lights[size_t(reach[k + i])]);
            gl_state().apply(transparent_state(prog.id(), k == 0, range));
            prog.set("nlights", int(n));
            prog.set("ambient", k == 0 ? scene.ambient : glm::vec3(0));
            if (m.metal_rough) prog.set("emissive", k == 0 ? m.emissive : glm::vec3(0));  // added once
            if (n) arrays.set(prog, LightArrays::kLight);
            gpu.draw(range);
            ++st.passes;
            k += n;
        } while (k < reach.size());
        // Each shadowed light added by its own pass, the light's term scaled by its map's lookup.
        for (int i : shadowed) {
            const ShadowLookup& map = *shadows[size_t(i)];
            Program& sp = shadow_program(m.normal_map, map.packed, filter, range.surface(), m.metal_rough);
            gl_state().apply(transparent_state(sp.id(), false, range));
            set_forward_material(sp, m, scene.materials[size_t(mi)].shininess);
            sp.set("opacity", m.opacity);
            if (range.cut_out) sp.set("alpha_cutoff", m.alpha_cutoff);
            sp.set("nlights", 1);
            sp.set("ambient", glm::vec3(0));
            if (m.metal_rough) sp.set("emissive", glm::vec3(0));
            set_light_params(sp, lights[size_t(i)]);  // element 0 of forward.frag's arrays
            bind_shadow_map(sp, map);
            gpu.draw(range);
            unbind_shadow_map();
            ++st.passes;
        }
        ++st.objects;
    }
    for (int u : {6, 5, 2, 1, 0}) {
        glActiveTexture(GL_TEXTURE0 + u);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    gpu.unbind();
    check_gl_stage("transparent pass");
    return st;
}

}  // namespace dsr
