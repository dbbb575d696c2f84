// The shadow stage (shadow_stage.h).
#include "deferred/shadow_stage.h"

#include <algorithm>
#include <string>

#include "deferred/depth_codec.h"
#include "deferred/gpu_scene.h"
#include "deferred/main_buffer_map.h"
#include "dsr_error.h"
#include "gl/check.h"
#include "gl/readback.h"
#include "gl/state.h"
#include "scene/shadow_budget.h"

namespace dsr {

namespace {

// ShadowLookup::generation: counted across every stage of the process, so that a texture name
// freed and given again, even by another stage, never comes back with a number already seen.
unsigned next_generation() {
    static unsigned n = 0;
    return ++n;
}

// Every view of a map: its clip volume's culling, a cube's faces against the light's sphere too.
bool casts_into(const Light& light, const ShadowLayout& s, const ShadowView& v, const ObjectBounds& b) {
    if (s.kind == ShadowKind::cube && glm::length(b.centre - light.pos) > light.radius + b.radius) return false;
    return !shadow_view_culls(v, b);
}

// The view's place in the texture: the whole of it, or a cube face's tile of the 3 x 2.
MapPiece view_rect(const ShadowLayout& s, size_t view) {
    if (s.kind != ShadowKind::cube) return {0, 0, s.width, s.height};
    return {int(view % 3) * s.face, int(view / 3) * s.face, s.face, s.face};
}

}  // namespace

ShadowStage::ShadowStage(const ShaderConfig& c, ProgramSet& programs)
    : caster_(programs.take("shadow_caster")),
      sources_(programs.sources("shadow_caster")),
      packed_(shadow_maps_packed(c.caps)),
      main_buffer_(!c.caps.fbo),
      hard_(c.opts.shadows.filter == ShadowFilter::hard),
      reuse_(c.opts.shadows.reuse) {
    GLint max = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
    max_texture_ = std::max(64, int(max));
}

ShadowStage::~ShadowStage() {
    for (auto& m : maps_) release(m.second);
}

Program& ShadowStage::cut_out_caster(bool colors) {
    Program& p = cut_out_casters_[colors];
    if (!p.id()) {
        p = sources_.build("shadow_caster", surface_defines(kSurfaceCutOut | (colors ? kSurfaceColors : 0)));
        p.use();
        p.set("colortex", 0);
    }
    return p;
}

void ShadowStage::release(Map& m) {
    if (m.fbo) glDeleteFramebuffersEXT(1, &m.fbo);
    if (m.depth_rb) glDeleteRenderbuffersEXT(1, &m.depth_rb);
    if (m.texture) glDeleteTextures(1, &m.texture);
    m = Map{};
}

void ShadowStage::set_scene(const Scene& scene) {
    bounds_ = object_bounds(scene);
    for (auto& m : maps_) release(m.second);
    maps_.clear();
}

void ShadowStage::allocate(Map& m, int width, int height) {
    if (m.texture && m.width == width && m.height == height) return;
    release(m);
    m.width = width, m.height = height;
    glGenTextures(1, &m.texture);
    glBindTexture(GL_TEXTURE_2D, m.texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    if (!main_buffer_) {
        glGenFramebuffersEXT(1, &m.fbo);
        glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, m.fbo);
    }
    if (packed_) {
        // The shader filters (shadow.glsl): each texel's code must come back whole.
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, width, height, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr);
        if (main_buffer_) {  // the main frame buffer's depth serves the test
            glBindTexture(GL_TEXTURE_2D, 0);
            return;
        }
        glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, m.texture, 0);
        glGenRenderbuffersEXT(1, &m.depth_rb);
        glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, m.depth_rb);
        glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, width, height);
        glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, 0);
        glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT, m.depth_rb);
    } else {
        // ARB_shadow: the lookup compares; GL_LINEAR asks the GL to filter the 2x2 comparisons.
        const GLint filter = hard_ ? GL_NEAREST : GL_LINEAR;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE_ARB, GL_COMPARE_R_TO_TEXTURE_ARB);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC_ARB, GL_LEQUAL);
        glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE_ARB, GL_LUMINANCE);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, width, height, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
        if (main_buffer_) {  // filled from the main frame buffer's depth
            glBindTexture(GL_TEXTURE_2D, 0);
            return;
        }
        glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_TEXTURE_2D, m.texture, 0);
        glDrawBuffer(GL_NONE);  // the framebuffer object's own state: depth only
        glReadBuffer(GL_NONE);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    const GLenum status = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE_EXT)
        throw Error("shadow map of " + std::to_string(width) + "x" + std::to_string(height) +
                    (packed_ ? " (RGB8 and a depth renderbuffer)" : " (a depth texture)") + ": framebuffer incomplete");
}

