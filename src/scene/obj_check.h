// Internal to the OBJ loader (obj_loader.cpp): the line-by-line check of an OBJ file, which
// counts what tinyobjloader must return, collects the mtllib and usemtl lines, and blanks every
// line but v, vt, vn and f, so tinyobjloader parses geometry only (materials, names and the
// statements dsr skips are read here).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scene/obj_text.h"

namespace dsr::obj {

struct ObjCheck {
    size_t v = 0, vt = 0, vn = 0, faces = 0, corners = 0, triangles = 0;
    size_t points_and_lines = 0;  // p and l statements, skipped
    struct Mtllib {
        std::string whole;               // the rest of the line, "\ " unescaped, other `\` read as `/`
        std::vector<std::string> names;  // the same split on unescaped spaces
        int line = 0;
    };
    std::vector<Mtllib> mtllibs;
    // Material slots: the distinct usemtl names (the rest of the line, trimmed; "" for a usemtl
    // without one) in the order of first use, with that line.
    std::vector<std::string> usemtl_names;
    std::vector<int> usemtl_lines;
    std::vector<size_t> usemtl_count;  // usemtl lines naming each
    // (first face, slot) where the material changes; slot -1: faces before any usemtl.
    std::vector<std::pair<size_t, int>> material_runs;
    std::vector<uint32_t> face_line;  // per face, its line
    // (face, corners) of the faces of more than 255 corners: tinyobjloader counts a face's
    // corners in an unsigned char, so these are the counts to trust.
    std::vector<std::pair<size_t, size_t>> large_faces;
    std::vector<uint8_t> coloured;    // per vertex, 1 where it has r g b; empty when none has
};

// One mtllib argument split on spaces, with "\ " an escaped space.
std::vector<std::string> split_escaped(std::string_view s);

// Checks the OBJ text line by line (comments and every line but v, vt, vn and f blanked in
// place); notes the statements it skips. More than max_triangles triangles is an error;
// `budget_note` says whose budget that is ("" for the file's own limit, kMaxObjElements).
ObjCheck check_obj(const std::string& path, std::string& text, Notes& notes, size_t max_triangles,
                   const std::string& budget_note);

}  // namespace dsr::obj
