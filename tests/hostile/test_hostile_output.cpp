// Hostile output paths, for every command that writes: an output that is one of the run's
// inputs (by device and inode, whatever the spelling), a folder, a device, a missing folder, two
// outputs naming one file, an empty name. Refused with one line, nothing written, no input
// touched; an output that fails late takes the others with it.
#include <string>
#include <vector>

#include "hostile.h"

namespace dsr::hostile {
namespace {

using D = const std::string&;

// a.scene (a texture t.png, a mesh m.obj with m.mtl naming k.png), for the cases to aim at.
void scene_with_files(D d) {
    write(d, "a.scene", scene_text("mesh m.obj\n", " diffuse_map t.png"));
    image(d, "t.png", 8, 8);
    image(d, "k.png", 8, 8);
    write(d, "m.obj", quad_obj("m.mtl"));
    write(d, "m.mtl", "newmtl a\nKd 1 1 1\nmap_Kd k.png\n");
}

Case render_case(const std::string& name, std::function<void(D)> more, const std::string& flags, const std::string& expect) {
    return {name,
            [more](D d) {
                scene_with_files(d);
                if (more) more(d);
            },
            "render a.scene --size 16x16 " + flags, expect};
}

std::vector<Case> cases() {
    std::vector<Case> c;
    const std::string not_input = "expected a file that is not an input of this run, got ";
    // ---- render: an output that is an input
    c.push_back(render_case("o_is_texture", nullptr, "-o t.png", "dsr render: -o: " + not_input + "'t.png' (a file the scene reads, t.png)"));
    c.push_back(render_case("o_is_mtl_texture", nullptr, "-o k.png", "dsr render: -o: " + not_input + "'k.png' (a file the scene reads, k.png)"));
    c.push_back(render_case("o_is_texture_other_spelling", [](D d) { folder(d, "sub"); }, "-o sub/../t.png", "dsr render: -o: " + not_input + "'sub/../t.png'"));
    c.push_back(render_case("o_is_scene_symlink", [](D d) { symlink_to(d, "s.png", "a.scene"); }, "-o s.png", "dsr render: -o: " + not_input + "'s.png' (the scene file a.scene)"));
    c.push_back(render_case("o_is_texture_hardlink", [](D d) { hardlink_to(d, "h.png", "t.png"); }, "-o h.png", "dsr render: -o: " + not_input + "'h.png' (a file the scene reads, t.png)"));
    c.push_back(render_case("o_is_obj_symlink", [](D d) { symlink_to(d, "o.png", "m.obj"); }, "-o o.png", "dsr render: -o: " + not_input + "'o.png' (a file the scene reads, m.obj)"));
    c.push_back(render_case("o_is_mtl_symlink", [](D d) { symlink_to(d, "o.tif", "m.mtl"); }, "-o o.tif", "dsr render: -o: " + not_input + "'o.tif' (a file the scene reads, m.mtl)"));
    c.push_back({"stats_is_scene", [](D d) { write(d, "a.json", scene_text()); }, "render a.json --size 16x16 -o out.png --stats a.json",
                 "dsr render: --stats: " + not_input + "'a.json' (the scene file a.json)"});
    c.push_back(render_case("stats_is_scene_symlink", [](D d) { symlink_to(d, "s.json", "a.scene"); }, "-o out.png --stats s.json", "dsr render: --stats: " + not_input + "'s.json' (the scene file a.scene)"));
    // ---- render: outputs that cannot be written, caught before the render
    c.push_back(render_case("stats_no_folder", nullptr, "-o out.png --stats nodir/s.json", "dsr render: --stats: cannot write nodir/s.json: No such file or directory"));
    c.push_back(render_case("stats_in_proc", nullptr, "-o out.png --stats /proc/dsr.json", "dsr render: --stats: cannot write /proc/dsr.json"));
    c.push_back(render_case("stats_is_folder", [](D d) { folder(d, "s.json"); }, "-o out.png --stats s.json", "dsr render: --stats: expected a file to write, got 's.json', a folder"));
    c.push_back(render_case("stats_under_a_file", nullptr, "-o out.png --stats a.scene/s.json", "dsr render: --stats: cannot write a.scene/s.json: Not a directory"));
    c.push_back(render_case("o_no_folder", nullptr, "-o nodir/out.png", "dsr render: -o: cannot write nodir/out.png: No such file or directory"));
    c.push_back(render_case("o_is_folder", [](D d) { folder(d, "out.png"); }, "-o out.png", "dsr render: -o: expected a file to write, got 'out.png', a folder"));
    c.push_back(render_case("o_is_fifo", [](D d) { fifo(d, "out.png"); }, "-o out.png", "dsr render: -o: expected a file to write, got 'out.png', a FIFO"));
    c.push_back(render_case("o_under_proc", nullptr, "-o /proc/self/out.png", "dsr render: -o: cannot write /proc/self/out.png"));
    c.push_back(render_case("o_is_device_link", [](D d) { symlink_to(d, "out.png", "/dev/null"); }, "-o out.png", "dsr render: -o: expected a file to write, got 'out.png', a character device"));
    c.push_back(render_case("stats_empty", nullptr, "-o out.png --stats ''", "dsr render: --stats: expected a value, got ''"));
    c.push_back(render_case("o_empty", nullptr, "-o ''", "dsr render: -o: expected a value, got ''"));
    c.push_back(render_case("lights_empty", nullptr, "-o out.png --lights ''", "dsr render: --lights: expected a value, got ''"));
    c.push_back(render_case("o_unknown_format", nullptr, "-o out.bmpx", "dsr render: -o: expected a file ending .png, .exr, .tif, .tiff, .jpg or .ppm, got 'out.bmpx'"));
    // ---- figures
    c.push_back({"figures_o_is_file", [](D d) { write(d, "figs", "not a folder"); }, "figures -o figs --size 64x64", "dsr figures: -o: expected a folder, got 'figs'"});
    c.push_back({"figures_o_two_levels", nullptr, "figures -o a/b --size 64x64", "dsr figures: cannot create a/b: No such file or directory"});
    c.push_back({"figures_o_empty", nullptr, "figures -o ''", "dsr figures: -o: expected a value, got ''"});
    c.push_back({"figures_output_is_scene", [](D d) { folder(d, "figs"); write(d, "a.scene", scene_text()); hardlink_to(d, "figs/fig4a_normal.png", "a.scene"); },
                 "figures a.scene -o figs --size 64x64", "dsr figures: -o: " + not_input + "'figs/fig4a_normal.png' (the scene file a.scene)"});
    c.push_back({"figures_output_is_folder", [](D d) { folder(d, "figs/fig6_final.png"); write(d, "a.scene", scene_text()); },
                 "figures a.scene -o figs --size 64x64", "dsr figures: -o: expected a file to write, got 'figs/fig6_final.png', a folder"});
    // ---- gen-textures
    c.push_back({"gen_textures_into_file", [](D d) { write(d, "tex", "x"); }, "gen-textures tex", "dsr gen-textures: DIR: expected a folder, got 'tex'"});
    c.push_back({"gen_textures_two_levels", nullptr, "gen-textures a/b", "dsr gen-textures: cannot create a/b: No such file or directory"});
    c.push_back({"gen_textures_one_is_folder", [](D d) { folder(d, "tex/brick_normal.png"); }, "gen-textures tex", "dsr gen-textures: DIR: expected a file to write, got 'tex/brick_normal.png', a folder"});
    // ---- bench (refused before the sweep)
    c.push_back({"bench_json_is_scene", [](D d) { write(d, "a.json", scene_text()); }, "bench a.json --quick --json a.json",
                 "dsr bench: --json: " + not_input + "'a.json' (the scene file a.json)"});
    c.push_back({"bench_json_two_levels", [](D d) { write(d, "a.scene", scene_text()); }, "bench a.scene --quick --json x/y/b.json", "dsr bench: cannot create x/y/: No such file or directory"});
    c.push_back({"bench_json_empty", [](D d) { write(d, "a.scene", scene_text()); }, "bench a.scene --quick --json ''", "dsr bench: --json: expected a value, got ''"});
    c.push_back({"bench_plot_is_texture", [](D d) { scene_with_files(d); hardlink_to(d, "r_plot.png", "t.png"); }, "bench a.scene --quick --report r.md",
                 "dsr bench: --report's plot: " + not_input + "'r_plot.png' (a file the scene reads, t.png)"});
    // ---- stress (refused before the sweep)
    c.push_back({"stress_plot_is_json", nullptr, "stress --quick --json x.png --plot x.png", "dsr stress: --plot: expected a file no other output names, got 'x.png' (also --json x.png)"});
    c.push_back({"stress_report_fifo", [](D d) { fifo(d, "r.md"); }, "stress --quick --report r.md", "dsr stress: --report: expected a file to write, got 'r.md', a FIFO"});
    c.push_back({"stress_report_folder", [](D d) { folder(d, "r.md"); }, "stress --quick --report r.md", "dsr stress: --report: expected a file to write, got 'r.md', a folder"});
    c.push_back({"stress_json_is_report", [](D d) { write(d, "r.md", "<!-- BEGIN generated by: dsr stress --report -->\n<!-- END generated -->\n"); }, "stress --quick --report r.md --json r.md",
                 "dsr stress: --report: expected a file no other output names, got 'r.md' (also --json r.md)"});
    c.push_back({"stress_plot_no_folder", nullptr, "stress --quick --plot nodir/p.png", "dsr stress: --plot: cannot write nodir/p.png: No such file or directory"});
    return c;
}

INSTANTIATE_TEST_SUITE_P(Output, Hostile, ::testing::ValuesIn(cases()), CaseName());

}  // namespace
}  // namespace dsr::hostile
