// A real model dsr makes itself (`dsr gen-model DIR`, and the model figure of `dsr figures`):
// a windmill as an OBJ + MTL + PNG maps that go through the same loader paths a downloaded
// model does. Pure (no GL); writes through the image seam (scene/image.h).
//
// The windmill stands on y = 0, about 8.4 units tall, its sails facing +Z:
//   base    brick box        map_Kd, map_bump (tangent-space normal map), map_Ks
//   tower   stone frustum    map_Kd, norm, map_Ks; smooth normals given (v/t/n)
//   band    metal ring       map_Kd, map_bump, map_Ns (read as a specular map)
//   roof    shingle cone     map_Kd, map_Bump, map_Ks; its underside one 16-sided face
//   door, window, four sails of a stock and a board lattice: wood (map_Kd, norm, map_Ks)
//   axle and hub cap: metal
// Faces are quads, triangles and 16-gons; boxes give no normals (the loader computes flat ones),
// curved parts give theirs; the sails use negative (relative) indices. Five `usemtl` groups
// shared across parts. Every map comes from scene/procedural_textures.h.
// Deterministic: the geometry uses only + - * / sqrt (circle points by bisection), so the files
// are the same bytes on every machine.
#pragma once
#include <string>
#include <vector>

#include "scene/image.h"

namespace dsr {

struct GeneratedFile {
    std::string name;  // file name within the model's folder
    std::string text;  // OBJ or MTL text; empty for an image
    Image image;       // a PNG map
    bool is_image() const { return text.empty(); }
};

struct GeneratedModel {
    std::string obj_name;  // which of files is the OBJ
    std::vector<GeneratedFile> files;
};

GeneratedModel windmill_model();

// Writes every file of `model` into `dir` (created when missing): all of them first into a fresh
// temporary folder inside `dir`, then each renamed into place, so no file is ever half-written
// and a failure while writing (a full disk) leaves `dir` as it was. Returns the OBJ's path.
// Throws dsr::Error naming the path that failed.
std::string write_model(const GeneratedModel& model, const std::string& dir);

}  // namespace dsr