std::vector<ShadowLookup> ShadowStage::draw(const FrameDef& f, const Scene& scene, GpuScene& gpu, ShadowCounts& stats) {
    std::vector<ShadowLookup> out(size_t(f.shadowed_lights));
    last_.clear();
    if (f.shadowed_lights == 0) return out;
    // Every shadowed light's map counted against the budget before any is made, at this stage's
    // own texel size (scene/shadow_budget.h).
    const int texel_bytes = shadow_texel_bytes(packed_, !main_buffer_);
    const ShadowBudgetUse use = shadow_budget_use(scene.lights, texel_bytes, max_texture_);
    if (use.over)
        throw Error("shadow stage: expected " + shadow_budget_text(scene.lights[use.light], use.before, texel_bytes, max_texture_) +
                    " (light " + std::to_string(use.light + 1) + " of " + std::to_string(scene.lights.size()) + ")");
    if (bounds_.size() != scene.objects.size()) bounds_ = object_bounds(scene);
    const ShadowFit fit = shadow_fit(f.camera, f.aspect, bounds_);
    const glm::dmat4 eye_to_world = glm::inverse(f.camera.view_d());
    RenderState s = opaque_geometry();
    s.cull = false;         // open surfaces (planes) cast from either side, two-sided ones too
    // Cut-out surfaces cast where they are drawn: their caster reads the diffuse map's alpha (and
    // the vertex colours'), so the arrays are all bound where the scene has any.
    const bool cut_outs = gpu.has_cut_outs();
    bool map_bound = false;  // a diffuse map on unit 0
    s.color_write = packed_;
    s.program = caster_.id();
    bool bound = false;
    for (const LightDraw& l : f.lights) {
        if (l.shadow < 0) continue;
        const Light& light = *l.light;
        const ShadowLayout layout = shadow_layout(light, light.shadow.size, fit, max_texture_);
        // Which objects each view draws: opaque ones (transparent surfaces receive, not cast)
        // whose bounds reach it.
        Map key;
        for (const ShadowView& v : layout.views) {
            key.clips.push_back(v.proj * v.view);
            std::vector<size_t> objs;
            for (size_t o = 0; o < scene.objects.size() && o < bounds_.size(); ++o)
                if (!gpu.transparent(o) && casts_into(light, layout, v, bounds_[o])) {
                    objs.push_back(o);
                    key.models.push_back(scene.objects[o].model);
                }
            key.objects.push_back(std::move(objs));
        }
        Map& m = maps_[l.index];
        const bool same = reuse_ && m.texture && m.width == layout.width && m.height == layout.height && m.clips == key.clips &&
                          m.objects == key.objects && m.models == key.models;
        if (!same) {
            allocate(m, layout.width, layout.height);
            m.clips = key.clips, m.objects = key.objects, m.models = key.models;
            if (!bound) {
                if (cut_outs) gpu.bind_all();
                else gpu.bind_positions();
                bound = true;
            }
            glClearDepth(1.0);
            glClearColor(1, 1, 1, 1);  // pack_depth(1): far, wherever nothing is drawn
            const GLbitfield clear = GL_DEPTH_BUFFER_BIT | (packed_ ? GL_COLOR_BUFFER_BIT : 0);
            // View v's objects with its viewport moved by -(ox, oy).
            auto draw_view = [&](size_t v, int ox, int oy) {
                const MapPiece r = view_rect(layout, v);
                glViewport(r.x - ox, r.y - oy, r.width, r.height);
                gl_state().set_camera(glm::mat4(layout.views[v].proj));
                gpu.set_view(layout.views[v].view);
                for (size_t o : m.objects[v]) {
                    const DrawRange& rg = gpu.object_range(o);
                    if (cut_outs) {  // the caster of the object's surface, with the map's depth range
                        Program& p = rg.cut_out ? cut_out_caster(rg.colors) : caster_;
                        p.use();
                        p.set("shadow_depth", layout.depth);
                        if (rg.cut_out) {
                            const GpuMaterial& mat = gpu.material(rg.material);
                            p.set("tile", mat.tile);
                            p.set("alpha_cutoff", mat.alpha_cutoff);
                            glActiveTexture(GL_TEXTURE0);
                            glBindTexture(GL_TEXTURE_2D, mat.diffuse_tex);
                            map_bound = true;
                        }
                    }
                    gpu.draw(rg);
                    stats.triangles += rg.count / 3;
                }
            };
            if (!main_buffer_) {
                glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, m.fbo);
                glViewport(0, 0, m.width, m.height);
                gl_state().apply(s);
                glClear(clear);
                caster_.set("shadow_depth", layout.depth);
                for (size_t v = 0; v < layout.views.size(); ++v) draw_view(v, 0, 0);
                glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
            } else {
                // Into the frame's own region of the main frame buffer (what the copy P-buffers
                // take, so the drawable holds it), in pieces where the map is larger; each piece
                // draws the views that reach it (its triangles count once per piece).
                RenderState sp = s;
                sp.scissor = true;
                gl_state().apply(sp);
                caster_.set("shadow_depth", layout.depth);
                draw_through_main_buffer(m.texture, map_pieces(m.width, m.height, f.width, f.height), !packed_, clear,
                                         [&](const MapPiece& p) {
                                             for (size_t v = 0; v < layout.views.size(); ++v)
                                                 if (pieces_overlap(view_rect(layout, v), p)) draw_view(v, p.x, p.y);
                                         });
            }
            stats.maps += int(layout.views.size());
            m.generation = next_generation();
        }
        ShadowLookup& k = out[size_t(l.shadow)];
        k.texture = m.texture;
        k.kind = int(layout.kind);
        k.eye_to_light = glm::mat4(layout.light * eye_to_world);
        k.proj = glm::mat4(layout.views[0].proj);
        k.depth = layout.depth;
        k.texel = layout.texel;
        k.bias = light.shadow.bias;
        k.slope = light.shadow.slope;
        k.width = layout.width, k.height = layout.height, k.face = layout.face;
        k.packed = packed_;
        k.generation = m.generation;
    }
    if (bound) gpu.unbind();
    if (map_bound) {
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    check_gl_stage("shadow stage");
    last_ = out;
    return out;
}

Image ShadowStage::read_map(const ShadowLookup& m) const {
    // A depth texture reads back as grey; a packed map's codes go through the codec's CPU twin.
    Image img = read_texture(m.texture, m.width, m.height, m.width, m.height, !packed_);
    if (packed_)
        for (size_t i = 0; i < img.rgba.size(); i += 4) {
            const float d = unpack_depth(glm::vec3(img.rgba[i], img.rgba[i + 1], img.rgba[i + 2]));
            img.rgba[i] = img.rgba[i + 1] = img.rgba[i + 2] = d, img.rgba[i + 3] = 1.0f;
        }
    return img;
}

}  // namespace dsr
