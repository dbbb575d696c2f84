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

// Writes every file of `model` into `dir` (created, with its missing parents, when absent), all
// or nothing: a name in `dir` held by a folder (or anything but a file) is refused before any
// write; every file is written into a hidden folder inside `dir`, then each moved into place (the
// file it replaces kept aside until the end); a failure anywhere (a full disk, a name too long)
// puts back what was there and removes every folder it made. Returns the OBJ's path. Throws
// dsr::Error naming `dir` as given (quoted, scene/user_file.h) and the file, never the hidden
// folder: "cannot write 'brick_normal.png' in 'out/wm': No space left on device",
// "DIR: expected a folder, got 'out/wm', a file".
std::string write_model(const GeneratedModel& model, const std::string& dir);

}  // namespace dsr
