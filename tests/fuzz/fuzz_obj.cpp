// libFuzzer target for the OBJ/MTL loader (`make fuzz`). The input is an OBJ text; after a line
// "#MTL" the rest is the text of every MTL it names. Images named in the MTL are 2x2 grey
// unless their name contains "bad" (then unreadable), so no file is touched.
// Any dsr::Error is a correct answer; a crash, sanitizer report, leak or hang is a finding, and
// so is a loaded model the renderer could not use (an index out of range, a colour outside 0..1,
// a number that is not finite).
#include <cstddef>
#include <cstdint>
#include <string>

#include "dsr_error.h"
#include "scene/obj_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string all(reinterpret_cast<const char*>(data), size);
    const size_t split = all.find("#MTL\n");
    const std::string obj = split == std::string::npos ? all : all.substr(0, split);
    const std::string mtl = split == std::string::npos ? std::string() : all.substr(split + 5);
    dsr::ObjOptions opts;
    opts.read_text = [&](const std::string& path) -> std::string {
        if (path.size() >= 4 && path.compare(path.size() - 4, 4, ".mtl") == 0) return mtl;
        throw dsr::Error("cannot open " + path + ": no such file");
    };
    opts.read_image = [](const std::string& path) {
        if (path.find("bad") != std::string::npos) throw dsr::Error("cannot read image " + path);
        dsr::Image img;
        img.width = img.height = 2;
        img.rgba = {0.5f, 0.5f, 0.5f, 1, 0.7f, 0.7f, 0.7f, 1, 0.2f, 0.2f, 0.2f, 1, 0.9f, 0.9f, 0.9f, 1};
        return img;
    };
    try {
        dsr::ObjModel m = dsr::parse_obj("fuzz/in.obj", obj, opts);
        // Everything the renderer would read must be in range and finite.
        for (const dsr::Material& mat : m.materials)
            for (int map : {mat.diffuse_map, mat.normal_map, mat.specular_map})
                if (map >= int(m.textures.size()) || map < -1) __builtin_trap();
        if (m.texture_paths.size() != m.textures.size()) __builtin_trap();
        for (const dsr::Image& t : m.textures)
            if (t.width <= 0 || t.height <= 0 || t.rgba.size() != size_t(t.width) * size_t(t.height) * 4) __builtin_trap();
        for (const dsr::Mesh& g : m.groups) {
            if (g.material < 0 || size_t(g.material) >= m.materials.size()) __builtin_trap();
            if (!g.two_sided) __builtin_trap();
            if (!g.colors.empty() && g.colors.size() != g.vertices.size()) __builtin_trap();
            for (const glm::vec4& c : g.colors)
                if (!(c.r >= 0 && c.r <= 1 && c.g >= 0 && c.g <= 1 && c.b >= 0 && c.b <= 1 && c.a == 1)) __builtin_trap();
            for (uint32_t i : g.indices)
                if (i >= g.vertices.size()) __builtin_trap();
            for (const dsr::Vertex& v : g.vertices)
                for (float f : {v.pos.x, v.pos.y, v.pos.z, v.normal.x, v.normal.y, v.normal.z, v.tangent.x,
                                v.tangent.y, v.tangent.z, v.binormal.x, v.binormal.y, v.binormal.z, v.uv.x, v.uv.y})
                    if (!(f == f) || f - f != 0) __builtin_trap();
        }
    } catch (const dsr::Error&) {
    }
    return 0;
}
