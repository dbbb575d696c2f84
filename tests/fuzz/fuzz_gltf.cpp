// libFuzzer target for the glTF reader (`make fuzz`): the input is read as the bytes of a .glb and
// of a .gltf; every other file it names (buffers, images) does not exist, so data: URIs and a
// .glb's BIN chunk are all it has. Any dsr::Error is a correct answer; a crash, sanitizer report,
// leak, hang or a model the renderer could not draw is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "dsr_error.h"
#include "scene/gltf_loader.h"

namespace {

bool finite(float f) { return f == f && f - f == 0; }

void check(const dsr::GltfModel& m) {
    for (const dsr::Mesh& g : m.meshes) {
        if (g.material < 0 || size_t(g.material) >= m.materials.size()) __builtin_trap();
        if (!g.colors.empty() && g.colors.size() != g.vertices.size()) __builtin_trap();
        for (uint32_t i : g.indices)
            if (i >= g.vertices.size()) __builtin_trap();
        for (const dsr::Vertex& v : g.vertices)
            for (float f : {v.pos.x, v.pos.y, v.pos.z, v.normal.x, v.normal.y, v.normal.z, v.tangent.x, v.tangent.y,
                            v.tangent.z, v.binormal.x, v.binormal.y, v.binormal.z, v.uv.x, v.uv.y})
                if (!finite(f)) __builtin_trap();
    }
    for (const auto& p : m.placements)
        if (p.mesh >= m.meshes.size()) __builtin_trap();
    for (const dsr::Material& mt : m.materials)
        for (int t : {mt.diffuse_map, mt.normal_map, mt.specular_map})
            if (t >= int(m.textures.size())) __builtin_trap();
    if (m.texture_sampling.size() != m.textures.size() || m.texture_paths.size() != m.textures.size()) __builtin_trap();
    for (const dsr::Light& l : m.lights)
        if (!finite(l.radius) || !finite(l.color.r) || !finite(l.pos.x)) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    dsr::GltfOptions opts;
    opts.read_file = [](const std::string& path) -> std::string { throw dsr::Error("cannot open " + path + ": no such file"); };
    opts.max_triangles = 1'000'000;
    opts.max_texels = 1 << 20;
    for (const char* name : {"fuzz/in.glb", "fuzz/in.gltf"}) {
        try {
            check(dsr::parse_gltf(name, bytes, opts));
        } catch (const dsr::Error&) {
        }
    }
    return 0;
}
