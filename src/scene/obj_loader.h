// Wavefront OBJ/MTL models (docs/scene-format.md): parsed with tinyobjloader, validated here so that every
// mistake in a file is one dsr::Error naming the file, the line and what was expected. Pure: no
// GL. Textures go through the image interface (scene/image.h); paths in an MTL are resolved
// relative to the MTL, an MTL relative to its OBJ.
//
// What is read (docs/scene-format.md, "Meshes"):
//   OBJ: v (3, 4, 6 or 7 numbers: colours and w ignored), vt (1-3), vn (3), f (3 to
//        kMaxPolygonVertices corners, v | v/t | v//n | v/t/n, negative = relative), o, g, s,
//        mtllib (one file per line), usemtl; l, p, vp and the free-form statements are warned
//        about and skipped; anything else is an error.
//   MTL: newmtl, Kd, Ks, Ns, d / Tr (opacity: below 1 drawn by the forward stage, docs/forward.md), map_Kd, map_Ks, map_Ns
//        (a specular map, as some exported models use it), map_bump / map_Bump /
//        bump / norm (a tangent-space normal map; a greyscale one is a height map, converted on
//        load with strength -bm). Ka, Ke, Ni, illum, Tf, map_Ka, map_d, disp, refl and the PBR
//        extension are warned about and skipped; anything else is an error.
// Faces are triangulated (tinyobjloader: quads by the shorter diagonal, larger polygons by ear
// clipping), grouped by material (Listing 9: one Mesh per material used), vertices shared by
// hash of their (position, uv, normal) indices. Missing normals are computed: area-weighted face
// normals averaged over the faces around a position whose normals lie within
// ObjOptions::smooth_angle_deg of each other, so creases sharper than that stay flat.
// Tangent frames come from compute_tangents (scene/tangents.h).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "scene/image.h"
#include "scene/scene.h"

namespace dsr {

// Limits beyond which an input is refused as absurd (each error says which limit).
constexpr size_t kMaxObjBytes = size_t(2) << 30;       // an OBJ or MTL file
constexpr size_t kMaxObjElements = 20'000'000;        // v, vt, vn, triangles, each
constexpr int kMaxPolygonVertices = 256;              // corners of one face
constexpr double kMaxObjCoordinate = 1e12;            // |any number in v, vt, vn|

struct ObjOptions {
    // Missing normals: faces around a vertex whose normals differ by less than this share one
    // smooth normal; sharper creases stay flat.
    float smooth_angle_deg = 60.0f;
    // How files are read. Empty: the file system (regular files only) and load_image.
    // The fuzzer and tests replace them; both throw dsr::Error.
    std::function<std::string(const std::string& path)> read_text;
    std::function<Image(const std::string& path)> read_image;
    // Budgets: at most this many triangles (checked line by line, before tinyobjloader
    // allocates) and texels of textures (checked on each image's header); `budget_note` says
    // whose budget they are in messages (a scene's), "" for the file's own limits.
    size_t max_triangles = kMaxObjElements;
    size_t max_texels = kMaxImageTexels;
    std::string budget_note;
};

// A parsed model in object space. groups[i].material indexes materials; materials' maps index
// textures (texture_paths parallel, as resolved; a height map converted to a normal map is named
// "PATH (height map, bm B)").
struct ObjModel {
    std::string path;
    std::vector<Material> materials;  // names are "OBJFILE:MTLNAME"; "OBJFILE:(default)" for faces without usemtl
    std::vector<Image> textures;
    std::vector<std::string> texture_paths;
    std::vector<Mesh> groups;
    size_t triangles = 0, vertices = 0;
    std::vector<std::string> warnings;  // "FILE:LINE: ..." for statements dsr ignores
    std::vector<std::string> inputs;    // every file read: the OBJ, its MTLs and images
};

// Reads and parses an OBJ file, its MTL files and their textures.
ObjModel load_obj(const std::string& path, const ObjOptions& options = {});
// The same from OBJ text already in memory; `path` names it in messages and resolves mtllib.
ObjModel parse_obj(const std::string& path, std::string text, const ObjOptions& options = {});

// A greyscale height map (0..1 in red) as a tangent-space normal map, encoded n*0.5+0.5:
// n = normalize(-strength * dh/dx, -strength * dh/dy, 1), dh per texel by central differences
// with wrap-around (material maps repeat), x along +u and y along +v.
Image height_to_normal(const Image& height, float strength);
// Every texel's red, green and blue within 2/255 of each other.
bool is_greyscale(const Image& img);

}  // namespace dsr
