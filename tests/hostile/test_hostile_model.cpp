// A model given as the scene (`dsr render FILE.obj|.gltf|.glb`): files of other formats, models
// that 32-bit coordinates cannot draw, and the flags that choose how a model is shown.
#include <string>
#include <vector>

#include "hostile.h"

namespace dsr::hostile {
namespace {

using D = const std::string&;

// A one-triangle OBJ whose corners are `a`, `b`, `c` ("x y z").
std::string triangle(const std::string& a, const std::string& b, const std::string& c) {
    return "v " + a + "\nv " + b + "\nv " + c + "\nf 1 2 3\n";
}

Case model_case(const std::string& name, std::function<void(D)> setup, const std::string& args, const std::string& expect,
                int status = 1) {
    return {name, setup, args, expect, status};
}

std::vector<Case> cases() {
    std::vector<Case> c;
    const auto cube_far = [](D d) {
        std::string s;
        for (int i = 0; i < 8; ++i)
            s += "v " + std::string(i & 1 ? "1000000001" : "1000000000") + (i & 2 ? " 1" : " 0") + (i & 4 ? " 1\n" : " 0\n");
        s += "f 1 2 4 3\nf 5 6 8 7\nf 1 2 6 5\nf 3 4 8 7\nf 1 3 7 5\nf 2 6 8 4\n";
        write(d, "far.obj", s);
    };
    c.push_back(model_case("model_far_from_origin", cube_far, "render far.obj --size 16x16 -o out.png",
                           "far.obj: expected a model wider than 1e-7 of its distance from the origin (its "
                           "coordinates are 32-bit floats), got a radius of 0.707 at 1e+09: move it nearer the origin"));
    c.push_back(model_case("model_too_small", [](D d) { write(d, "tiny.obj", triangle("0 0 0", "1e-20 0 0", "0 1e-20 0")); },
                           "render tiny.obj --size 16x16 -o out.png",
                           "tiny.obj: expected a model at least 1e-12 units across, got a radius of 7.07e-21: scale it up"));
    c.push_back(model_case("model_foreign_format", [](D d) { write(d, "m.ply", "ply\nformat ascii 1.0\nend_header\n"); },
                           "render m.ply --size 16x16 -o out.png",
                           "m.ply: expected a scene file (docs/scene-format.md) or a model dsr reads: OBJ (.obj) or glTF 2.0 "
                           "(.gltf, .glb); this format is not one of them"));
    c.push_back(model_case("model_binary_scene", [](D d) { write(d, "m.scene", std::string("\x01\x02\x03 binary", 10)); },
                           "render m.scene --size 16x16 -o out.png", "m.scene:1: expected text, got the control byte 0x01 at column 1"));
    c.push_back(model_case("model_from_bad", [](D d) { write(d, "m.obj", triangle("0 0 0", "1 0 0", "0 1 0")); },
                           "render m.obj --from sideways -o out.png",
                           "--from: expected one of front, back, left, right, above, below or a non-zero direction X,Y,Z, got 'sideways'"));
    c.push_back(model_case("model_from_zero", [](D d) { write(d, "m.obj", triangle("0 0 0", "1 0 0", "0 1 0")); },
                           "render m.obj --from 0,0,0 -o out.png", "--from: expected one of front"));
    c.push_back(model_case("model_camera_none", [](D d) { write(d, "m.obj", triangle("0 0 0", "1 0 0", "0 1 0")); },
                           "render m.obj --camera 1 --size 16x16 -o out.png",
                           "m.obj: --camera 1: expected a model with cameras, got none"));
    c.push_back(model_case("model_ambient_bad", [](D d) { write(d, "m.obj", triangle("0 0 0", "1 0 0", "0 1 0")); },
                           "render m.obj --ambient 1,2 -o out.png", "--ambient: expected three numbers R,G,B in [0, 1000], got '1,2'"));
    // --strict: what a default render substitutes with a warning is refused, naming the line.
    c.push_back(model_case("model_strict_unknown_material",
                           [](D d) { write(d, "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl nowhere\nf 1 2 3\n"); },
                           "render m.obj --strict --size 16x16 -o out.png", "m.obj:4:"));
    // The model's own files are inputs: no output may replace them.
    c.push_back(model_case("model_output_is_its_mtl",
                           [](D d) {
                               write(d, "m.obj", quad_obj("m.mtl"));
                               write(d, "m.mtl", "newmtl a\nKd 1 1 1\n");
                           },
                           "render m.obj --size 16x16 -o out.png --stats m.mtl", "--stats: expected a file ending .json"));
    c.push_back(model_case("model_output_is_its_texture",
                           [](D d) {
                               write(d, "m.obj", quad_obj("m.mtl"));
                               write(d, "m.mtl", "newmtl a\nKd 1 1 1\nmap_Kd t.png\n");
                               image(d, "t.png", 4, 4);
                           },
                           "render m.obj --size 16x16 -o t.png", "t.png"));
    return c;
}

}  // namespace

INSTANTIATE_TEST_SUITE_P(Model, Hostile, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& i) { return i.param.name; });

}  // namespace dsr::hostile
