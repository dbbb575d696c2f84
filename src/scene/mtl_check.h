// Internal to the OBJ loader (obj_loader.cpp): the line-by-line check of an MTL file, which
// records where each material's statements are so later messages can name the line, and writes
// the text tinyobjloader parses: only the statements dsr reads, each material's name replaced by
// a token tinyobjloader can read ("m" and the material's number), `\` in map file names as `/`,
// a one-number colour (Kd 0.5) as three.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "scene/obj_text.h"

namespace dsr::obj {

struct MtlMaterialInfo {
    std::string name;  // as written: the rest of the newmtl line, trimmed (may hold spaces, may be empty)
    std::string file;  // the MTL, as resolved
    int line = 0;      // newmtl
    std::map<std::string, int> lines;  // statement -> line (last one)
};

// The line of `key` in the material (the newmtl line when it has none).
int line_of(const MtlMaterialInfo& info, const std::string& key);

// Every material of every MTL read, in the order of definition; tinyobjloader's name for
// materials[i] is "m" + i.
struct MtlMaterials {
    std::vector<MtlMaterialInfo> materials;
    std::map<std::string, size_t> by_name;
};

// Checks one MTL text (comments blanked) line by line, adds its materials to `all` and returns
// the text for tinyobjloader.
std::string check_mtl(const std::string& path, std::string& text, MtlMaterials& all, Notes& notes);

}  // namespace dsr::obj
