// Internal to the OBJ loader (obj_loader.cpp): from what tinyobjloader returned to the model's
// groups: triangles checked and kept with their face normals, missing normals computed by
// smoothing clusters, vertices shared within each material's group.
#pragma once
#include <tiny_obj_loader.h>

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/obj_loader.h"

namespace dsr::obj {

struct Corner {
    int v, vt, vn;  // vn < 0: computed (then `cluster` names the smoothing cluster)
};

// The triangles with area, in tinyobjloader's order.
struct Triangles {
    std::vector<Corner> corners;     // three per triangle
    std::vector<int> material;       // per triangle, into ObjModel::materials
    std::vector<glm::dvec3> face_n;  // per triangle: area-weighted normal, in double
};

// Every triangle of `shapes`, its corners checked against attrib's sizes (already checked
// against the OBJ's counts); zero-area triangles dropped with a warning; triangles without a
// material get one "OBJFILE:(default)" material appended to model.materials.
Triangles collect_triangles(const std::string& path, const std::string& obj_name, const tinyobj::attrib_t& attrib,
                            const std::vector<tinyobj::shape_t>& shapes, ObjModel& model);

// Where each vertex normal comes from.
struct Normals {
    std::vector<glm::vec3> file;          // attrib's normals, unit length where usable
    std::vector<uint32_t> cluster;        // per corner with vn < 0: its smoothing cluster
    std::vector<glm::dvec3> cluster_sum;  // per cluster: the sum of its faces' normals
};

// File normals where usable (a corner whose file normal is zero gets vn = -1, with a warning);
// the other corners clustered per position within smooth_angle_deg.
Normals smooth_normals(const std::string& path, const tinyobj::attrib_t& attrib, float smooth_angle_deg,
                       Triangles& tris, std::vector<std::string>& warnings);

// One Mesh per material used, vertices shared by corner key, tangent frames computed; appended
// to model.groups with model.vertices and model.triangles counted.
void group_by_material(const tinyobj::attrib_t& attrib, const Triangles& triangles, const Normals& normals,
                       ObjModel& model);

}  // namespace dsr::obj
