// libFuzzer target for the scene-file parser (`make fuzz`): the input is a scene file's text,
// parsed as if it were tests/fuzz/scene_file/in.scene, so `mesh` and map lines may name the
// seed OBJ, MTL and images kept beside it (and any other file; devices and directories are
// refused). Any dsr::Error is a correct answer; a crash, sanitizer report, leak or hang is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "dsr_error.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        dsr::Scene s = dsr::parse_scene(std::string(DSR_SOURCE_DIR) + "/tests/fuzz/files/in.scene", text);
        for (const dsr::Mesh& m : s.meshes) {
            if (m.material < -1 || m.material >= int(s.materials.size())) __builtin_trap();
            for (uint32_t i : m.indices)
                if (i >= m.vertices.size()) __builtin_trap();
        }
        for (const dsr::Object& o : s.objects)
            if (o.mesh >= s.meshes.size() || o.material < 0 || o.material >= int(s.materials.size())) __builtin_trap();
    } catch (const dsr::Error&) {
    }
    return 0;
}
