// The glTF reader's look at the raw JSON (gltf_internal.h), before tinygltf parses it: tinygltf
// skips members of the wrong type, truncates integers to int and follows image buffer views
// without a bound check, so those are refused here, each with its JSON pointer.
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "scene/gltf_internal.h"
#include "scene/user_file.h"

namespace dsr::gltf {

using nlohmann::json;
using std::string;

namespace {

enum class T { object, uint, number, string, boolean, uints, numbers, objects, strings, texinfo };

// A member's pointer with '*' for any array index or object key, its type, whether its parent
// must have it, and for number arrays the length (0: any).
struct Rule {
    const char* pattern;
    T type;
    bool required = false;
    int length = 0;
};

const std::vector<Rule>& rules() {
    static const std::vector<Rule> r = {
        {"/asset", T::object, true},
        {"/asset/version", T::string, true},
        {"/scene", T::uint},
        {"/scenes", T::objects},
        {"/scenes/*/nodes", T::uints},
        {"/nodes", T::objects},
        {"/nodes/*/children", T::uints},
        {"/nodes/*/mesh", T::uint},
        {"/nodes/*/camera", T::uint},
        {"/nodes/*/skin", T::uint},
        {"/nodes/*/matrix", T::numbers, false, 16},
        {"/nodes/*/translation", T::numbers, false, 3},
        {"/nodes/*/rotation", T::numbers, false, 4},
        {"/nodes/*/scale", T::numbers, false, 3},
        {"/nodes/*/weights", T::numbers},
        {"/nodes/*/extensions", T::object},
        {"/nodes/*/extensions/KHR_lights_punctual", T::object},
        {"/nodes/*/extensions/KHR_lights_punctual/light", T::uint, true},
        {"/meshes", T::objects},
        {"/meshes/*/primitives", T::objects, true},
        {"/meshes/*/weights", T::numbers},
        {"/meshes/*/primitives/*/attributes", T::object, true},
        {"/meshes/*/primitives/*/attributes/*", T::uint},
        {"/meshes/*/primitives/*/indices", T::uint},
        {"/meshes/*/primitives/*/material", T::uint},
        {"/meshes/*/primitives/*/mode", T::uint},
        {"/meshes/*/primitives/*/targets", T::objects},
        {"/accessors", T::objects},
        {"/accessors/*/bufferView", T::uint},
        {"/accessors/*/byteOffset", T::uint},
        {"/accessors/*/componentType", T::uint, true},
        {"/accessors/*/normalized", T::boolean},
        {"/accessors/*/count", T::uint, true},
        {"/accessors/*/type", T::string, true},
        {"/accessors/*/min", T::numbers},
        {"/accessors/*/max", T::numbers},
        {"/accessors/*/sparse", T::object},
        {"/accessors/*/sparse/count", T::uint, true},
        {"/accessors/*/sparse/indices", T::object, true},
        {"/accessors/*/sparse/indices/bufferView", T::uint, true},
        {"/accessors/*/sparse/indices/byteOffset", T::uint},
        {"/accessors/*/sparse/indices/componentType", T::uint, true},
        {"/accessors/*/sparse/values", T::object, true},
        {"/accessors/*/sparse/values/bufferView", T::uint, true},
        {"/accessors/*/sparse/values/byteOffset", T::uint},
        {"/bufferViews", T::objects},
        {"/bufferViews/*/buffer", T::uint, true},
        {"/bufferViews/*/byteOffset", T::uint},
        {"/bufferViews/*/byteLength", T::uint, true},
        {"/bufferViews/*/byteStride", T::uint},
        {"/bufferViews/*/target", T::uint},
        {"/buffers", T::objects},
        {"/buffers/*/byteLength", T::uint, true},
        {"/buffers/*/uri", T::string},
        {"/images", T::objects},
        {"/images/*/uri", T::string},
        {"/images/*/bufferView", T::uint},
        {"/images/*/mimeType", T::string},
        {"/textures", T::objects},
        {"/textures/*/sampler", T::uint},
        {"/textures/*/source", T::uint},
        {"/samplers", T::objects},
        {"/samplers/*/magFilter", T::uint},
        {"/samplers/*/minFilter", T::uint},
        {"/samplers/*/wrapS", T::uint},
        {"/samplers/*/wrapT", T::uint},
        {"/materials", T::objects},
        {"/materials/*/pbrMetallicRoughness", T::object},
        {"/materials/*/pbrMetallicRoughness/baseColorFactor", T::numbers, false, 4},
        {"/materials/*/pbrMetallicRoughness/metallicFactor", T::number},
        {"/materials/*/pbrMetallicRoughness/roughnessFactor", T::number},
        {"/materials/*/pbrMetallicRoughness/baseColorTexture", T::texinfo},
        {"/materials/*/pbrMetallicRoughness/metallicRoughnessTexture", T::texinfo},
        {"/materials/*/normalTexture", T::texinfo},
        {"/materials/*/normalTexture/scale", T::number},
        {"/materials/*/occlusionTexture", T::texinfo},
        {"/materials/*/occlusionTexture/strength", T::number},
        {"/materials/*/emissiveTexture", T::texinfo},
        {"/materials/*/emissiveFactor", T::numbers, false, 3},
        {"/materials/*/alphaMode", T::string},
        {"/materials/*/alphaCutoff", T::number},
        {"/materials/*/doubleSided", T::boolean},
        {"/cameras", T::objects},
        {"/cameras/*/type", T::string, true},
        {"/cameras/*/perspective", T::object},
        {"/cameras/*/perspective/yfov", T::number, true},
        {"/cameras/*/perspective/znear", T::number, true},
        {"/cameras/*/perspective/zfar", T::number},
        {"/cameras/*/perspective/aspectRatio", T::number},
        {"/cameras/*/orthographic", T::object},
        {"/extensions", T::object},
        {"/extensions/KHR_lights_punctual", T::object},
        {"/extensions/KHR_lights_punctual/lights", T::objects, true},
        {"/extensions/KHR_lights_punctual/lights/*/type", T::string, true},
        {"/extensions/KHR_lights_punctual/lights/*/color", T::numbers, false, 3},
        {"/extensions/KHR_lights_punctual/lights/*/intensity", T::number},
        {"/extensions/KHR_lights_punctual/lights/*/range", T::number},
        {"/extensions/KHR_lights_punctual/lights/*/spot", T::object},
        {"/extensions/KHR_lights_punctual/lights/*/spot/innerConeAngle", T::number},
        {"/extensions/KHR_lights_punctual/lights/*/spot/outerConeAngle", T::number},
        {"/extensionsUsed", T::strings},
        {"/extensionsRequired", T::strings},
        {"/skins", T::objects},
        {"/animations", T::objects},
        {"/scenes/*/name", T::string},
        {"/nodes/*/name", T::string},
        {"/meshes/*/name", T::string},
        {"/accessors/*/name", T::string},
        {"/bufferViews/*/name", T::string},
        {"/buffers/*/name", T::string},
        {"/images/*/name", T::string},
        {"/textures/*/name", T::string},
        {"/samplers/*/name", T::string},
        {"/materials/*/name", T::string},
        {"/cameras/*/name", T::string},
        {"/skins/*/name", T::string},
        {"/animations/*/name", T::string},
        {"/extensions/KHR_lights_punctual/lights/*/name", T::string},
    };
    return r;
}

const char* type_name(T t) {
    switch (t) {
    case T::object: case T::texinfo: return "an object";
    case T::uint: return "an integer in [0, 2147483647]";
    case T::number: return "a number";
    case T::string: return "a string";
    case T::boolean: return "true or false";
    case T::uints: return "an array of integers in [0, 2147483647]";
    case T::numbers: return "an array of numbers";
    case T::objects: return "an array of objects";
    case T::strings: return "an array of strings";
    }
    return "?";
}

string got(const json& v) {
    switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array of " + std::to_string(v.size());
    case json::value_t::string: return "the string " + quote(v.get_ref<const string&>());
    case json::value_t::boolean: return v.get<bool>() ? "true" : "false";
    case json::value_t::number_integer: return std::to_string(v.get<int64_t>());
    case json::value_t::number_unsigned: return std::to_string(v.get<uint64_t>());
    case json::value_t::number_float: return num(v.get<double>());
    default: return "something else";
    }
}

bool is_uint(const json& v) {
    if (v.is_number_unsigned()) return v.get<uint64_t>() <= 2147483647u;
    if (v.is_number_integer()) return v.get<int64_t>() >= 0 && v.get<int64_t>() <= 2147483647;
    return false;
}

bool fits(const json& v, T t, int length) {
    switch (t) {
    case T::object: case T::texinfo: return v.is_object();
    case T::uint: return is_uint(v);
    case T::number: return v.is_number() && std::isfinite(v.get<double>());
    case T::string: return v.is_string();
    case T::boolean: return v.is_boolean();
    case T::uints:
        if (!v.is_array()) return false;
        for (const json& e : v)
            if (!is_uint(e)) return false;
        return true;
    case T::numbers:
        if (!v.is_array() || (length > 0 && v.size() != size_t(length))) return false;
        for (const json& e : v)
            if (!e.is_number() || !std::isfinite(e.get<double>())) return false;
        return true;
    case T::objects:
        if (!v.is_array()) return false;
        for (const json& e : v)
            if (!e.is_object()) return false;
        return true;
    case T::strings:
        if (!v.is_array()) return false;
        for (const json& e : v)
            if (!e.is_string()) return false;
        return true;
    }
    return false;
}

// The first element of an array that does not fit, for the message's pointer.
string first_bad(const json& v, T t, const string& ptr, string& what) {
    if (!v.is_array()) return ptr;
    for (size_t i = 0; i < v.size(); ++i) {
        const json& e = v[i];
        const bool ok = t == T::uints ? is_uint(e)
                        : t == T::numbers ? e.is_number() && std::isfinite(e.get<double>())
                        : t == T::objects ? e.is_object()
                                          : e.is_string();
        if (!ok) {
            what = t == T::uints ? "an integer in [0, 2147483647]"
                   : t == T::numbers ? "a number"
                   : t == T::objects ? "an object"
                                     : "a string";
            return ptr + "/" + std::to_string(i);
        }
    }
    return ptr;
}

string escape_key(const string& k) {
    string out;
    for (char c : k) {
        if (c == '~') out += "~0";
        else if (c == '/') out += "~1";
        else out += c;
    }
    return out;
}

std::vector<string> split(const char* pattern) {
    std::vector<string> parts;
    const char* p = pattern;
    while (*p == '/') {
        const char* e = std::strchr(p + 1, '/');
        if (!e) e = p + std::strlen(p);
        parts.emplace_back(p + 1, size_t(e - p - 1));
        p = e;
    }
    return parts;
}

void check_value(const string& path, const json& v, const string& ptr, const Rule& r) {
    if (fits(v, r.type, r.length)) return;
    if ((r.type == T::uints || r.type == T::numbers || r.type == T::objects || r.type == T::strings) && v.is_array() &&
        !(r.type == T::numbers && r.length > 0 && v.size() != size_t(r.length))) {
        string what;
        const string at = first_bad(v, r.type, ptr, what);
        throw Error(path + ": " + at + ": expected " + what + ", got " + got(v[std::stoul(at.substr(at.rfind('/') + 1))]));
    }
    string expected = type_name(r.type);
    if (r.type == T::numbers && r.length > 0) expected = "an array of " + std::to_string(r.length) + " numbers";
    throw Error(path + ": " + ptr + ": expected " + expected + ", got " + got(v));
}

// Applies rule r from part k on, at value v (pointer ptr).
void apply(const string& path, const json& v, const string& ptr, const std::vector<string>& parts, size_t k,
           const Rule& r) {
    if (k + 1 == parts.size()) {
        // v is the parent of the last part.
        if (parts[k] == "*") {
            if (v.is_object())
                for (auto it = v.begin(); it != v.end(); ++it) check_value(path, it.value(), ptr + "/" + escape_key(it.key()), r);
            return;
        }
        if (!v.is_object()) return;
        auto it = v.find(parts[k]);
        if (it == v.end()) {
            if (r.required) throw Error(path + ": " + (ptr.empty() ? string("/") : ptr) + ": expected a member '" + parts[k] + "', got none");
            return;
        }
        check_value(path, *it, ptr + "/" + parts[k], r);
        return;
    }
    if (parts[k] == "*") {
        if (v.is_array())
            for (size_t i = 0; i < v.size(); ++i) apply(path, v[i], ptr + "/" + std::to_string(i), parts, k + 1, r);
        else if (v.is_object())
            for (auto it = v.begin(); it != v.end(); ++it) apply(path, it.value(), ptr + "/" + escape_key(it.key()), parts, k + 1, r);
        return;
    }
    if (!v.is_object()) return;
    auto it = v.find(parts[k]);
    if (it != v.end()) apply(path, *it, ptr + "/" + parts[k], parts, k + 1, r);
}

// A texture reference (textureInfo): index required, texCoord, KHR_texture_transform.
void check_texinfo(const string& path, const json& t, const string& ptr) {
    static const Rule index{"", T::uint, true}, coord{"", T::uint}, obj{"", T::object}, two{"", T::numbers, false, 2},
        number{"", T::number};
    auto i = t.find("index");
    if (i == t.end()) throw Error(path + ": " + ptr + ": expected a member 'index', got none");
    check_value(path, *i, ptr + "/index", index);
    if (auto c = t.find("texCoord"); c != t.end()) check_value(path, *c, ptr + "/texCoord", coord);
    auto e = t.find("extensions");
    if (e == t.end()) return;
    check_value(path, *e, ptr + "/extensions", obj);
    auto x = e->find("KHR_texture_transform");
    if (x == e->end()) return;
    const string xp = ptr + "/extensions/KHR_texture_transform";
    check_value(path, *x, xp, obj);
    if (auto m = x->find("offset"); m != x->end()) check_value(path, *m, xp + "/offset", two);
    if (auto m = x->find("scale"); m != x->end()) check_value(path, *m, xp + "/scale", two);
    if (auto m = x->find("rotation"); m != x->end()) check_value(path, *m, xp + "/rotation", number);
    if (auto m = x->find("texCoord"); m != x->end()) check_value(path, *m, xp + "/texCoord", coord);
}

void apply_texinfo(const string& path, const json& doc, const Rule& r) {
    // Patterns with texinfo have one '*' (the material index).
    const std::vector<string> parts = split(r.pattern);
    auto mats = doc.find("materials");
    if (mats == doc.end() || !mats->is_array()) return;
    for (size_t m = 0; m < mats->size(); ++m) {
        const json* v = &(*mats)[m];
        string ptr = "/materials/" + std::to_string(m);
        for (size_t k = 2; k < parts.size() && v; ++k) {
            if (!v->is_object()) v = nullptr;
            else if (auto it = v->find(parts[k]); it != v->end()) {
                v = &*it;
                ptr += "/" + parts[k];
            } else v = nullptr;
        }
        if (v) check_texinfo(path, *v, ptr);
    }
}

bool base64_char(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' || c == '/';
}

// A data: URI tinygltf decodes: one of its MIME prefixes, base64 without stray characters.
// Returns the decoded size.
size_t check_data_uri(const string& path, const string& uri, const string& ptr, bool buffer) {
    static const char* buffer_kinds[] = {"data:application/octet-stream;base64,", "data:application/gltf-buffer;base64,"};
    static const char* image_kinds[] = {"data:image/png;base64,", "data:image/jpeg;base64,", "data:image/bmp;base64,",
                                        "data:image/gif;base64,", "data:application/octet-stream;base64,"};
    size_t start = 0;
    if (buffer) {
        for (const char* k : buffer_kinds)
            if (uri.compare(0, std::strlen(k), k) == 0) start = std::strlen(k);
    } else {
        for (const char* k : image_kinds)
            if (uri.compare(0, std::strlen(k), k) == 0) start = std::strlen(k);
    }
    if (start == 0)
        throw Error(path + ": " + ptr + ": expected a base64 data URI of " +
                    (buffer ? string("application/octet-stream or application/gltf-buffer")
                            : string("image/png, image/jpeg or application/octet-stream")) +
                    ", got " + quote(uri));
    size_t n = uri.size() - start, pad = 0;
    while (n > 0 && uri[start + n - 1] == '=' && pad < 2) --n, ++pad;
    for (size_t i = 0; i < n; ++i)
        if (!base64_char(uri[start + i]))
            throw Error(path + ": " + ptr + ": expected base64 data, got " + quote(string(1, uri[start + i])) +
                        " at character " + std::to_string(start + i + 1));
    if (n % 4 == 1 || (pad > 0 && (n + pad) % 4 != 0))
        throw Error(path + ": " + ptr + ": expected base64 data, got " + std::to_string(n) +
                    " characters (a cut or padded wrongly)");
    const size_t bytes = n / 4 * 3 + (n % 4 == 0 ? 0 : n % 4 - 1);
    if (bytes == 0) throw Error(path + ": " + ptr + ": expected base64 data, got none");
    return bytes;
}

const json* member(const json& o, const char* k) {
    if (!o.is_object()) return nullptr;
    auto it = o.find(k);
    return it == o.end() ? nullptr : &*it;
}

uint64_t uint_at(const json& o, const char* k, uint64_t dflt = 0) {
    const json* v = member(o, k);
    return v ? v->get<uint64_t>() : dflt;
}

// Which extensions dsr reads (the rest: ignored with a warning, or refused when required).
bool known_extension(const string& e) {
    return e == "KHR_lights_punctual" || e == "KHR_texture_transform" || e == "KHR_mesh_quantization";
}

}  // namespace

