// Hostile scene files (`dsr render`, `figures`, `bench`, `view` all read them through
// load_scene): what is not a file, what is not text, numbers outside their documented ranges
// and scenes over the budgets (docs/scene-format.md).
#include <string>
#include <vector>

#include "hostile.h"

namespace dsr::hostile {
namespace {

using D = const std::string&;

// A case whose only input is the scene file `a.scene` with `text`, rendered by `dsr render`.
Case bad_scene(const std::string& name, const std::string& text, const std::string& expect) {
    return {name, [text](D d) { write(d, "a.scene", text); }, "render a.scene --size 16x16 -o out.png --stats s.json",
            expect};
}

// A scene whose camera line is `camera` (the rest valid).
Case bad_camera(const std::string& name, const std::string& camera, const std::string& expect) {
    return bad_scene(name,
                     camera + "\nmaterial m diffuse 1 1 1 specular 0 0 0 shininess 2\nplane size 4 at 0 0 0 material m\n",
                     expect);
}

// A 250,632-triangle grid (354 x 354 quads): 79 instances fit the 20 M budget, 80 do not.
std::string grid_obj() {
    const int n = 354;
    std::string s;
    s.reserve(8 << 20);
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) s += "v " + std::to_string(x) + " 0 " + std::to_string(y) + "\n";
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const int a = y * (n + 1) + x + 1;
            s += "f " + std::to_string(a) + " " + std::to_string(a + n + 1) + " " + std::to_string(a + n + 2) + " " +
                 std::to_string(a + 1) + "\n";
        }
    return s;
}

