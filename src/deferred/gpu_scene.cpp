#include "deferred/gpu_scene.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "gl/check.h"
#include "gl/state.h"
#include "gl/vertex_arrays.h"

namespace dsr {

float srgb_to_linear(float c) {
    // IEC 61966-2-1: linear below 0.04045, else ((c + 0.055) / 1.055)^2.4. The 8-bit code first,
    // as EXT_texture_sRGB decodes the stored byte.
    c = std::round(std::clamp(c, 0.0f, 1.0f) * 255.0f) / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

float encode_shininess(float shininess) {
    return std::clamp(std::log2(std::max(shininess, 1.0f)) / 11.0f, 0.0f, 1.0f);
}

// A texel index outside [0, n) as the map's wrap mode reads it.
static int wrap_index(int i, int n, TextureSampling::Wrap w) {
    switch (w) {
    case TextureSampling::Wrap::clamp: return std::clamp(i, 0, n - 1);
    case TextureSampling::Wrap::mirror: {
        const int p = ((i % (2 * n)) + 2 * n) % (2 * n);
        return p < n ? p : 2 * n - 1 - p;
    }
    case TextureSampling::Wrap::repeat: break;
    }
    return ((i % n) + n) % n;
}

// Bilinear resample, reading past the edges as the map's wrap modes do (material maps tile by
// default), for GPUs without NPOT textures.
static Image resample_wrapped(const Image& src, int w, int h, const TextureSampling& ts) {
    Image dst;
    dst.width = w;
    dst.height = h;
    dst.rgba.resize(size_t(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float fx = (x + 0.5f) * src.width / w - 0.5f, fy = (y + 0.5f) * src.height / h - 0.5f;
            int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
            float ax = fx - x0, ay = fy - y0;
            auto px = [&](int xx, int yy) {
                return src.at(wrap_index(xx, src.width, ts.wrap_s), wrap_index(yy, src.height, ts.wrap_t));
            };
            for (int c = 0; c < 4; ++c)
                dst.at(x, y)[c] = (1 - ay) * ((1 - ax) * px(x0, y0)[c] + ax * px(x0 + 1, y0)[c]) +
                                  ay * ((1 - ax) * px(x0, y0 + 1)[c] + ax * px(x0 + 1, y0 + 1)[c]);
        }
    return dst;
}

static GLint gl_wrap(TextureSampling::Wrap w) {
    switch (w) {
    case TextureSampling::Wrap::clamp: return GL_CLAMP_TO_EDGE;
    case TextureSampling::Wrap::mirror: return GL_MIRRORED_REPEAT;
    case TextureSampling::Wrap::repeat: break;
    }
    return GL_REPEAT;
}

// The map's TextureSampling on the bound texture (mipmaps were generated where ts.mipmaps).
static void set_sampling(const TextureSampling& ts) {
    const GLint min = ts.mipmaps ? (ts.nearest_min ? GL_NEAREST_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_LINEAR)
                                 : (ts.nearest_min ? GL_NEAREST : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, ts.nearest_mag ? GL_NEAREST : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, gl_wrap(ts.wrap_s));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, gl_wrap(ts.wrap_t));
}

static bool is_pow2(int v) { return v > 0 && (v & (v - 1)) == 0; }

GpuScene::GpuScene(const Scene& scene, bool pow2_textures, ColourMaps colour_maps) {
    // Every mesh once, in object space (instances of one OBJ group share it).
    std::vector<Vertex> verts;
    std::vector<uint32_t> idx;
    // Per-vertex colours where any mesh has them (white for the others), else no colour buffer.
    const auto has_colors = [](const Mesh& m) { return !m.colors.empty() && m.colors.size() == m.vertices.size(); };
    bool any_colors = false;
    for (const Mesh& m : scene.meshes) any_colors = any_colors || has_colors(m);
    std::vector<glm::vec4> colors;
    std::vector<std::pair<size_t, GLsizei>> mesh_at(scene.meshes.size());  // first index, count
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        const uint32_t base = uint32_t(verts.size());
        mesh_at[m] = {idx.size(), GLsizei(mesh.indices.size())};
        verts.insert(verts.end(), mesh.vertices.begin(), mesh.vertices.end());
        if (any_colors && has_colors(mesh)) colors.insert(colors.end(), mesh.colors.begin(), mesh.colors.end());
        else if (any_colors) colors.resize(verts.size(), glm::vec4(1));
        for (uint32_t i : mesh.indices) idx.push_back(base + i);
    }
    uploaded_vertices_ = verts.size();
    // One draw per object, ordered by material so a material's state is set once (Listing 9).
    object_ranges_.resize(scene.objects.size());
    models_.resize(scene.objects.size());
    modelviews_.assign(scene.objects.size(), glm::mat4(1));
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& obj = scene.objects[o];
        const auto [first, count] = mesh_at.at(obj.mesh);
        object_ranges_[o] = {count, first, obj.material, o};
        object_ranges_[o].two_sided = obj.two_sided;
        object_ranges_[o].colors = has_colors(scene.meshes.at(obj.mesh));
        object_ranges_[o].cut_out = scene.materials.at(size_t(obj.material)).cut_out();
        models_[o] = obj.model;
        triangles_ += size_t(count) / 3;
    }
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        if (scene.materials.at(size_t(scene.objects[o].material)).transparent()) transparent_.push_back(o);
        else ranges_.push_back(object_ranges_[o]);
    }
    // Cut-outs after the others (their depth comes from the material pass), each part by material.
    std::stable_sort(ranges_.begin(), ranges_.end(), [](const DrawRange& a, const DrawRange& b) {
        return a.cut_out != b.cut_out ? b.cut_out : a.material < b.material;
    });
    solid_ranges_ = size_t(std::find_if(ranges_.begin(), ranges_.end(), [](const DrawRange& r) { return r.cut_out; }) -
                           ranges_.begin());
    glGenBuffers(1, &vbo_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, verts.size() * sizeof(Vertex), verts.data(), GL_STATIC_DRAW);
    glGenBuffers(1, &ibo_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, idx.size() * sizeof(uint32_t), idx.data(), GL_STATIC_DRAW);
    if (any_colors) {
        glGenBuffers(1, &cbo_);
        glBindBuffer(GL_ARRAY_BUFFER, cbo_);
        glBufferData(GL_ARRAY_BUFFER, colors.size() * sizeof(glm::vec4), colors.data(), GL_STATIC_DRAW);
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);

    // Material maps: RGBA8 with mipmaps, repeating (tile > 1 wraps, Listing 13). With --textures
    // srgb the diffuse (base colour) and emissive maps (only they hold colour) are decoded (ColourMaps).
    std::vector<bool> colour(scene.textures.size(), false);
    if (colour_maps != ColourMaps::as_stored)
        for (const Material& m : scene.materials)
            for (int map : {m.diffuse_map, m.emissive_map})
                if (map >= 0) colour.at(size_t(map)) = true;
    for (size_t t = 0; t < scene.textures.size(); ++t) {
        const Image& img = scene.textures[t];
        // A map without sampling of its own keeps the defaults (and the path it always took).
        const TextureSampling ts = t < scene.texture_sampling.size() ? scene.texture_sampling[t] : TextureSampling{};
        const bool sampled_as_ever = ts == TextureSampling{};
        Image r;
        const Image* up = &img;
        if (pow2_textures && !(is_pow2(img.width) && is_pow2(img.height))) {
            int w = 1, h = 1;
            while (w * 2 <= img.width) w *= 2;  // nearest power of two at or below
            while (h * 2 <= img.height) h *= 2;
            r = resample_wrapped(img, w, h, ts);
            up = &r;
        }
        GLenum internal = GL_RGBA8;
        Image decoded;
        if ((colour[t] || ts.srgb) && colour_maps == ColourMaps::srgb_texture) {
            internal = GL_SRGB8_ALPHA8;  // stored as the file's codes, decoded by the GL when sampled
        } else if (colour[t] || ts.srgb) {
            decoded = *up;  // decoded here; alpha is linear in sRGB images
            for (size_t i = 0; i < decoded.rgba.size(); ++i)
                if (i % 4 != 3) decoded.rgba[i] = srgb_to_linear(decoded.rgba[i]);
            up = &decoded;
            internal = GL_RGBA16;
        }
        textures_.emplace_back(up->width, up->height, internal, GL_RGBA, GL_FLOAT, up->rgba.data(), GL_LINEAR, GL_REPEAT,
                               ts.mipmaps);
        if (!sampled_as_ever) {
            glBindTexture(GL_TEXTURE_2D, textures_.back().id());
            set_sampling(ts);
            glBindTexture(GL_TEXTURE_2D, 0);
        }
    }
    // A missing diffuse or specular map is a white texel: map x colour = colour exactly.
    const float one[4] = {1, 1, 1, 1};
    white_ = Texture(1, 1, GL_RGBA8, GL_RGBA, GL_FLOAT, one, GL_NEAREST, GL_REPEAT);
    const unsigned char flat[4] = {128, 128, 255, 255};
    flat_normal_ = Texture(1, 1, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, flat, GL_NEAREST, GL_REPEAT);
    for (const Material& m : scene.materials) {
        GpuMaterial g;
        g.diffuse = m.diffuse;
        g.specular = m.specular;
        g.shininess_code = encode_shininess(m.shininess);
        g.tile = m.tile;
        g.opacity = m.opacity;
        g.alpha_cutoff = m.alpha_cutoff;
        g.diffuse_tex = m.diffuse_map >= 0 ? textures_[m.diffuse_map].id() : white_.id();
        g.specular_tex = m.specular_map >= 0 ? textures_[m.specular_map].id() : white_.id();
        g.normal_map = m.normal_map >= 0;
        g.has_specular = m.specular.r > 0 || m.specular.g > 0 || m.specular.b > 0;
        g.normal_tex = g.normal_map ? textures_[m.normal_map].id() : white_.id();
        g.occlusion_tex = g.emissive_tex = white_.id();
        if (m.metal_rough()) {
            g.metal_rough = true;
            g.specular = glm::vec3(m.metallic, m.roughness, m.occlusion_strength);
            g.has_specular = true;  // target 2 holds metallic and roughness: no NO_SPECULAR form
            g.specular_tex = m.metallic_roughness_map >= 0 ? textures_[m.metallic_roughness_map].id() : white_.id();
            if (m.occlusion_map >= 0) g.occlusion_tex = textures_[m.occlusion_map].id();
            if (m.emissive_map >= 0) g.emissive_tex = textures_[m.emissive_map].id();
            g.emissive = m.emissive;
        }
        materials_.push_back(g);
    }
    check_gl("uploading the scene");
}

