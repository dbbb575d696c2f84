// glTF materials as dsr's metallic-roughness materials (gltf_internal.h; the mapping is the table
// in docs/gltf.md, "Materials"; the BRDF is docs/metal_rough.md's), their textures decoded
// through decode_image within the texel budget, each (image, sampler, bake) once.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include "scene/gltf_internal.h"
#include "scene/user_file.h"

namespace dsr::gltf {

using nlohmann::json;
using std::string;

namespace {

namespace fs = std::filesystem;

// A URI's %XX escapes decoded; a scheme ("http:") refused.
string uri_to_path(const Context& ctx, const string& uri, const string& ptr) {
    const size_t colon = uri.find(':'), slash = uri.find('/');
    if (colon != string::npos && (slash == string::npos || colon < slash) && colon > 1)
        ctx.fail(ptr, "expected a relative file name or a data URI, got " + quote(uri));
    string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit((unsigned char)uri[i + 1]) &&
            std::isxdigit((unsigned char)uri[i + 2])) {
            out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    if (out.find('\0') != string::npos) ctx.fail(ptr, "expected a file name, got a NUL byte in " + quote(uri));
    fs::path p(out);
    if (p.is_relative()) p = fs::path(ctx.dir) / p;
    return p.lexically_normal().string();
}

// Roles a texture is read for; each bakes its image differently.
enum class Role { base_colour, normal, metallic_roughness, emissive, occlusion };

struct Textures {
    std::map<string, int> index;  // "image:sampler:role:params" -> ctx.out.textures
    size_t texels = 0;
    std::map<int, Image> decoded;  // glTF image -> pixels, while materials are read
};

Image read_image(Context& ctx, Textures& t, int image, const string& user) {
    if (auto it = t.decoded.find(image); it != t.decoded.end()) return it->second;
    const tinygltf::Image& im = ctx.tm.images[size_t(image)];
    const string ptr = "/images/" + std::to_string(image);
    string bytes, name;
    if (!im.uri.empty() && im.uri.compare(0, 5, "data:") != 0) {
        name = uri_to_path(ctx, im.uri, ptr + "/uri");
        try {
            bytes = ctx.options.read_file(name);
        } catch (const Error& e) {
            ctx.fail(ptr + "/uri", string("expected a readable image file, got ") + quote(im.uri) + ": " + e.what());
        }
        ctx.out.inputs.push_back(name);
    } else {
        name = ctx.path + "#" + ptr;
        bytes.assign(im.image.begin(), im.image.end());
    }
    const size_t left = ctx.options.max_texels > t.texels ? ctx.options.max_texels - t.texels : 0;
    Image img;
    try {
        img = decode_image(bytes, name, left);
    } catch (const ImageTooLarge& e) {
        ctx.fail(ptr, "expected textures within " +
                          (ctx.options.budget_note.empty() ? std::to_string(ctx.options.max_texels) + " texels"
                                                           : ctx.options.budget_note) +
                          ", got " + std::to_string(size_t(e.width) * size_t(e.height)) + " (" + std::to_string(e.width) +
                          " x " + std::to_string(e.height) + ") for " + user + " after " + std::to_string(t.texels));
    } catch (const Error& e) {
        ctx.fail(ptr, string("expected a readable image for ") + user + ", got: " + e.what());
    }
    if (img.width <= 0 || img.height <= 0 || img.rgba.size() != size_t(img.width) * size_t(img.height) * 4)
        ctx.fail(ptr, "expected an image with pixels, got none");
    for (float f : img.rgba)
        if (!std::isfinite(f)) ctx.fail(ptr, "expected finite texel values");
    t.decoded[image] = img;
    return img;
}

TextureSampling sampling(const Context& ctx, int sampler, const string& ptr) {
    TextureSampling s;
    if (sampler < 0) return s;
    if (size_t(sampler) >= ctx.tm.samplers.size())
        ctx.fail(ptr + "/sampler", "expected a sampler index below " + std::to_string(ctx.tm.samplers.size()) + ", got " +
                                       std::to_string(sampler));
    const tinygltf::Sampler& sm = ctx.tm.samplers[size_t(sampler)];
    const string sp = "/samplers/" + std::to_string(sampler);
    auto wrap = [&](int w, const char* key) {
        switch (w) {
        case -1:
        case TINYGLTF_TEXTURE_WRAP_REPEAT: return TextureSampling::Wrap::repeat;
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureSampling::Wrap::clamp;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureSampling::Wrap::mirror;
        }
        ctx.fail(sp + "/" + key, "expected 10497, 33071 or 33648, got " + std::to_string(w));
    };
    s.wrap_s = wrap(sm.wrapS, "wrapS");
    s.wrap_t = wrap(sm.wrapT, "wrapT");
    switch (sm.magFilter) {
    case -1: case TINYGLTF_TEXTURE_FILTER_LINEAR: break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST: s.nearest_mag = true; break;
    default: ctx.fail(sp + "/magFilter", "expected 9728 or 9729, got " + std::to_string(sm.magFilter));
    }
    switch (sm.minFilter) {
    case -1: case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR: break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST: s.nearest_min = true; s.mipmaps = false; break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR: s.mipmaps = false; break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST: s.nearest_min = true; break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST: break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR: s.nearest_min = true; break;
    default: ctx.fail(sp + "/minFilter", "expected 9728, 9729 or 9984 to 9987, got " + std::to_string(sm.minFilter));
    }
    return s;
}

// The glTF image of texture `tex`, checked; -1 (with a warning) where it has none dsr reads.
int texture_source(Context& ctx, int tex, const string& ptr) {
    if (tex < 0 || size_t(tex) >= ctx.tm.textures.size())
        ctx.fail(ptr + "/index", "expected a texture index below " + std::to_string(ctx.tm.textures.size()) + ", got " +
                                     std::to_string(tex));
    const tinygltf::Texture& t = ctx.tm.textures[size_t(tex)];
    if (t.source < 0) {
        ctx.warn(ptr, "texture " + std::to_string(tex) + " has no source image dsr reads: the map is left out");
        return -1;
    }
    if (size_t(t.source) >= ctx.tm.images.size())
        ctx.fail("/textures/" + std::to_string(tex) + "/source",
                 "expected an image index below " + std::to_string(ctx.tm.images.size()) + ", got " + std::to_string(t.source));
    return t.source;
}

// A dsr texture for texture `tex` in `role`: the image baked by `bake` (identity when empty), once
// per distinct key. -1 when the texture has no source.
template <class Bake>
int texture(Context& ctx, Textures& t, int tex, const string& ptr, Role role, const string& params, Bake bake) {
    const int src = texture_source(ctx, tex, ptr);
    if (src < 0) return -1;
    const tinygltf::Texture& gt = ctx.tm.textures[size_t(tex)];
    TextureSampling s = sampling(ctx, gt.sampler, "/textures/" + std::to_string(tex));
    s.srgb = role == Role::base_colour || role == Role::emissive;
    const string key = std::to_string(src) + ":" + std::to_string(gt.sampler) + ":" + std::to_string(int(role)) + ":" + params;
    if (auto it = t.index.find(key); it != t.index.end()) return it->second;
    Image img = read_image(ctx, t, src, ptr);
    const size_t n = size_t(img.width) * size_t(img.height);
    if (n > ctx.options.max_texels - std::min(ctx.options.max_texels, t.texels))
        ctx.fail(ptr, "expected textures within " +
                          (ctx.options.budget_note.empty() ? std::to_string(ctx.options.max_texels) + " texels"
                                                           : ctx.options.budget_note) +
                          ", got /images/" + std::to_string(src) + " of " + std::to_string(n) + " (" +
                          std::to_string(img.width) + " x " + std::to_string(img.height) + ") after " + std::to_string(t.texels));
    t.texels += n;
    bake(img);
    ctx.out.textures.push_back(std::move(img));
    ctx.out.texture_paths.push_back(ctx.tm.images[size_t(src)].uri.empty() || ctx.tm.images[size_t(src)].uri.compare(0, 5, "data:") == 0
                                        ? ctx.path + "#/images/" + std::to_string(src)
                                        : uri_to_path(ctx, ctx.tm.images[size_t(src)].uri, "/images/" + std::to_string(src) + "/uri"));
    ctx.out.texture_sampling.push_back(s);
    const int index = int(ctx.out.textures.size() - 1);
    t.index[key] = index;
    return index;
}

// The KHR_texture_transform of a textureInfo, as a matrix in glTF's uv space, and its texCoord override.
struct UvTransform {
    bool present = false;
    glm::dmat3 m{1.0};
    int tex_coord = -1;
};
UvTransform uv_transform(const Context& ctx, const string& ptr) {
    UvTransform u;
    const json* x = ctx.at(ptr + "/extensions/KHR_texture_transform");
    if (!x) return u;
    u.present = true;
    glm::dvec2 offset(0), scale(1);
    double rotation = 0;
    if (auto it = x->find("offset"); it != x->end()) offset = {(*it)[0].get<double>(), (*it)[1].get<double>()};
    if (auto it = x->find("scale"); it != x->end()) scale = {(*it)[0].get<double>(), (*it)[1].get<double>()};
    if (auto it = x->find("rotation"); it != x->end()) rotation = it->get<double>();
    if (auto it = x->find("texCoord"); it != x->end()) u.tex_coord = it->get<int>();
    const double c = std::cos(rotation), s = std::sin(rotation);
    const glm::dmat3 t(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    const glm::dmat3 r(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::dmat3 sc(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    u.m = t * r * sc;
    return u;
}

void check_unit(const Context& ctx, double v, const string& ptr) {
    if (!(v >= 0 && v <= 1)) ctx.fail(ptr, "expected a number in [0, 1], got " + num(v));
}

}  // namespace

std::vector<MaterialUse> read_materials(Context& ctx) {
    Textures t;
    std::vector<MaterialUse> uses;
    const string file = fs::path(ctx.path).filename().string();
    for (size_t i = 0; i <= ctx.tm.materials.size(); ++i) {
        Material m;
        MaterialUse use;
        m.model = Material::Model::metallic_roughness;
        m.specular = glm::vec3(0);  // unused by the model; the forward stage's Phong sees no highlight
        if (i == ctx.tm.materials.size()) {
            // The glTF default material: white, metallic 1, roughness 1.
            m.name = file + ":(default)";
            m.diffuse = glm::vec3(1);
            ctx.out.materials.push_back(m);
            uses.push_back(use);
            break;
        }
        const tinygltf::Material& g = ctx.tm.materials[i];
        const string mp = "/materials/" + std::to_string(i);
        const string pp = mp + "/pbrMetallicRoughness";
        m.name = file + ":" + (g.name.empty() ? "#" + std::to_string(i) : g.name);
        const auto& pbr = g.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() != 4) ctx.fail(pp + "/baseColorFactor", "expected 4 numbers");
        for (int c = 0; c < 4; ++c) check_unit(ctx, pbr.baseColorFactor[size_t(c)], pp + "/baseColorFactor/" + std::to_string(c));
        check_unit(ctx, pbr.metallicFactor, pp + "/metallicFactor");
        check_unit(ctx, pbr.roughnessFactor, pp + "/roughnessFactor");
        const glm::dvec3 base(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]);
        const double alpha = pbr.baseColorFactor[3];
        m.diffuse = glm::vec3(base);
        m.metallic = float(pbr.metallicFactor);
        m.roughness = float(pbr.roughnessFactor);
        use.double_sided = g.doubleSided;

        // Which uv set and transform the maps read: the base colour texture's, else the normal
        // map's, else the metallic-roughness map's.
        UvTransform chosen;
        bool have_uv = false;
        auto note_uv = [&](int index, int tex_coord, const string& ptr) {
            if (index < 0) return;
            const UvTransform u = uv_transform(ctx, ptr);
            const int set = u.tex_coord >= 0 ? u.tex_coord : tex_coord;
            if (set < 0 || set > 1)
                ctx.fail(ptr + "/texCoord", "expected TEXCOORD_0 or TEXCOORD_1 (0 or 1), got " + std::to_string(set));
            if (!have_uv) {
                have_uv = true;
                use.uv_set = set;
                chosen = u;
            } else {
                if (set != use.uv_set)
                    ctx.warn(ptr, "this map reads TEXCOORD_" + std::to_string(set) + ", the material's first map TEXCOORD_" +
                                      std::to_string(use.uv_set) + ": dsr has one uv set per vertex and uses the first");
                if (u.present != chosen.present || u.m != chosen.m)
                    ctx.warn(ptr, "this map's KHR_texture_transform differs from the material's first map's: dsr bakes the first into the uvs");
            }
        };
        note_uv(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, pp + "/baseColorTexture");
        note_uv(g.normalTexture.index, g.normalTexture.texCoord, mp + "/normalTexture");
        note_uv(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord, pp + "/metallicRoughnessTexture");
        note_uv(g.occlusionTexture.index, g.occlusionTexture.texCoord, mp + "/occlusionTexture");
        note_uv(g.emissiveTexture.index, g.emissiveTexture.texCoord, mp + "/emissiveTexture");
        use.has_transform = chosen.present;
        use.uv_transform = chosen.m;
        use.needs_uvs = have_uv;

        // Alpha.
        const string& mode = g.alphaMode;
        if (mode == "MASK") {
            if (!(g.alphaCutoff >= 0)) ctx.fail(mp + "/alphaCutoff", "expected a number >= 0, got " + num(g.alphaCutoff));
            m.alpha_cutoff = float(g.alphaCutoff);
        } else if (mode == "BLEND") {
            m.opacity = float(alpha);
        } else if (mode != "OPAQUE" && !mode.empty()) {
            ctx.fail(mp + "/alphaMode", "expected OPAQUE, MASK or BLEND, got " + quote(mode));
        }

        if (pbr.baseColorTexture.index >= 0) {
            const string ptr = pp + "/baseColorTexture";
            m.diffuse_map = texture(ctx, t, pbr.baseColorTexture.index, ptr, Role::base_colour, "", [&](Image& img) {
                if (mode == "BLEND") {
                    bool varies = false;
                    for (size_t k = 3; k < img.rgba.size() && !varies; k += 4) varies = img.rgba[k] < 1.0f;
                    if (varies)
                        ctx.warn(ptr, "alphaMode BLEND with a per-texel alpha: dsr's forward stage uses one opacity per "
                                      "material, baseColorFactor's alpha " + num(alpha));
                }
            });
        }
        if (g.normalTexture.index >= 0) {
            const string ptr = mp + "/normalTexture";
            const double scale = g.normalTexture.scale;
            if (!std::isfinite(scale)) ctx.fail(ptr + "/scale", "expected a finite number");
            m.normal_map = texture(ctx, t, g.normalTexture.index, ptr, Role::normal, num(scale), [&](Image& img) {
                if (scale == 1.0) return;
                // glTF: n = normalize((2c - 1) * vec3(scale, scale, 1)); stored back as n / 2 + 1/2.
                for (size_t k = 0; k < img.rgba.size(); k += 4) {
                    glm::dvec3 n(2.0 * img.rgba[k] - 1.0, 2.0 * img.rgba[k + 1] - 1.0, 2.0 * img.rgba[k + 2] - 1.0);
                    n.x *= scale;
                    n.y *= scale;
                    const double l = glm::length(n);
                    n = l > 0 ? n / l : glm::dvec3(0, 0, 1);
                    for (int c = 0; c < 3; ++c) img.rgba[k + size_t(c)] = float(n[c] * 0.5 + 0.5);
                }
            });
        }
        if (pbr.metallicRoughnessTexture.index >= 0)  // roughness in green, metallic in blue, as stored
            m.metallic_roughness_map = texture(ctx, t, pbr.metallicRoughnessTexture.index, pp + "/metallicRoughnessTexture",
                                               Role::metallic_roughness, "", [](Image&) {});
        if (g.emissiveFactor.size() == 3) {
            for (size_t c = 0; c < 3; ++c)
                if (!(g.emissiveFactor[c] >= 0))
                    ctx.fail(mp + "/emissiveFactor/" + std::to_string(c), "expected a number >= 0, got " + num(g.emissiveFactor[c]));
            m.emissive = glm::vec3(float(g.emissiveFactor[0]), float(g.emissiveFactor[1]), float(g.emissiveFactor[2]));
        } else if (!g.emissiveFactor.empty()) {
            ctx.fail(mp + "/emissiveFactor", "expected 3 numbers");
        }
        if (g.emissiveTexture.index >= 0)
            m.emissive_map = texture(ctx, t, g.emissiveTexture.index, mp + "/emissiveTexture", Role::emissive, "", [](Image&) {});
        if (g.occlusionTexture.index >= 0) {
            const string ptr = mp + "/occlusionTexture";
            check_unit(ctx, g.occlusionTexture.strength, ptr + "/strength");
            m.occlusion_strength = float(g.occlusionTexture.strength);
            m.occlusion_map = texture(ctx, t, g.occlusionTexture.index, ptr, Role::occlusion, "", [](Image&) {});
        }
        ctx.out.materials.push_back(m);
        uses.push_back(use);
    }
    return uses;
}

}  // namespace dsr::gltf
