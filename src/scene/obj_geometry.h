// Internal to the OBJ loader (obj_loader.cpp): from what tinyobjloader returned (untriangulated
// faces) to the model's groups: faces triangulated (obj_triangulate.h), triangles checked and
// kept with their face normals, missing normals computed by smoothing clusters, vertices shared
// within each material's group, vertex colours where the file gives them.
#pragma once
#include <tiny_obj_loader.h>

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/obj_check.h"
#include "scene/obj_loader.h"
#include "scene/obj_text.h"

namespace dsr::obj {

struct Corner {
    int v, vt, vn;  // vn < 0: computed (then `cluster` names the smoothing cluster)
};

// The triangles with area, in the file's order.
struct Triangles {
    std::vector<Corner> corners;     // three per triangle
    std::vector<int> material;       // per triangle, into ObjModel::materials
    std::vector<glm::dvec3> face_n;  // per triangle: area-weighted normal, in double
    std::vector<uint32_t> face;      // per triangle: its face (ObjCheck::face_line names its line)
};

// Every face of `shapes` (tinyobjloader's, untriangulated: one shape of the v, vt, vn and f lines
// check_obj left) triangulated, its corners checked against attrib's sizes (already checked
// against the OBJ's counts); zero-area triangles dropped with a warning. A face's material is its
// usemtl slot's in `slot_material` (check.material_runs); faces before any usemtl and slots of
// -1 get one "OBJFILE:(default)" material appended to model.materials.
Triangles collect_triangles(const std::string& path, const std::string& obj_name, const tinyobj::attrib_t& attrib,
                            const std::vector<tinyobj::shape_t>& shapes, const ObjCheck& check,
                            const std::vector<int>& slot_material, ObjModel& model, Notes& notes);

// Where each vertex normal comes from.
struct Normals {
    std::vector<glm::vec3> file;          // attrib's normals, unit length where usable
    std::vector<uint32_t> cluster;        // per corner with vn < 0: its smoothing cluster
    std::vector<glm::dvec3> cluster_sum;  // per cluster: the sum of its faces' normals
};

// File normals where usable (a corner whose file normal is zero gets vn = -1, with a warning
// naming its face's line);
// the other corners clustered per position within smooth_angle_deg.
Normals smooth_normals(const std::string& path, const tinyobj::attrib_t& attrib, float smooth_angle_deg,
                       Triangles& tris, const ObjCheck& check, Notes& notes);

// Default material: grey diffuse 0.8, no specular.
Material default_material(const std::string& obj_name);

// One Mesh per material used, vertices shared by corner key (a position index has one colour, so
// corners of different colour never merge), tangent frames computed, two-sided; a group with a
// coloured vertex gets Mesh::colors (clamped to 0..1, alpha 1; a vertex without one white, with a
// warning). Appended to model.groups with model.vertices and model.triangles counted.
void group_by_material(const std::string& path, const tinyobj::attrib_t& attrib, const Triangles& triangles,
                       const Normals& normals, const ObjCheck& check, ObjModel& model, Notes& notes);

}  // namespace dsr::obj
