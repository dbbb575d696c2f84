// The light pass every geometry shares (light_pass.h).
#include "deferred/light_pass.h"

#include <algorithm>

#include "deferred/reconstruct.h"
#include "deferred/screen_quad.h"
#include "deferred/shadow_atlas.h"

namespace dsr {

RenderState light_pass_state(GLuint program, bool scissor) {
    RenderState s;
    s.blend = true;
    s.blend_src = s.blend_dst = GL_ONE;
    s.scissor = scissor;
    s.program = program;
    return s;
}

void set_light_uniforms(Program& prog, const FrameDef& f) {
    gl_state().use_program(prog.id());
    prog.set("normal_map", 0);
    prog.set("diffuse_map", 1);
    prog.set("specular_map", 2);
    prog.set("depth_map", 3);
    prog.set("planes", f.planes);
    prog.set("zrange", f.zrange);
    // Texture coordinates from gl_FragCoord (the G-buffer may be padded to powers of two).
    prog.set("uv_scale", f.uv_scale);
    // The view ray through window point (x, y): the corner rays' bilinear map, which is affine.
    prog.set("ray_map", f.ray_map);
}

void set_light_params(Program& prog, const LightParams& lp) {
    prog.set("lightpos", lp.pos);
    prog.set("lightcolor", lp.color);
    prog.set("lightdir", lp.dir);
    prog.set("lightspot", lp.spot);
    prog.set("lightatt", lp.att);
}

namespace {

// Window depth of eye-space z (glm::perspective's mapping, §3.4.3's `planes` inverted).
float window_depth(float z, glm::vec2 planes) { return (planes.x * z + planes.y) / -z; }

}  // namespace

void LightArrays::clear() { pos_.clear(), color_.clear(), dir_.clear(), spot_.clear(), att_.clear(); }

void LightArrays::add(const LightParams& p) {
    pos_.push_back(p.pos), color_.push_back(p.color), dir_.push_back(p.dir);
    spot_.push_back(p.spot), att_.push_back(p.att);
}

void LightArrays::set(Program& prog, const char* const (&names)[5]) const {
    const int n = size();
    prog.set_array(names[0], pos_.data(), n);
    prog.set_array(names[1], color_.data(), n);
    prog.set_array(names[2], dir_.data(), n);
    prog.set_array(names[3], spot_.data(), n);
    prog.set_array(names[4], att_.data(), n);
}

void bind_shadow(Program& prog, const FrameDef& f, const LightDraw& l) {
    if (l.shadow < 0) return;
    bind_shadow_map(prog, f.shadows.at(size_t(l.shadow)));
}

void bind_shadow_map(Program& prog, const ShadowLookup& m) {
    prog.set_array("shadow_view", &m.eye_to_light[0], 4);
    prog.set_array("shadow_proj", &m.proj[0], 4);
    prog.set("shadow_depth", m.depth);
    prog.set("shadow_params", glm::vec4(m.bias, m.slope, m.texel.x, m.texel.y));
    prog.set("shadow_size", glm::vec4(float(m.kind), float(m.face), float(m.width), float(m.height)));
    glActiveTexture(GL_TEXTURE4);
    glBindTexture(GL_TEXTURE_2D, m.texture);
    glActiveTexture(GL_TEXTURE0);
}

void unbind_shadow(const LightDraw& l) {
    if (l.shadow >= 0) unbind_shadow_map();
}

void unbind_shadow_map() {
    glActiveTexture(GL_TEXTURE4);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
}

ShadowSlots::ShadowSlots(bool packed) : packed_(packed) {}

ShadowSlots::~ShadowSlots() = default;

void ShadowSlots::clear() {
    maps_.clear();
    atlas_ = nullptr;
}

float ShadowSlots::add(const FrameDef& f, const LightDraw& l) {
    if (l.shadow < 0) return -1.0f;
    maps_.push_back(&f.shadows.at(size_t(l.shadow)));
    return float(maps_.size() - 1);
}

Program& ShadowSlots::prepare(LightPrograms& progs, FrameStats& stats) {
    atlas_ = nullptr;
    if (!progs.shadow_atlas().id() || maps_.empty()) return progs.shadow();
    if (max_texture_ == 0) {
        GLint max = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
        max_texture_ = int(max);
    }
    sizes_.clear();
    for (const ShadowLookup* m : maps_) sizes_.push_back(AtlasRegion{0, 0, m->width, m->height});
    layout_ = place_atlas(sizes_, max_texture_);
    if (!layout_.fits()) return progs.shadow();  // larger than the GL's textures: the chain
    if (next_ == atlases_.size()) atlases_.push_back(std::make_unique<ShadowAtlas>(packed_));
    atlas_ = atlases_[next_++].get();
    stats.shadows.atlas_texels += atlas_->update(layout_, maps_, kShadowUnit);
    return progs.shadow_atlas();
}

void ShadowSlots::set(Program& prog) {
    if (maps_.empty()) return;
    view_.clear(), proj_.clear(), params_.clear(), size_.clear(), depth_.clear(), region_.clear();
    for (const ShadowLookup* m : maps_) {
        for (int c = 0; c < 4; ++c) view_.push_back(m->eye_to_light[c]), proj_.push_back(m->proj[c]);
        depth_.push_back(m->depth);
        params_.push_back(glm::vec4(m->bias, m->slope, m->texel.x, m->texel.y));
        size_.push_back(glm::vec4(float(m->kind), float(m->face), float(m->width), float(m->height)));
    }
    const int n = size();
    prog.set_array("shadow_view", view_.data(), 4 * n);
    prog.set_array("shadow_proj", proj_.data(), 4 * n);
    prog.set_array("shadow_depth", depth_.data(), n);
    prog.set_array("shadow_params", params_.data(), n);
    prog.set_array("shadow_size", size_.data(), n);
    if (atlas_) {
        for (const AtlasRegion& r : layout_.regions)
            region_.push_back(glm::vec4(float(r.x), float(r.y), float(layout_.width), float(layout_.height)));
        prog.set_array("shadow_region", region_.data(), n);
        glActiveTexture(GLenum(GL_TEXTURE0 + kShadowUnit));
        glBindTexture(GL_TEXTURE_2D, atlas_->texture());
        glActiveTexture(GL_TEXTURE0);
        return;
    }
    for (int k = 0; k < n; ++k) {
        glActiveTexture(GLenum(GL_TEXTURE0 + kShadowUnit + k));
        glBindTexture(GL_TEXTURE_2D, maps_[size_t(k)]->texture);
    }
    glActiveTexture(GL_TEXTURE0);
}

void ShadowSlots::unbind() const {
    for (int k = 0; k < (atlas_ ? 1 : size()); ++k) {
        glActiveTexture(GLenum(GL_TEXTURE0 + kShadowUnit + k));
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    glActiveTexture(GL_TEXTURE0);
}

LightParams with_shadow_slot(LightParams p, float slot) {
    p.spot.z = slot;
    return p;
}

Program& load_batch(const FrameDef& f, const std::vector<int>& batch, LightArrays& arrays, ShadowSlots& shadows,
                    LightPrograms& progs, FrameStats& stats) {
    bool with_maps = false;
    for (int i : batch) with_maps |= f.lights[size_t(i)].shadow >= 0;
    arrays.clear();
    shadows.clear();
    for (int i : batch) {
        const LightDraw& l = f.lights[size_t(i)];
        arrays.add(with_maps ? with_shadow_slot(l.params, shadows.add(f, l)) : l.params);
    }
    return shadows.size() > 0 ? shadows.prepare(progs, stats) : progs[LightPrograms::common(f, batch)];
}

std::optional<glm::vec3> shared_attenuation(const FrameDef& f, const std::vector<int>& batch) {
    if (batch.empty()) return std::nullopt;
    const glm::vec3 a(f.lights[size_t(batch[0])].params.att);
    if (!std::all_of(batch.begin(), batch.end(), [&](int i) { return glm::vec3(f.lights[size_t(i)].params.att) == a; }))
        return std::nullopt;
    return a;
}

// The family's programs by the table's names: FAMILY_point, FAMILY_point_inverse, FAMILY, and
// FAMILY_shadow, FAMILY_shadow_atlas where `has` them.
template <class Has, class Get>
void LightPrograms::load(const std::string& family, bool shadow_only, Has&& has, Get&& get) {
    if (!shadow_only) {
        forms_[int(LightShader::point_linear)] = get(family + "_point");
        forms_[int(LightShader::point_inverse)] = get(family + "_point_inverse");
        forms_[int(LightShader::any)] = get(family);
    }
    if (has(family + "_shadow")) shadow_ = get(family + "_shadow");
    if (has(family + "_shadow_atlas")) shadow_atlas_ = get(family + "_shadow_atlas");
}

LightPrograms::LightPrograms(ProgramSet& programs, const std::string& family, bool shadow_only, int shadow_slots)
    : shadow_slots_(shadow_slots) {
    load(family, shadow_only, [&](const std::string& n) { return programs.has(n); },
         [&](const std::string& n) { return programs.take(n); });
}

LightPrograms::LightPrograms(const ProgramSources& sources, const std::string& family, int shadow_slots,
                             const Defines& extra)
    : shadow_slots_(shadow_slots) {
    load(family, false, [&](const std::string& n) { return sources.has(n); },
         [&](const std::string& n) { return sources.build(n, extra); });
}

void LightPrograms::begin(const FrameDef& f) {
    for (Program& p : forms_)
        if (p.id()) set_light_uniforms(p, f);
    if (shadow_.id()) {
        set_light_uniforms(shadow_, f);
        if (shadow_slots_ == 0) shadow_.set("shadow_map", kShadowUnit);
        for (int k = 0; k < shadow_slots_; ++k)
            shadow_.set(("shadow_maps[" + std::to_string(k) + "]").c_str(), kShadowUnit + k);
    }
    if (shadow_atlas_.id()) {
        set_light_uniforms(shadow_atlas_, f);
        shadow_atlas_.set("shadow_atlas", kShadowUnit);
    }
}

LightShader LightPrograms::common(const FrameDef& f, const std::vector<int>& lights) {
    if (lights.empty()) return LightShader::any;
    const LightShader first = f.lights[size_t(lights[0])].shader();
    for (int i : lights)
        if (f.lights[size_t(i)].shader() != first) return LightShader::any;
    return first;
}

LightQuads::LightQuads(ProgramSet& programs, bool depth_bounds, bool shadow_only)
    : progs_(programs, "light", shadow_only), depth_bounds_(depth_bounds) {}

void LightQuads::begin(const FrameDef& f) {
    gl_state().set_camera(f.pixels());
    progs_.begin(f);
}

void LightQuads::draw(const FrameDef& f, const LightDraw& l, LightQueries& q) {
    Program& prog = progs_.form(l);
    RenderState s = light_pass_state(prog.id(), !l.full);
    if (!l.full) glScissor(l.rect.x0, l.rect.y0, l.rect.x1 - l.rect.x0, l.rect.y1 - l.rect.y0);  // set_light_scissor
    if (depth_bounds_ && l.eye.kind != LightVolume::Kind::full_screen) {
        // The depth span of the volume's bounding sphere (a cone's lies inside its apex sphere's),
        // tested against the scene's depth the hand-off put in P-buffer 0, before the shader runs.
        const BoundingSphere b = bounding_sphere(l.eye);
        const float n = f.zrange.x, fa = f.zrange.y;
        const float z_near = std::min(-n, b.centre.z + b.radius), z_far = std::max(-fa, b.centre.z - b.radius);
        s.depth_bounds_test = true;
        s.depth_test = true;  // the bounds test reads the depth buffer; GL_ALWAYS keeps the rest as it was
        s.depth_func = GL_ALWAYS;
        s.depth_write = false;
        glDepthBoundsEXT(std::max(0.0f, window_depth(z_near, f.planes)), std::min(1.0f, window_depth(z_far, f.planes)));
    }
    gl_state().apply(s);
    set_light_params(prog, l.params);
    bind_shadow(prog, f, l);
    q.begin();
    draw_rect(f, 0, 0, float(f.width), float(f.height), true);
    q.end();
    unbind_shadow(l);
}

LightQuadBatch::LightQuadBatch(ProgramSet& programs, int batch) : progs_(programs, "light_batch"), batch_(batch) {}

void LightQuadBatch::draw(const FrameDef& f, const std::vector<const LightDraw*>& lights, LightQueries& q,
                          FrameStats& stats, bool scene_depth) {
    if (lights.empty()) return;
    gl_state().set_camera(f.pixels());
    progs_.begin(f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glClientActiveTexture(GL_TEXTURE2);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    buffers_.begin_frame();
    for_each_light_batch(lights, batch_, [&](LightShader form, const LightDraw* const* run, size_t n) {
        Program& prog = progs_[form];
        arrays_.clear();
        verts_.clear();
        for (size_t k = 0; k < n; ++k) {
            const LightDraw& l = *run[k];
            arrays_.add(l.params);
            // The rectangle as a quad (x, y, z, slot per corner); a full light's is the viewport.
            const float x0 = float(l.full ? 0 : l.rect.x0), y0 = float(l.full ? 0 : l.rect.y0);
            const float x1 = float(l.full ? f.width : l.rect.x1), y1 = float(l.full ? f.height : l.rect.y1);
            // The pixel camera (glOrtho's near -1, far 1) puts eye z at window depth (1 - z) / 2;
            // depth 1 (z = -1) lies on the far clip plane, which clipping keeps. A light without a
            // span (directional, or any with the test off) at depth 1 passes everywhere.
            const bool span = scene_depth && l.light->type != Light::Type::directional;
            const float depth = span ? sphere_back_depth(l.params.pos.z, l.params.pos.w, f.zrange.x, f.zrange.y) : 1.0f;
            const float z = 1.0f - 2.0f * depth, slot = float(k);
            const float quad[16] = {x0, y0, z, slot, x1, y0, z, slot, x1, y1, z, slot, x0, y1, z, slot};
            verts_.insert(verts_.end(), quad, quad + 16);
        }
        RenderState s = light_pass_state(prog.id(), false);
        if (scene_depth) {
            s.depth_test = true;
            s.depth_func = GL_GEQUAL;
            s.depth_write = false;
        }
        gl_state().apply(s);
        arrays_.set(prog, LightArrays::kBatch);
        // Each batch's vertices in a buffer object of its own: the driver's copies of client arrays
        // cost the CPU more than the uploads (docs/gpu_frame.md, "Choices these costs decide").
        buffers_.upload_next(verts_.data(), verts_.size() * sizeof(float));
        glVertexPointer(3, GL_FLOAT, 4 * sizeof(float), nullptr);
        glTexCoordPointer(1, GL_FLOAT, 4 * sizeof(float), reinterpret_cast<const void*>(3 * sizeof(float)));
        q.begin();
        glDrawArrays(GL_QUADS, 0, GLsizei(4 * n));
        q.end();
        ++stats.lights.passes;
    });
    StreamBuffer::unbind();  // later client-array draws read client memory again
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glClientActiveTexture(GL_TEXTURE0);
    glDisableClientState(GL_VERTEX_ARRAY);
}

}  // namespace dsr