GpuScene::~GpuScene() {
    glDeleteBuffers(1, &vbo_);
    glDeleteBuffers(1, &ibo_);
    if (cbo_) glDeleteBuffers(1, &cbo_);
}

void GpuScene::bind_positions() const {
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
    vertex_array(3, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, pos)));
}

void GpuScene::bind_all() const {
    bind_positions();
    normal_array(sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, normal)));
    const size_t offs[3] = {offsetof(Vertex, uv), offsetof(Vertex, tangent), offsetof(Vertex, binormal)};
    const int sizes[3] = {2, 3, 3};
    for (int i = 0; i < 3; ++i) texcoord_array(i, sizes[i], sizeof(Vertex), reinterpret_cast<void*>(offs[i]));
    if (cbo_) {
        glBindBuffer(GL_ARRAY_BUFFER, cbo_);
        color_array(sizeof(glm::vec4), nullptr);
        glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    }
}

void GpuScene::unbind() const {
    if (cbo_) disable_color_array();
    for (int i = 0; i < 3; ++i) disable_texcoord_array(i);
    disable_normal_array();
    disable_vertex_array();
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

void GpuScene::set_view(const glm::dmat4& view) {
    for (size_t o = 0; o < models_.size(); ++o) modelviews_[o] = camera_relative(view, models_[o]);
}

void GpuScene::draw(const DrawRange& r) const {
    gl_state().set_modelview(modelviews_[r.object]);
    glDrawElements(GL_TRIANGLES, r.count, GL_UNSIGNED_INT, reinterpret_cast<void*>(r.first * sizeof(uint32_t)));
}

void GpuScene::draw_all() const {
    const RenderState pass = gl_state().current();
    for (size_t i = 0; i < solid_ranges_; ++i) {
        gl_state().apply(faces_state(pass, ranges_[i]));
        draw(ranges_[i]);
    }
    gl_state().apply(pass);
}

}  // namespace dsr