std::vector<Case> cases() {
    std::vector<Case> c;
    // ---- not a file
    c.push_back({"fifo", [](D d) { fifo(d, "a.scene"); }, "render a.scene -o out.png", "a.scene: expected a regular file, got a FIFO"});
    c.push_back({"directory", [](D d) { folder(d, "a.scene"); }, "render a.scene -o out.png", "a.scene: expected a file, got a directory"});
    c.push_back({"dev_zero", nullptr, "render /dev/zero -o out.png", "/dev/zero: expected a regular file, got a character device"});
    c.push_back({"dev_null", nullptr, "render /dev/null -o out.png", "/dev/null: expected a regular file, got a character device"});
    c.push_back({"missing", nullptr, "render none.scene -o out.png", "none.scene: No such file or directory"});
    c.push_back({"symlink_loop", [](D d) { symlink_to(d, "a.scene", "a.scene"); }, "render a.scene -o out.png",
                 "a.scene: Too many levels of symbolic links"});
    c.push_back({"dangling_symlink", [](D d) { symlink_to(d, "a.scene", "gone.scene"); }, "render a.scene -o out.png",
                 "a.scene: No such file or directory"});
    c.push_back({"oversize", [](D d) { sparse(d, "a.scene", (64ll << 20) + 1); }, "render a.scene -o out.png",
                 "a.scene: expected at most 67108864 bytes, got 67108865"});
    c.push_back({"proc_file_not_a_scene", nullptr, "render /proc/self/status -o out.png", "/proc/self/status:1: expected a directive"});
    c.push_back({"empty_path", nullptr, "render '' -o out.png", "dsr render: expected an argument, got ''"});
    // ---- not text
    c.push_back(bad_scene("nul_in_number", std::string(kCamera).replace(45, 1, std::string(1, '\0')), "a.scene:1: expected text, got a NUL byte at column 46"));
    c.push_back(bad_scene("nul_in_comment", scene_text(std::string("# a\0b\n", 6)), "a.scene:5: expected text, got a NUL byte at column 4"));
    c.push_back(bad_scene("escape_byte", scene_text("ambient 0.1 0.1 0.1\x1b[2J\n"), "a.scene:5: expected text, got the control byte 0x1B at column 20"));
    c.push_back(bad_scene("delete_byte", scene_text("ambient 0.1\x7f 0.1 0.1\n"), "a.scene:5: expected text, got the control byte 0x7F"));
    c.push_back(bad_scene("form_feed", scene_text("\f\n"), "a.scene:5: expected text, got the control byte 0x0C at column 1"));
    c.push_back(bad_scene("bom_then_bad_directive", "\xEF\xBB\xBFteapot 1\n", "a.scene:1: expected a directive (camera, ambient, background, material, plane, box, sphere, mesh, light, post, markers), got 'teapot'"));
    c.push_back(bad_scene("utf16_file", std::string("\xFF\xFE" "c\0a\0m\0", 8), "a.scene:1: expected text, got a NUL byte at column 4"));
    c.push_back(bad_scene("binary_garbage", std::string("\x7f" "ELF\x02\x01\x01", 7), "a.scene:1: expected text, got the control byte 0x7F at column 1"));
    c.push_back(bad_scene("lone_cr_lines", std::string(kCamera).replace(std::string(kCamera).size() - 1, 1, "\r") + "teapot\r", "a.scene:2: expected a directive"));
    // ---- long tokens: echoed at most 60 characters
    c.push_back({"huge_token", [](D d) { write(d, "a.scene", std::string(kCamera) + "teapot" + std::string(50 << 20, 'x') + "\n"); },
                 "render a.scene -o out.png", "a.scene:2: expected a directive (camera, ambient, background, material, plane, box, sphere, mesh, light, post, markers), got 'teapotxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...'"});
    c.push_back(bad_scene("long_number", scene_text("ambient " + std::string(5000, '1') + " 0 0\n"), "a.scene:5: expected a number for ambient, got '111111111111111111111111111111111111111111111111111111111111...'"));
    c.push_back(bad_scene("long_material_name", scene_text("sphere radius 1 at 0 0 0 material " + std::string(1000, 'q') + "\n"), "a.scene:5: expected a material defined on an earlier line, got 'qqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqqq...'"));
    c.push_back(bad_scene("long_texture_name", scene_text("", " diffuse_map " + std::string(300, 'p') + ".png"), "a.scene:2: expected a readable image for diffuse_map, got 'pppppppppppppppppppppppppppppppppppppppppppppppppppppppppppp...'"));
    // ---- the camera
    c.push_back(bad_camera("near_denormal", "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near 1e-45 far 100", "a.scene:1: expected far / near at most 1e7, got 100 / 1.4013e-45"));
    c.push_back(bad_camera("near_tiny", "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near 1e-30 far 100", "a.scene:1: expected far / near at most 1e7, got 100 / 1e-30 = 1e+32"));
    c.push_back(bad_camera("far_over_near_1e8", "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near 1e-6 far 100", "a.scene:1: expected far / near at most 1e7"));
    c.push_back(bad_camera("far_huge", "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near 0.1 far 1e30", "a.scene:1: expected a number for far within +-1e12, got '1e30'"));
    c.push_back(bad_camera("near_zero", "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near 0 far 100", "a.scene:1: expected near > 0, got '0'"));
    c.push_back(bad_camera("near_negative_zero", "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near -0 far 100", "a.scene:1: expected near > 0, got '-0'"));
    c.push_back(bad_camera("far_below_near", "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near 10 far 1", "a.scene:1: expected far > near, got '1'"));
    c.push_back(bad_camera("fov_zero", "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 0 near 0.1 far 100", "a.scene:1: expected fov in (0, 180) degrees, got '0'"));
    c.push_back(bad_camera("fov_180", "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 180 near 0.1 far 100", "a.scene:1: expected fov in (0, 180) degrees, got '180'"));
    c.push_back(bad_camera("fov_nan", "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov nan near 0.1 far 100", "a.scene:1: expected a finite number for fov, got 'nan'"));
    c.push_back(bad_camera("pos_huge", "camera pos 0 1e13 5 target 0 0 0 up 0 1 0 fov 60 near 0.1 far 100", "a.scene:1: expected a number for camera pos within +-1e12, got '1e13'"));
    c.push_back(bad_camera("up_zero", "camera pos 0 1 5 target 0 0 0 up 0 0 0 fov 60 near 0.1 far 100", "a.scene:1: expected camera up not parallel to target - pos"));
    c.push_back(bad_camera("target_is_pos", "camera pos 0 1 5 target 0 1 5 up 0 1 0 fov 60 near 0.1 far 100", "a.scene:1: camera target equals camera pos"));
    c.push_back(bad_scene("no_camera", "material m diffuse 1 1 1 specular 0 0 0 shininess 2\n", "a.scene: no camera line"));
    c.push_back(bad_scene("empty_file", "", "a.scene: no camera line"));
    // ---- sizes, scales, positions
    c.push_back(bad_scene("mesh_scale_1e38", scene_text("mesh m.obj scale 1e38\n"), "a.scene:5: expected a number for mesh scale within +-1e12, got '1e38'"));
    c.push_back(bad_scene("mesh_scale_1e13", scene_text("mesh m.obj scale 1e13\n"), "a.scene:5: expected a number for mesh scale within +-1e12, got '1e13'"));
    c.push_back({"mesh_world_beyond", [](D d) { write(d, "a.scene", scene_text("mesh m.obj scale 1e12 at 1e12 0 0\n")); write(d, "m.obj", quad_obj()); },
                 "render a.scene -o out.png", "a.scene:5: expected scale and at that keep 'm.obj' within +-1e12 in world space, got a vertex at 2e+12 0 -1e+12"});
    c.push_back(bad_scene("sphere_radius_huge", scene_text("sphere radius 1e13 at 0 0 0 material m\n"), "a.scene:5: expected a number for sphere radius within +-1e12, got '1e13'"));
    c.push_back(bad_scene("sphere_radius_float_zero", scene_text("sphere radius 1e-50 at 0 0 0 material m\n"), "a.scene:5: expected sphere radius > 0, got '1e-50'"));
    c.push_back(bad_scene("plane_world_beyond", scene_text("plane size 1e12 at 9e11 0 0 material m\n"), "a.scene:5: expected plane within +-1e12 in world space, got a vertex at 1.4e+12"));
    c.push_back(bad_scene("box_size_negative", scene_text("box size 1 -1 1 at 0 0 0 material m\n"), "a.scene:5: expected box size > 0, got '-1'"));
    c.push_back(bad_scene("shape_at_inf", scene_text("box size 1 1 1 at 0 inf 0 material m\n"), "a.scene:5: expected a finite number for box at, got 'inf'"));
    c.push_back(bad_scene("rotate_huge", scene_text("mesh m.obj rotate_y 1e300\n"), "a.scene:5: expected a finite number for mesh rotate_y (degrees), got '1e300'"));
    c.push_back(bad_scene("tile_huge", scene_text("", " tile 1e20"), "a.scene:2: expected a number for tile within +-1e12, got '1e20'"));
    // ---- lights and colours
    c.push_back(bad_scene("light_pos_huge", scene_text("light point pos 1e13 0 0 color 1 1 1 radius 1\n"), "a.scene:5: expected a number for light pos within +-1e12, got '1e13'"));
    c.push_back(bad_scene("light_radius_huge", scene_text("light point pos 0 0 0 color 1 1 1 radius 2e12\n"), "a.scene:5: expected a number for light radius within +-1e12, got '2e12'"));
    c.push_back(bad_scene("attenuation_radius_huge", scene_text("light point pos 0 1 0 color 1 1 1 attenuation 1e-9 0 1e-30\n"), "a.scene:5: expected attenuation whose radius (where it reaches threshold 0.0195312) is within 1e12"));
    c.push_back(bad_scene("light_dir_tiny", scene_text("light directional dir 0 -1e-30 0 color 1 1 1\n"), "a.scene:5: expected a non-zero light dir (length >= 1e-12), got '0'"));
    c.push_back(bad_scene("colour_negative", scene_text("ambient 0.1 -0.1 0.1\n"), "a.scene:5: expected ambient component >= 0, got '-0.1'"));
    c.push_back(bad_scene("colour_huge", scene_text("background 1e13 0 0\n"), "a.scene:5: expected a number for background within +-1e12, got '1e13'"));
    c.push_back(bad_scene("colour_hex_inf", scene_text("background 0x1p200 0 0\n"), "a.scene:5: expected a finite number for background, got '0x1p200'"));
    // ---- budgets
    c.push_back({"triangle_budget_instances", [](D d) {
                     write(d, "g.obj", grid_obj());
                     std::string lines;
                     for (int i = 0; i < 80; ++i) lines += "mesh g.obj at " + std::to_string(i) + " 0 0\n";
                     write(d, "a.scene", scene_text(lines));
                 },
                 "render a.scene -o out.png", "a.scene:84: expected at most 20000000 triangles in the scene, got mesh 'g.obj' of 250632 after 19799930"});
    c.push_back({"triangle_budget_shapes_after_meshes", [](D d) {
                     write(d, "g.obj", grid_obj());
                     std::string lines;
                     for (int i = 0; i < 79; ++i) lines += "mesh g.obj\n";
                     for (int i = 0; i < 100; ++i) lines += "sphere radius 1 at 0 0 0 material m\n";
                     write(d, "a.scene", scene_text(lines));
                 },
                 "render a.scene -o out.png", "a.scene:174: expected at most 20000000 triangles in the scene, got a sphere of 2208 after 19998650"});
    c.push_back({"texel_budget", [](D d) {
                     grey_png(d, "big.png", 8192, 8192);
                     header_only_png(d, "small.png", 16, 16);
                     write(d, "a.scene", scene_text("material n diffuse 1 1 1 specular 0 0 0 shininess 2 diffuse_map small.png\n", " diffuse_map big.png"));
                 },
                 "render a.scene -o out.png", "a.scene:5: expected textures within the scene's budget of 67108864 texels, got diffuse_map 'small.png' of 256 (16 x 16) after 67108864"});
    c.push_back({"image_header_absurd", [](D d) { header_only_png(d, "huge.png", 100000, 100000); write(d, "a.scene", scene_text("", " diffuse_map huge.png")); },
                 "render a.scene -o out.png", "a.scene:2: expected a readable image for diffuse_map, got 'huge.png': cannot read image huge.png: 100000 x 100000 pixels, expected at most 16384 a side"});
    // ---- other commands that read a scene
    c.push_back({"figures_fifo", [](D d) { fifo(d, "a.scene"); }, "figures a.scene -o figs", "a.scene: expected a regular file, got a FIFO"});
    c.push_back({"bench_fifo", [](D d) { fifo(d, "a.scene"); }, "bench a.scene --quick", "a.scene: expected a regular file, got a FIFO"});
    c.push_back({"view_fifo", [](D d) { fifo(d, "a.scene"); }, "view a.scene", "a.scene: expected a regular file, got a FIFO"});
    c.push_back({"view_nul", [](D d) { write(d, "a.scene", std::string("camera\0", 7)); }, "view a.scene", "a.scene:1: expected text, got a NUL byte at column 7"});
    return c;
}

INSTANTIATE_TEST_SUITE_P(Scene, Hostile, ::testing::ValuesIn(cases()), CaseName());

}  // namespace
}  // namespace dsr::hostile
