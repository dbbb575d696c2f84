// The scene uploaded once: one vertex buffer and one index buffer holding every mesh once, in
// object space, textures with mipmaps, and the objects' draws ordered by material (Listing 9
// draws the faces grouped by material: one draw call per material group of each object).
// Each draw loads its own modelview, composed with the camera in double (set_view).
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "gl/gl.h"
#include "gl/state.h"
#include "gl/texture.h"
#include "scene/scene.h"

namespace dsr {

struct GpuMaterial {
    glm::vec3 diffuse{1}, specular{0};
    float shininess_code = 0;  // log2(M_shi)/11, what the specular target's alpha holds
    float tile = 1;
    GLuint diffuse_tex = 0, normal_tex = 0, specular_tex = 0;
    bool normal_map = false;
    bool has_specular = true;  // false: M_spec is zero, the specular target is zero
    float opacity = 1;         // below 1: transparent, drawn by the forward stage (docs/forward.md)
    float alpha_cutoff = 0;    // above 0: cut-out, coverage below it discarded (Material::alpha_cutoff)
    // Metallic-roughness (Material::Model): `diffuse` is the base colour, `specular` holds
    // (metallic, roughness, occlusion strength), specular_tex the metallic-roughness map.
    bool metal_rough = false;
    glm::vec3 emissive{0};
    GLuint occlusion_tex = 0, emissive_tex = 0;
};

// --textures srgb: the diffuse maps decoded from sRGB to linear when sampled, by the GL
// (EXT_texture_sRGB: GL_SRGB8_ALPHA8) or on upload (into GL_RGBA16, where 8 linear bits would band
// the dark end); as_stored: RGBA8, as the tutorial.
enum class ColourMaps { as_stored, srgb_texture, decoded_on_upload };

// What a surface brings beyond the tutorial's (scene.h), as bits of DrawRange::surface(): each
// picks a shader form by a define (shader_table.h surface_defines), so a surface without them
// draws with the programs it always had.
enum SurfaceBits {
    kSurfaceTwoSided = 1,  // Object::two_sided: no culling, a back face's normal flipped
    kSurfaceColors = 2,    // Mesh::colors: per-vertex RGBA multiplies diffuse and coverage
    kSurfaceCutOut = 4,    // Material::alpha_cutoff > 0: coverage below it discarded
    kSurfaceForms = 8,     // how many combinations
};
// The material pass's form for a metallic-roughness material (material.frag METAL_ROUGH_MATERIAL),
// beside the surface bits: the geometry stage adds it, DrawRange::surface() does not carry it.
constexpr int kMaterialMetalRough = 16;

struct DrawRange {
    GLsizei count = 0;        // indices
    size_t first = 0;         // first index
    int material = 0;
    size_t object = 0;        // index into Scene::objects
    bool two_sided = false;   // the object's
    bool colors = false;      // its mesh has per-vertex colours
    bool cut_out = false;     // its material's
    int surface() const {
        return (two_sided ? kSurfaceTwoSided : 0) | (colors ? kSurfaceColors : 0) | (cut_out ? kSurfaceCutOut : 0);
    }
};

// A pass's state for one draw: the pass's own, with back faces kept for a two-sided surface.
inline RenderState faces_state(RenderState s, const DrawRange& r) {
    if (r.two_sided) s.cull = false;
    return s;
}

// IEC 61966-2-1's decoding of a value stored as an 8-bit sRGB code (rounded to one first).
float srgb_to_linear(float c);

// Inverse of decode_shininess in glsl120/lighting.glsl.
float encode_shininess(float shininess);

class GpuScene {
public:
    // pow2_textures: without ARB_texture_non_power_of_two, material maps are rescaled to
    // powers of two (texture coordinates are unchanged: maps repeat).
    // colour_maps: how the diffuse maps are stored (--textures, docs/hdr.md); normal and specular
    // maps are uploaded as they are, unless the scene's TextureSampling says a map is sRGB-encoded:
    // that map is decoded whatever colour_maps says (by the GL where colour_maps is srgb_texture,
    // which found EXT_texture_sRGB, else on upload into GL_RGBA16). Each map is sampled with its
    // TextureSampling (wrap, filters, mipmaps); without one, repeating with trilinear mipmaps.
    explicit GpuScene(const Scene& scene, bool pow2_textures = false, ColourMaps colour_maps = ColourMaps::as_stored);
    ~GpuScene();
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    // Listing 8's array_lock(VERTICES): positions only.
    void bind_positions() const;
    // Listing 9's array_lock(VERTICES|NORMALS|TEXTURE|TANGENT): texcoord 0 = uv,
    // texcoord 1 = tangent, texcoord 2 = binormal (Listing 10's a2v); and where a mesh has
    // per-vertex colours, the colour array (white for the meshes without; unbind() sets the current
    // colour back to white).
    void bind_all() const;
    void unbind() const;
    // The camera for the draws that follow: every object's modelview = view * model in double,
    // rounded to float once (camera_relative in scene/scene.h).
    void set_view(const glm::dmat4& view);
    // Loads r's object's modelview (GL_MODELVIEW) and draws its indices.
    void draw(const DrawRange& r) const;
    // Every opaque object that is not a cut-out (ranges() up to solid_ranges()), positions only
    // is enough (the depth pre-pass, Listing 8): under the state the caller applied, with culling
    // off for the two-sided ones (that state applied again after).
    void draw_all() const;

    // The opaque objects' draws, ordered by material (stable: scene order within a material):
    // what the G-buffer holds. Objects with a transparent material (opacity < 1) are left out.
    // Cut-out objects come last, after solid_ranges() others (each part by material): their depth
    // is laid down by the material pass, where they discard (geometry_stage.cpp).
    const std::vector<DrawRange>& ranges() const { return ranges_; }
    size_t solid_ranges() const { return solid_ranges_; }
    bool has_cut_outs() const { return solid_ranges_ < ranges_.size(); }
    // The objects with a transparent material, in scene order (the forward pass sorts them).
    const std::vector<size_t>& transparent_objects() const { return transparent_; }
    bool transparent(size_t object) const { return materials_[size_t(object_ranges_.at(object).material)].opacity < 1; }
    // The draw of Scene::objects[object]: per-object draws of the forward renderers
    // (Listings 3-4 draw object by object; the deferred passes draw by material).
    const DrawRange& object_range(size_t object) const { return object_ranges_.at(object); }
    size_t object_count() const { return object_ranges_.size(); }
    const GpuMaterial& material(int i) const { return materials_[i]; }
    size_t triangle_count() const { return triangles_; }  // drawn, over objects
    size_t uploaded_vertices() const { return uploaded_vertices_; }  // in the vertex buffer: each mesh once
    // A 1x1 tangent-space normal map pointing straight out (128,128,255): what a material
    // without a map reads when the shader variants are off.
    GLuint flat_normal() const { return flat_normal_.id(); }

private:
    GLuint vbo_ = 0, ibo_ = 0;
    GLuint cbo_ = 0;  // per-vertex colours, parallel to vbo_; 0 where no mesh has them
    size_t triangles_ = 0, uploaded_vertices_ = 0;
    std::vector<glm::dmat4> models_;     // per object
    std::vector<glm::mat4> modelviews_;  // per object, from set_view
    std::vector<Texture> textures_;
    Texture white_, flat_normal_;
    std::vector<GpuMaterial> materials_;
    std::vector<DrawRange> ranges_;
    size_t solid_ranges_ = 0;
    std::vector<DrawRange> object_ranges_;
    std::vector<size_t> transparent_;
};

}  // namespace dsr
