// Hostile OBJ and MTL files and the textures they name, through a scene's `mesh` line: the same
// file rules as scene files (user_file.h), then the OBJ and MTL line checks. An MTL or texture
// that cannot be read is a warning (the model drawn without it), so those cases run with
// --strict, where the warning is the one error line (tests/test_obj.cpp checks what is loaded).
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

// The same under --strict: the first warning is the error.
Case strict_case(const std::string& name, std::function<void(D)> setup, const std::string& expect) {
    Case c = mesh_case(name, std::move(setup), expect);
    c.args = "render a.scene --strict --size 16x16 -o out.png";
    return c;
}

// m.obj uses material `a` of m.mtl, whose text is `mtl`.
Case mtl_case(const std::string& name, const std::string& mtl, const std::string& expect) {
    return mesh_case(name, [mtl](D d) { write(d, "m.obj", quad_obj("m.mtl")); write(d, "m.mtl", mtl); }, expect);
}

std::vector<Case> cases() {
    std::vector<Case> c;
    // The scene reader's words before the OBJ loader's ("a.scene:5: expected a readable ... file")
    // are its own; these cases check what follows.
    const std::string head = " file for mesh, got 'm.obj': ";
    // ---- not a file
    c.push_back(mesh_case("obj_fifo", [](D d) { fifo(d, "m.obj"); }, head + "cannot open OBJ file m.obj: expected a regular file, got a FIFO"));
    c.push_back(mesh_case("obj_directory", [](D d) { folder(d, "m.obj"); }, head + "cannot open OBJ file m.obj: expected a file, got a directory"));
    c.push_back(mesh_case("obj_symlink_loop", [](D d) { symlink_to(d, "m.obj", "m.obj"); }, head + "cannot open OBJ file m.obj: Too many levels of symbolic links"));
    c.push_back(mesh_case("obj_to_dev_zero", [](D d) { symlink_to(d, "m.obj", "/dev/zero"); }, head + "cannot open OBJ file m.obj: expected a regular file, got a character device"));
    c.push_back(mesh_case("obj_oversize", [](D d) { sparse(d, "m.obj", (2ll << 30) + 1); }, head + "cannot open OBJ file m.obj: expected at most 2147483648 bytes, got 2147483649"));
    const std::string unreadable_mtl = "m.obj:1: mtllib 'm.mtl' cannot be read (cannot open MTL file m.mtl: ";
    c.push_back(strict_case("mtl_fifo", [](D d) { write(d, "m.obj", quad_obj("m.mtl")); fifo(d, "m.mtl"); }, unreadable_mtl + "expected a regular file, got a FIFO): its materials are drawn with the default material"));
    c.push_back(strict_case("mtl_directory", [](D d) { write(d, "m.obj", quad_obj("m.mtl")); folder(d, "m.mtl"); }, unreadable_mtl + "expected a file, got a directory)"));
    c.push_back(strict_case("mtl_symlink_loop", [](D d) { write(d, "m.obj", quad_obj("m.mtl")); symlink_to(d, "m.mtl", "m.mtl"); }, unreadable_mtl + "Too many levels of symbolic links)"));
    c.push_back(mesh_case("mtl_oversize", [](D d) { write(d, "m.obj", quad_obj("m.mtl")); sparse(d, "m.mtl", (2ll << 30) + 1); }, "m.obj:1: expected a readable MTL file for mtllib, got 'm.mtl': cannot open MTL file m.mtl: expected at most 2147483648 bytes, got 2147483649"));
    // ---- not text
    c.push_back(mesh_case("obj_nul", [](D d) { write(d, "m.obj", std::string("v 0 0 0\nv 1 0\0 0\n", 18)); }, head + "m.obj:2: expected text, got a NUL byte at column 6"));
    c.push_back(mesh_case("obj_control_byte", [](D d) { write(d, "m.obj", "v 0 0 0\x01\n"); }, head + "m.obj:1: expected text, got the control byte 0x01 at column 8"));
    c.push_back(mesh_case("obj_bom_then_bad", [](D d) { write(d, "m.obj", "\xEF\xBB\xBFv 1 x 3\n"); }, head + "m.obj:1: expected a number for a vertex coordinate, got 'x'"));
    c.push_back(mesh_case("obj_utf16_then_bad", [](D d) { write(d, "m.obj", std::string("\xFF\xFEv\0 \0" "1\0 \0x\0 \0" "3\0", 16)); }, head + "m.obj:1: expected a number for a vertex coordinate, got 'x'"));
    c.push_back(mesh_case("obj_utf16_odd", [](D d) { write(d, "m.obj", std::string("\xFE\xFF\0v\0", 5)); }, head + "m.obj:1: expected UTF-16 text (it begins with a UTF-16 byte-order mark), got an odd number of bytes"));
    c.push_back(mesh_case("obj_unknown_only", [](D d) { write(d, "m.obj", "vx 1 2 3\nt x 1000000/1000000/1000000\n"); }, head + "m.obj: expected at least one face (f line), got none: an empty mesh"));
    c.push_back(mtl_case("mtl_nul", std::string("newmtl a\nKd 1 1\0 1\n", 20), "m.mtl:2: expected text, got a NUL byte at column 7"));
    c.push_back(mtl_case("mtl_bom_then_bad", "\xEF\xBB\xBFKd 1 1 1\n", "m.mtl:1: expected newmtl before 'Kd'"));
    c.push_back(mesh_case("obj_long_token", [](D d) { write(d, "m.obj", "v 1 2 " + std::string(100000, '3') + "\n"); }, head + "m.obj:1: expected a number for a vertex coordinate, got '333333333333333333333333333333333333333333333333333333333333...'"));
    // ---- numbers and sizes
    c.push_back(mesh_case("obj_coordinate_huge", [](D d) { write(d, "m.obj", "v 1e13 0 0\n"); }, head + "m.obj:1: expected a vertex coordinate within +-1e12, got '1e13' (an absurd size)"));
    // A face of any number of corners is read (tests/test_obj.cpp); one past the vertices is not.
    c.push_back(mesh_case("obj_long_face_bad_index", [](D d) {
                    std::string s;
                    for (int i = 0; i < 300; ++i) s += "v " + std::to_string(i) + " 0 0\n";
                    s += "f";
                    for (int i = 1; i <= 301; ++i) s += " " + std::to_string(i);
                    write(d, "m.obj", s + "\n");
                },
                head + "m.obj:301: vertex index 301 in '301' out of range: expected 1..300"));
    c.push_back(mesh_case("obj_index_out_of_range", [](D d) { write(d, "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"); }, head + "m.obj:4: vertex index 4 in '4' out of range"));
    // ---- textures an MTL names
    c.push_back(strict_case("texture_missing", [](D d) { write(d, "m.obj", quad_obj("m.mtl")); write(d, "m.mtl", "newmtl a\nmap_Kd t.png\n"); },
                            "m.mtl:2: map_Kd 't.png' cannot be read (cannot open image t.png: No such file or directory): drawn without it"));
    c.push_back(strict_case("texture_is_fifo", [](D d) { write(d, "m.obj", quad_obj("m.mtl")); write(d, "m.mtl", "newmtl a\nmap_Kd t.png\n"); fifo(d, "t.png"); },
                            "m.mtl:2: map_Kd 't.png' cannot be read (cannot open image t.png: expected a regular file, got a FIFO): drawn without it"));
    c.push_back(strict_case("texture_truncated_jpeg", [](D d) {
                    write(d, "m.obj", quad_obj("m.mtl"));
                    write(d, "m.mtl", "newmtl a\nmap_Kd t.jpg\n");
                    image(d, "full.jpg", 64, 64);
                    truncated(d, "t.jpg", "full.jpg", 700);
                },
                "m.mtl:2: map_Kd 't.jpg' cannot be read (cannot read image t.jpg: JPEG error: Premature end of JPEG file"));
    c.push_back(strict_case("texture_damaged_png", [](D d) {
                    write(d, "m.obj", quad_obj("m.mtl"));
                    write(d, "m.mtl", "newmtl a\nmap_bump t.png\n");
                    image(d, "full.png", 64, 64);
                    damaged(d, "t.png", "full.png", 200, "XXXXXXXX");
                },
                "m.mtl:2: map_bump 't.png' cannot be read (cannot read image t.png:"));
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
