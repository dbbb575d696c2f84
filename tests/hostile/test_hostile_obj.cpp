// Hostile OBJ and MTL files and the textures they name, through a scene's `mesh` line: the same
// file rules as scene files (user_file.h), then the OBJ and MTL line checks.
#include <string>
#include <vector>

#include "hostile.h"

namespace dsr::hostile {
namespace {

using D = const std::string&;

// `a.scene` draws m.obj; `setup` makes m.obj (and what it names).
Case mesh_case(const std::string& name, std::function<void(D)> setup, const std::string& expect) {
    return {name,
            [setup](D d) {
                write(d, "a.scene", scene_text("mesh m.obj\n"));
                setup(d);
            },
            "render a.scene --size 16x16 -o out.png", expect};
}

// m.obj uses material `a` of m.mtl, whose text is `mtl`.
Case mtl_case(const std::string& name, const std::string& mtl, const std::string& expect) {
    return mesh_case(name, [mtl](D d) { write(d, "m.obj", quad_obj("m.mtl")); write(d, "m.mtl", mtl); }, expect);
}

std::vector<Case> cases() {
    std::vector<Case> c;
    const std::string head = "a.scene:5: expected a readable OBJ file for mesh, got 'm.obj': ";
    // ---- not a file
    c.push_back(mesh_case("obj_fifo", [](D d) { fifo(d, "m.obj"); }, head + "cannot open OBJ file m.obj: expected a regular file, got a FIFO"));
    c.push_back(mesh_case("obj_directory", [](D d) { folder(d, "m.obj"); }, head + "cannot open OBJ file m.obj: expected a file, got a directory"));
    c.push_back(mesh_case("obj_symlink_loop", [](D d) { symlink_to(d, "m.obj", "m.obj"); }, head + "cannot open OBJ file m.obj: Too many levels of symbolic links"));
    c.push_back(mesh_case("obj_to_dev_zero", [](D d) { symlink_to(d, "m.obj", "/dev/zero"); }, head + "cannot open OBJ file m.obj: expected a regular file, got a character device"));
    c.push_back(mesh_case("obj_oversize", [](D d) { sparse(d, "m.obj", (2ll << 30) + 1); }, head + "cannot open OBJ file m.obj: expected at most 2147483648 bytes, got 2147483649"));
    c.push_back(mesh_case("mtl_fifo", [](D d) { write(d, "m.obj", quad_obj("m.mtl")); fifo(d, "m.mtl"); }, "m.obj:1: expected a readable MTL file for mtllib, got 'm.mtl': cannot open MTL file m.mtl: expected a regular file, got a FIFO"));
    c.push_back(mesh_case("mtl_directory", [](D d) { write(d, "m.obj", quad_obj("m.mtl")); folder(d, "m.mtl"); }, "m.obj:1: expected a readable MTL file for mtllib, got 'm.mtl': cannot open MTL file m.mtl: expected a file, got a directory"));
    c.push_back(mesh_case("mtl_symlink_loop", [](D d) { write(d, "m.obj", quad_obj("m.mtl")); symlink_to(d, "m.mtl", "m.mtl"); }, "cannot open MTL file m.mtl: Too many levels of symbolic links"));
    // ---- not text
    c.push_back(mesh_case("obj_nul", [](D d) { write(d, "m.obj", std::string("v 0 0 0\nv 1 0\0 0\n", 18)); }, head + "m.obj:2: expected text, got a NUL byte at column 6"));
    c.push_back(mesh_case("obj_control_byte", [](D d) { write(d, "m.obj", "v 0 0 0\x01\n"); }, head + "m.obj:1: expected text, got the control byte 0x01 at column 8"));
    c.push_back(mesh_case("obj_bom_then_bad", [](D d) { write(d, "m.obj", "\xEF\xBB\xBFvx 1 2 3\n"); }, head + "m.obj:1: expected an OBJ statement (v, vt, vn, f, o, g, s, mtllib, usemtl; l, p and free-form ignored), got 'vx'"));
    c.push_back(mtl_case("mtl_nul", std::string("newmtl a\nKd 1 1\0 1\n", 20), "m.mtl:2: expected text, got a NUL byte at column 7"));
    c.push_back(mtl_case("mtl_bom_then_bad", "\xEF\xBB\xBFKq 1\n", "m.mtl:1: expected an MTL statement"));
    c.push_back(mesh_case("obj_long_token", [](D d) { write(d, "m.obj", "v 1 2 " + std::string(100000, '3') + "\n"); }, head + "m.obj:1: expected a number for a vertex coordinate, got '333333333333333333333333333333333333333333333333333333333333...'"));
    // ---- numbers and sizes
    c.push_back(mesh_case("obj_coordinate_huge", [](D d) { write(d, "m.obj", "v 1e13 0 0\n"); }, head + "m.obj:1: expected a vertex coordinate within +-1e12, got '1e13' (an absurd size)"));
    c.push_back(mesh_case("obj_face_too_big", [](D d) {
                    std::string s;
                    for (int i = 0; i < 300; ++i) s += "v " + std::to_string(i) + " 0 0\n";
                    s += "f";
                    for (int i = 1; i <= 300; ++i) s += " " + std::to_string(i);
                    write(d, "m.obj", s + "\n");
                },
                head + "m.obj:301: expected a face of at most 256 corners, got 300 (an absurd size)"));
    c.push_back(mesh_case("obj_index_out_of_range", [](D d) { write(d, "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"); }, head + "m.obj:4: vertex index 4 in '4' out of range"));
    // ---- textures an MTL names
    c.push_back(mtl_case("texture_missing", "newmtl a\nmap_Kd t.png\n", "m.mtl:2: expected a readable image for map_Kd, got 't.png': cannot open image t.png: No such file or directory"));
    c.push_back(mesh_case("texture_is_fifo", [](D d) { write(d, "m.obj", quad_obj("m.mtl")); write(d, "m.mtl", "newmtl a\nmap_Kd t.png\n"); fifo(d, "t.png"); },
                          "m.mtl:2: expected a readable image for map_Kd, got 't.png': cannot open image t.png: expected a regular file, got a FIFO"));
    c.push_back(mesh_case("texture_truncated_jpeg", [](D d) {
                    write(d, "m.obj", quad_obj("m.mtl"));
                    write(d, "m.mtl", "newmtl a\nmap_Kd t.jpg\n");
                    image(d, "full.jpg", 64, 64);
                    truncated(d, "t.jpg", "full.jpg", 700);
                },
                "m.mtl:2: expected a readable image for map_Kd, got 't.jpg': cannot read image t.jpg: JPEG error: Premature end of JPEG file"));
    c.push_back(mesh_case("texture_damaged_png", [](D d) {
                    write(d, "m.obj", quad_obj("m.mtl"));
                    write(d, "m.mtl", "newmtl a\nmap_bump t.png\n");
                    image(d, "full.png", 64, 64);
                    damaged(d, "t.png", "full.png", 200, "XXXXXXXX");
                },
                "m.mtl:2: expected a readable image for map_bump, got 't.png': cannot read image t.png:"));
    c.push_back(mesh_case("texture_header_absurd", [](D d) {
                    write(d, "m.obj", quad_obj("m.mtl"));
                    write(d, "m.mtl", "newmtl a\nmap_Ks t.png\n");
                    header_only_png(d, "t.png", 20000, 20);
                },
                "m.mtl:2: expected a readable image for map_Ks, got 't.png': cannot read image t.png: 20000 x 20 pixels, expected at most 16384 a side"));
    return c;
}

INSTANTIATE_TEST_SUITE_P(Obj, Hostile, ::testing::ValuesIn(cases()), CaseName());

}  // namespace
}  // namespace dsr::hostile
