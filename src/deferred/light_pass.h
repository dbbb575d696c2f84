// What every light geometry shares (§3.4.2-3.4.3): the light pass's state, the uniforms every
// light program takes from the frame (bind_light()), one light's parameters, and the tutorial's
// scissored quad per light (Listings 16-17), which the quad geometry draws for every light and
// the volume geometries for the lights their mesh cannot serve.
#pragma once
#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "deferred/atlas_layout.h"
#include "deferred/frame.h"
#include "deferred/light_queries.h"
#include "deferred/shader_table.h"
#include "gl/program.h"
#include "gl/state.h"
#include "gl/stream_buffer.h"

namespace dsr {

// Listings 16-17: additive, through the light shader, limited to the light's scissor rectangle.
RenderState light_pass_state(GLuint program, bool scissor);
// Binds `prog` and sets what every light program reads of the frame: the G-buffer's samplers on
// units 0-3, planes and zrange (§3.4.3), uv_scale and ray_map (gl_FragCoord to G-buffer
// coordinates and view ray).
void set_light_uniforms(Program& prog, const FrameDef& f);
// set_light_params: one light as lighting.glsl's five vec4s (light_params.h).
void set_light_params(Program& prog, const LightParams& lp);

// A batch of lights in uniform arrays, lighting.glsl's five vec4s a light, one array each (the
// tiles' batches, screen's, the batched quads'). Kept between frames for its storage.
class LightArrays {
public:
    // The arrays' names in light_tiles.frag and light_screen.frag, and in light.frag's BATCH (and
    // batch_pos in light.vert's VOLUME_BATCH).
    static constexpr const char* kLight[5] = {"lightpos", "lightcolor", "lightdir", "lightspot", "lightatt"};
    static constexpr const char* kBatch[5] = {"batch_pos", "batch_color", "batch_dir", "batch_spot", "batch_att"};
    void clear();
    void add(const LightParams& p);
    int size() const { return int(pos_.size()); }
    // Into `prog`'s arrays (prog in use) of these names: position, colour, direction, spot, attenuation.
    void set(Program& prog, const char* const (&names)[5]) const;

private:
    std::vector<glm::vec4> pos_, color_, dir_, spot_, att_;
};

// A shadowed light's map (f.shadows[l.shadow]) on unit 4 and its uniforms (glsl120/shadow.glsl)
// in `prog`, in use; nothing for a light without one. unbind_shadow takes the map off unit 4.
void bind_shadow(Program& prog, const FrameDef& f, const LightDraw& l);
// The same for one map (the transparent pass's shadowed lights); unbind with unbind_shadow_map.
void bind_shadow_map(Program& prog, const ShadowLookup& m);
void unbind_shadow_map();
void unbind_shadow(const LightDraw& l);

class LightPrograms;
class ShadowAtlas;

// A batch's shadowed lights' maps (shadow.glsl SHADOW_SLOTS): each added light gets the next slot.
// Where the program table built the atlas form (framebuffer objects) and the maps fit one atlas of
// GL_MAX_TEXTURE_SIZE, they are copied into the atlas of the batch's position in the frame
// (shadow_atlas.h; kept between frames) and read through one sampler on kShadowUnit; else each map
// on unit kShadowUnit + slot, read through the if-chain. set() puts the maps' uniforms into the
// program's arrays and binds the textures, unbind() takes them off their units.
class ShadowSlots {
public:
    // packed: RGB8 maps, else depth textures (the atlas's format).
    explicit ShadowSlots(bool packed);
    ~ShadowSlots();
    // Before a frame's first batch: the first batch takes the first atlas.
    void begin_frame() { next_ = 0; }
    void clear();
    // l's slot among the batch's maps (as a float, for lightspot.z), -1 for a light without one.
    float add(const FrameDef& f, const LightDraw& l);
    int size() const { return int(maps_.size()); }
    // The program that draws the batch (size() > 0): progs' atlas form with the maps in this
    // batch position's atlas (copied where it did not hold them: stats.shadows.atlas_texels), or
    // its chain form.
    Program& prepare(LightPrograms& progs, FrameStats& stats);
    void set(Program& prog);  // prog in use, the one prepare() gave
    void unbind() const;

private:
    bool packed_;
    int max_texture_ = 0;
    std::vector<std::unique_ptr<ShadowAtlas>> atlases_;  // by batch position in the frame
    size_t next_ = 0;
    ShadowAtlas* atlas_ = nullptr;  // this batch's; null: the chain
    AtlasLayout layout_;
    std::vector<AtlasRegion> sizes_;
    std::vector<const ShadowLookup*> maps_;
    std::vector<glm::vec4> view_, proj_, params_, size_, region_;  // kept for their storage
    std::vector<glm::vec3> depth_;
};
// The light's parameters with its shadow slot in lightspot.z, a component no light law reads
// (lighting.glsl): the batched shaders' SHADOW forms read it.
LightParams with_shadow_slot(LightParams p, float slot);

// A light program in its three forms (the shader table's rows FAMILY, FAMILY_point and
// FAMILY_point_inverse): each light is drawn by the form of its LightShader, so the type and law
// selection is paid only by the lights that need it; and, where the scene has shadowed lights,
// FAMILY_shadow (any light, with the shadow lookup) for those.
class LightPrograms {
public:
    // shadow_only: just FAMILY_shadow (a geometry that draws only its shadowed lights as quads).
    // shadow_slots: FAMILY_shadow holds that many maps (shadow.glsl SHADOW_SLOTS); 0: one, on unit 4.
    LightPrograms(ProgramSet& programs, const std::string& family, bool shadow_only = false, int shadow_slots = 0);
    // The family's forms compiled anew from `sources` with `extra` defines (a variant the table
    // cannot know in advance: the screen geometry's light count).
    LightPrograms(const ProgramSources& sources, const std::string& family, int shadow_slots, const Defines& extra);
    // set_light_uniforms on every form, before a frame's first draw.
    void begin(const FrameDef& f);
    Program& operator[](LightShader s) { return forms_[int(s)]; }
    // The form that draws light l: the shadow form for a shadowed light, else its LightShader's.
    Program& form(const LightDraw& l) { return l.shadow >= 0 ? shadow_ : forms_[int(l.shader())]; }
    // FAMILY_shadow (id 0 where the table did not build it).
    Program& shadow() { return shadow_; }
    // FAMILY_shadow_atlas: the batched forms' maps in one atlas (id 0 where not built).
    Program& shadow_atlas() { return shadow_atlas_; }
    // The form that serves every light of `lights` (indices into f.lights): their common one, else any.
    static LightShader common(const FrameDef& f, const std::vector<int>& lights);

private:
    template <class Has, class Get>
    void load(const std::string& family, bool shadow_only, Has&& has, Get&& get);
    Program forms_[3];  // LightShader's order: point_linear, point_inverse, any
    Program shadow_;    // FAMILY_shadow, where the table built it
    Program shadow_atlas_;
    int shadow_slots_ = 0;
};

// A batch of f's lights (indices into f.lights) into `arrays`, each light's parameters with its
// shadow slot where the batch holds a shadowed light (`shadows` then holds their maps), and the
// program that draws it: ShadowSlots::prepare's where the batch has maps, else progs' form for
// the batch's lights. The tiles' and screen's batches.
Program& load_batch(const FrameDef& f, const std::vector<int>& batch, LightArrays& arrays, ShadowSlots& shadows,
                    LightPrograms& progs, FrameStats& stats);
// The attenuation constants every light of the batch has, to the bit, or nullopt where they
// differ (or the batch is empty): where they are point lights of the attenuation law, the batched
// shaders' ATT_SHARED form draws them with the constants in one uniform, `att_shared` (a CPU
// rasteriser reads an array at a light's index lane by lane: light_tiles.frag, light_screen.frag).
std::optional<glm::vec3> shared_attenuation(const FrameDef& f, const std::vector<int>& batch);

// A batch's program (load_batch_form) and, where it is the ATT_SHARED form, the constants its
// att_shared uniform takes.
struct BatchForm {
    Program& prog;
    std::optional<glm::vec3> att_shared;
    // The constants into prog, in use; nothing for another form.
    void set_shared() const {
        if (att_shared) prog.set("att_shared", *att_shared);
    }
};

// load_batch, and where its program is progs' attenuation-law point form and the batch's lights
// share their constants, shared_form(): that form built with ATT_SHARED (counted in
// stats.tiles.att_shared_batches). The one choice of the tiles' and screen's batches.
template <class SharedForm>
BatchForm load_batch_form(const FrameDef& f, const std::vector<int>& batch, LightArrays& arrays, ShadowSlots& shadows,
                          LightPrograms& progs, FrameStats& stats, SharedForm&& shared_form) {
    Program& p = load_batch(f, batch, arrays, shadows, progs, stats);
    if (&p != &progs[LightShader::point_inverse]) return BatchForm{p, std::nullopt};
    const std::optional<glm::vec3> att = shared_attenuation(f, batch);
    if (!att) return BatchForm{p, std::nullopt};
    ++stats.tiles.att_shared_batches;
    return BatchForm{shared_form(), att};
}

// The light's quad over its scissor rectangle, through the light's form of "light".
class LightQuads {
public:
    // depth_bounds: EXT_depth_bounds_test on each quad (Paths::depth_bounds). shadow_only: only
    // shadowed lights are drawn (the batched geometries' shadowed lights, light_geometry.cpp).
    LightQuads(ProgramSet& programs, bool depth_bounds, bool shadow_only = false);
    // Before the first quad of a frame: the pixel camera and both programs' frame uniforms.
    void begin(const FrameDef& f);
    // set_light_scissor, then the light shader over the rectangle; one counted pass.
    void draw(const FrameDef& f, const LightDraw& l, LightQueries& q);

private:
    LightPrograms progs_;
    bool depth_bounds_;
};

// The batched geometries' order (LightQuadBatch, LightVolumeBatch): `lights` split by their light
// program's form, and each form's lights in runs of at most `batch`; draw(form, run, n) once a run.
template <class Draw>
void for_each_light_batch(const std::vector<const LightDraw*>& lights, int batch, Draw&& draw) {
    std::vector<const LightDraw*> mine;
    mine.reserve(lights.size());
    for (LightShader form : {LightShader::point_linear, LightShader::point_inverse, LightShader::any}) {
        mine.clear();
        for (const LightDraw* l : lights)
            if (l->shader() == form) mine.push_back(l);
        for (size_t first = 0; first < mine.size(); first += size_t(batch))
            draw(form, mine.data() + first, std::min(mine.size() - first, size_t(batch)));
    }
}

// Many lights' quads in a handful of draws (pseudo-instancing with vertex arrays only, no GL 3
// instancing): the lights in batches of the uniform arrays' size ("light_batch" programs,
// light.frag BATCH), each quad over its light's scissor rectangle carrying the light's slot; one
// draw per batch and program form. The quad covers exactly the pixels the scissored full-screen
// quad lets through, and every light adds the same 8-bit step in any order, so the image is the
// per-light loop's; the CPU submits a few draws instead of one per light.
class LightQuadBatch {
public:
    // batch: lights the arrays hold (ShaderConfig::tile_batch).
    LightQuadBatch(ProgramSet& programs, int batch);
    // Every light of `lights` (of f), each one counted light pass per draw. scene_depth: P-buffer 0
    // holds the scene's depth (the depth hand-off) and the light shaders test a surface against the
    // light's depth span (SkipOptions::light_depth_test): each quad is then drawn at its sphere's
    // back (sphere_back_depth) with GL_GEQUAL, so the surfaces behind the light are rejected
    // before the shader runs, not by it; the pixels lit are the same.
    void draw(const FrameDef& f, const std::vector<const LightDraw*>& lights, LightQueries& q, FrameStats& stats,
              bool scene_depth = false);

private:
    LightPrograms progs_;
    int batch_;
    std::vector<float> verts_;  // kept for its storage
    StreamBuffers buffers_;  // one per batch of a frame
    LightArrays arrays_;
};

}  // namespace dsr
