// Wavefront OBJ/MTL models (docs/scene-format.md): parsed with tinyobjloader, checked here line by
// line. Strict where a file is broken, generous where it is merely unusual: what a viewer
// (Blender, MeshLab, assimp) can draw is drawn, each substitution a warning in
// ObjModel::warnings, one line per kind per file ("FILE:LINE: what was substituted (and N more
// lines)"), so --strict can refuse it; where nothing sensible can be drawn, one dsr::Error naming
// the file, the line and what was expected. Pure: no GL. Textures go through the image
// interface (scene/image.h); paths in an MTL are resolved relative to the MTL, an MTL relative to
// its OBJ.
//
// What is read (docs/scene-format.md, "Meshes"):
//   OBJ: v (3, 4, 6 or 7 numbers: x y z, w ignored; with 6 or 7, r g b are the vertex's colour and
//        a 7th is ignored), vt (1-3), vn (3), f (3 or more corners, v | v/t | v//n | v/t/n,
//        negative = relative), o, g, s, mtllib (the rest of the line names one file, "\ " an
//        escaped space; failing that, each name on it is one), usemtl (the rest of the line,
//        trimmed, is the name: spaces allowed; the MTLs of every mtllib line are searched,
//        wherever that line is).
//   MTL: newmtl (the rest of the line, trimmed, is the name), Kd, Ks (r g b, or one number for
//        all three), Ns, d / Tr (opacity: below 1 drawn by the forward stage, docs/forward.md),
//        map_Kd, map_Ks, map_Ns (a specular map, as some exported models use it), map_bump /
//        map_Bump / bump / norm (a tangent-space normal map; a greyscale one is a height map,
//        converted on load with strength -bm), map_d (a cut-out: below).
// Substituted, with a warning:
//   - usemtl naming no material of the MTLs read, or no name: the default material (grey
//     diffuse 0.8, no specular), the one faces before any usemtl get ("OBJFILE:(default)");
//   - an mtllib file that cannot be read (missing, not a regular file, unreadable): left out,
//     its names then get the default material; one over kMaxObjBytes is an error;
//   - a texture that cannot be read, missing or damaged (the image reader refuses it, or it has
//     no pixels or non-finite texels): the map left out; a header claiming an absurd size
//     and a texture over the texel budget are errors;
//   - statements dsr skips (OBJ l, p, free-form geometry; MTL Ka, Ke, Ni, illum, Tf, map_Ka, ...)
//     and statements it does not know, in OBJ or MTL (one line per keyword, the first line and
//     how many more; past 16 keywords the rest share one line): ignored, and never handed to
//     tinyobjloader;
//   - `\` in mtllib and map file names: read as `/`;
//   - UTF-16 text (byte-order mark FE FF or FF FE): decoded to UTF-8;
//   - a polygon ear clipping cannot handle: a fan (obj_triangulate.h); triangles without area
//     dropped;
//   - vertex colours outside 0..1 clamped; in a group with coloured vertices, one without a
//     colour is white.
// Faces are triangulated by obj_triangulate.h (quads along the shorter diagonal, as
// tinyobjloader split them; larger polygons by ear clipping in the plane of their Newell
// normal), grouped by material (Listing 9: one Mesh per material used), vertices shared by hash
// of their (position, uv, normal) indices (a position has one colour, so corners of different
// colour never merge). Every group is two-sided (Mesh::two_sided: OBJ faces are seen from both
// sides); a group with coloured vertices gets Mesh::colors (alpha 1), others leave it empty.
// Missing normals are computed: area-weighted face normals averaged over the faces around a
// position whose normals lie within ObjOptions::smooth_angle_deg of each other, so creases
// sharper than that stay flat. Tangent frames come from compute_tangents (scene/tangents.h).
// Cut-outs: a material's map_d gives coverage (its alpha where it has any texel below 1, else
// its red), which replaces the alpha of a copy of the diffuse map (of a white map of map_d's
// size without map_Kd), map_d resampled to the diffuse map's size by the nearest texel (with a
// warning) where they differ; the material's alpha_cutoff is 0.5. A diffuse map with any alpha
// below 0.5 makes its material a cut-out too.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "scene/image.h"
#include "scene/scene.h"

namespace dsr {

// Limits beyond which an input is refused as absurd (each error says which limit). A face may
// have any number of corners within the triangle budget.
constexpr size_t kMaxObjBytes = size_t(2) << 30;       // an OBJ or MTL file (UTF-8, as decoded)
constexpr size_t kMaxObjElements = 20'000'000;        // v, vt, vn, triangles, each
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
// "PATH (height map, bm B)", a diffuse map with map_d's alpha "PATH (alpha from MAP_D)", with
// PATH "white" where the material has no map_Kd).
struct ObjModel {
    std::string path;
    std::vector<Material> materials;  // names are "OBJFILE:MTLNAME"; "OBJFILE:(default)" for faces without usemtl
    std::vector<Image> textures;
    std::vector<std::string> texture_paths;
    std::vector<Mesh> groups;
    size_t triangles = 0, vertices = 0;
    std::vector<std::string> warnings;  // "FILE:LINE: ..." for each kind of substitution (above)
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
