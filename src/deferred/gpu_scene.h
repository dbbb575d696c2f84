// The scene uploaded once: one vertex buffer, one index buffer, textures with mipmaps,
// and draw ranges grouped by material (Listing 9 draws one range per material).
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "gl/gl.h"
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
};

struct DrawRange {
    GLsizei count = 0;        // indices
    size_t first = 0;         // first index
    int material = 0;
};

// Inverse of decode_shininess in glsl120/lighting.glsl.
float encode_shininess(float shininess);

class GpuScene {
public:
    // pow2_textures: without ARB_texture_non_power_of_two, material maps are rescaled to
    // powers of two (texture coordinates are unchanged: maps repeat).
    explicit GpuScene(const Scene& scene, bool pow2_textures = false);
    ~GpuScene();
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    // Listing 8's array_lock(VERTICES): positions only.
    void bind_positions() const;
    // Listing 9's array_lock(VERTICES|NORMALS|TEXTURE|TANGENT): texcoord 0 = uv,
    // texcoord 1 = tangent, texcoord 2 = binormal (Listing 10's a2v).
    void bind_all() const;
    void unbind() const;
    void draw(const DrawRange& r) const;
    void draw_all() const;

    const std::vector<DrawRange>& ranges() const { return ranges_; }
    // One range per Scene::meshes entry (same index): per-object draws of the forward
    // renderers (Listings 3-4 draw object by object; the deferred passes draw by material).
    const DrawRange& mesh_range(size_t mesh) const { return mesh_ranges_.at(mesh); }
    const GpuMaterial& material(int i) const { return materials_[i]; }
    size_t triangle_count() const { return indices_ / 3; }
    // A 1x1 tangent-space normal map pointing straight out (128,128,255): what a material
    // without a map reads when the shader variants are off.
    GLuint flat_normal() const { return flat_normal_.id(); }

private:
    GLuint vbo_ = 0, ibo_ = 0;
    size_t indices_ = 0;
    std::vector<Texture> textures_;
    Texture white_, flat_normal_;
    std::vector<GpuMaterial> materials_;
    std::vector<DrawRange> ranges_;
    std::vector<DrawRange> mesh_ranges_;
};

}  // namespace dsr
