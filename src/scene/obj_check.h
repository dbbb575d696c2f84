// Internal to the OBJ loader (obj_loader.cpp): the line-by-line check of an OBJ file, which
// counts what tinyobjloader must return and collects the mtllib and usemtl lines.
#pragma once
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace dsr::obj {

struct ObjCheck {
    size_t v = 0, vt = 0, vn = 0, faces = 0, triangles = 0;
    std::vector<std::pair<std::string, int>> mtllibs;  // name as written (unescaped), line
    std::vector<std::pair<std::string, int>> usemtls;  // name, line
};

// One mtllib argument as tinyobjloader splits it: on spaces, with "\ " an escaped space.
std::vector<std::string> split_escaped(std::string_view s);

// Checks the OBJ text line by line (comments blanked in place); warns about skipped statements.
// More than max_triangles triangles is an error; `budget_note` says whose budget that is ("" for
// the file's own limit, kMaxObjElements).
ObjCheck check_obj(const std::string& path, std::string& text, std::vector<std::string>& warnings,
                   size_t max_triangles, const std::string& budget_note);

}  // namespace dsr::obj
