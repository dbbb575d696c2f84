// Internal to the OBJ loader (obj_loader.cpp): the line-by-line check of an MTL file, which
// records where each material's statements are so later messages can name the line.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace dsr::obj {

struct MtlMaterialInfo {
    std::string file;  // the MTL, as resolved
    int line = 0;  // newmtl
    std::map<std::string, int> lines;  // statement -> line (last one)
    int mtllib_line = 0;  // the OBJ's mtllib line that read this MTL
};

// The line of `key` in the material (the newmtl line when it has none).
int line_of(const MtlMaterialInfo& info, const std::string& key);

struct MtlFile {
    std::string path, text;  // text with comments blanked
};

// Checks one MTL text line by line; records each material's lines.
void check_mtl(MtlFile& mtl, std::map<std::string, MtlMaterialInfo>& info, std::vector<std::string>& warnings);

}  // namespace dsr::obj