void check_json_depth(const string& path, const string& text) {
    int depth = 0;
    bool in_string = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') ++i;
            else if (c == '"') in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth)
                throw Error(path + ": expected JSON nested at most " + std::to_string(kMaxJsonDepth) +
                            " deep, got more at byte " + std::to_string(i + 1) + " (an absurd size)");
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
}

void check_document(const string& path, const json& doc, long long bin_size, std::vector<string>& warnings) {
    if (!doc.is_object()) throw Error(path + ": expected a JSON object at the top, got " + got(doc));
    // glTF 1.0: asset.version "1.x", or (older files) no version and dictionaries where 2.0 has arrays.
    const json* asset = member(doc, "asset");
    const json* version = asset ? member(*asset, "version") : nullptr;
    bool v1 = version && version->is_string() && version->get_ref<const string&>().compare(0, 2, "1.") == 0;
    if (!v1 && (!version || !version->is_string()))
        for (const char* k : {"meshes", "nodes", "accessors", "buffers", "bufferViews", "materials", "scenes"})
            if (const json* m = member(doc, k); m && m->is_object()) v1 = true;
    if (v1 || (version && version->is_string() && version->get_ref<const string&>() == "1"))
        throw Error(path + ": glTF 1.0 is not read; dsr reads glTF 2.0");
    if (version && version->is_string() && version->get_ref<const string&>().compare(0, 2, "2.") != 0)
        throw Error(path + ": /asset/version: expected '2.0', got " + quote(version->get_ref<const string&>()));

    for (const Rule& r : rules()) {
        if (r.type == T::texinfo) {
            apply_texinfo(path, doc, r);
            continue;
        }
        apply(path, doc, "", split(r.pattern), 0, r);
    }

    if (const json* req = member(doc, "extensionsRequired"))
        for (size_t i = 0; i < req->size(); ++i) {
            const string& e = (*req)[i].get_ref<const string&>();
            if (!known_extension(e))
                throw Error(path + ": /extensionsRequired/" + std::to_string(i) + ": the file requires " + quote(e) +
                            ", which dsr does not read (it reads KHR_lights_punctual, KHR_mesh_quantization, "
                            "KHR_texture_transform)");
        }
    if (const json* used = member(doc, "extensionsUsed"))
        for (size_t i = 0; i < used->size(); ++i) {
            const string& e = (*used)[i].get_ref<const string&>();
            if (!known_extension(e))
                warnings.push_back(path + ": /extensionsUsed/" + std::to_string(i) + ": extension " + quote(e) +
                                   " ignored (dsr does not read it)");
        }

    // Buffers: sizes, data URIs, and which may leave out its uri (only a .glb's first, the BIN chunk).
    const json* buffers = member(doc, "buffers");
    const size_t nbuffers = buffers ? buffers->size() : 0;
    for (size_t b = 0; b < nbuffers; ++b) {
        const json& buf = (*buffers)[b];
        const string ptr = "/buffers/" + std::to_string(b);
        const uint64_t len = uint_at(buf, "byteLength");
        if (len > kMaxGltfBytes)
            throw Error(path + ": " + ptr + "/byteLength: expected at most " + std::to_string(kMaxGltfBytes) +
                        " bytes, got " + std::to_string(len) + " (an absurd size)");
        const json* uri = member(buf, "uri");
        if (!uri) {
            if (bin_size < 0 || b != 0)
                throw Error(path + ": " + ptr + ": expected a uri (only a .glb's first buffer, its BIN chunk, may leave it out), got none");
            if (len > uint64_t(bin_size))
                throw Error(path + ": " + ptr + "/byteLength: expected at most the BIN chunk's " +
                            std::to_string(bin_size) + " bytes, got " + std::to_string(len));
            if (len == 0) throw Error(path + ": " + ptr + "/byteLength: expected at least 1, got 0");
            continue;
        }
        const string& u = uri->get_ref<const string&>();
        if (u.compare(0, 5, "data:") == 0) {
            const size_t bytes = check_data_uri(path, u, ptr + "/uri", true);
            if (bytes != len)
                throw Error(path + ": " + ptr + "/uri: expected base64 data of byteLength " + std::to_string(len) +
                            " bytes, got " + std::to_string(bytes));
        } else if (u.empty()) {
            throw Error(path + ": " + ptr + "/uri: expected a file name or data URI, got ''");
        } else if (len == 0) {
            throw Error(path + ": " + ptr + "/byteLength: expected at least 1, got 0");
        }
    }
    // Images: a data URI decodable, or a buffer view within its buffer (tinygltf reads it as it is).
    const json* views = member(doc, "bufferViews");
    if (const json* images = member(doc, "images"))
        for (size_t i = 0; i < images->size(); ++i) {
            const json& img = (*images)[i];
            const string ptr = "/images/" + std::to_string(i);
            const json* uri = member(img, "uri");
            const json* bv = member(img, "bufferView");
            if ((uri != nullptr) == (bv != nullptr))
                throw Error(path + ": " + ptr + ": expected one of uri and bufferView, got " + (uri ? "both" : "neither"));
            if (uri) {
                const string& u = uri->get_ref<const string&>();
                if (u.compare(0, 5, "data:") == 0) check_data_uri(path, u, ptr + "/uri", false);
                else if (u.empty()) throw Error(path + ": " + ptr + "/uri: expected a file name or data URI, got ''");
                continue;
            }
            const uint64_t v = bv->get<uint64_t>();
            if (!views || v >= views->size())
                throw Error(path + ": " + ptr + "/bufferView: expected a buffer view index below " +
                            std::to_string(views ? views->size() : 0) + ", got " + std::to_string(v));
            const json& view = (*views)[size_t(v)];
            const uint64_t b = uint_at(view, "buffer");
            if (b >= nbuffers)
                throw Error(path + ": /bufferViews/" + std::to_string(v) + "/buffer: expected a buffer index below " +
                            std::to_string(nbuffers) + ", got " + std::to_string(b));
            const uint64_t off = uint_at(view, "byteOffset"), len = uint_at(view, "byteLength");
            const uint64_t blen = uint_at((*buffers)[size_t(b)], "byteLength");
            if (len == 0 || off + len > blen)
                throw Error(path + ": /bufferViews/" + std::to_string(v) + ": expected bytes within buffer " +
                            std::to_string(b) + "'s " + std::to_string(blen) + ", got " + std::to_string(len) +
                            " at offset " + std::to_string(off));
        }
}

}  // namespace dsr::gltf
