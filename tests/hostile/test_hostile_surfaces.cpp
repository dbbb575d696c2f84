// Hostile input to the newer surfaces: `gen-model`'s folder (whole or nothing, its errors naming
// DIR as given, short however long the path), `gen-textures` and `figures` given a file for a
// folder, `camera fit` framing a camera no written line could hold, shadow maps over their
// budget (a scene's light lines, `--lights N-shadow`), and the refusals `--caps` forces, which
// say the capability was hidden rather than blame the GL.
#include <string>
#include <vector>

#include "hostile.h"

namespace dsr::hostile {
namespace {

using D = const std::string&;

// `n` characters of path: components of 200 'd's joined by '/', the last one shorter.
std::string long_path(size_t n) {
    std::string p;
    while (p.size() < n) {
        if (!p.empty()) p += '/';
        p += std::string(std::min<size_t>(200, n - p.size()), 'd');
    }
    return p;
}

// A scene file whose first line is `camera` and whose lights are `lights`.
std::string scene_with(std::string camera, const std::string& lights) {
    if (!camera.empty() && camera.back() == '\n') camera.pop_back();
    return camera + "\nmaterial m diffuse 0.5 0.5 0.5 specular 0.2 0.2 0.2 shininess 16\n"
                    "plane size 4 at 0 0 0 material m\nbox size 1 1 1 at 0 0.5 0 material m\n" + lights;
}

Case render_case(const std::string& name, const std::string& text, const std::string& flags, const std::string& expect) {
    return {name, [text](D d) { write(d, "a.scene", text); }, "render a.scene --size 16x16 -o out.png " + flags, expect};
}

std::vector<Case> cases() {
    std::vector<Case> c;
    // ---- gen-model: nothing of the model is left where a step fails, and what was there stays
    c.push_back({"gen_model_folder_in_the_way",
                 [](D d) {
                     folder(d, "w");
                     write(d, "w/windmill.obj", "an older model\n");
                     folder(d, "w/wood_normal.png");
                 },
                 "gen-model w", "dsr gen-model: DIR: expected a file to write, got 'wood_normal.png' in 'w', a folder"});
    c.push_back({"gen_model_into_a_file", [](D d) { write(d, "w", "not a folder"); }, "gen-model w",
                 "dsr gen-model: DIR: expected a folder, got 'w', a file"});
    c.push_back({"gen_model_into_a_fifo", [](D d) { fifo(d, "w"); }, "gen-model w",
                 "dsr gen-model: DIR: expected a folder, got 'w', a FIFO"});
    c.push_back({"gen_model_under_a_file", [](D d) { write(d, "f", "x"); }, "gen-model f/w/x",
                 "dsr gen-model: cannot create 'f/w': Not a directory"});
    // A 5,000-character name: one short line, the name cut.
    c.push_back({"gen_model_name_too_long", nullptr, "gen-model " + std::string(5000, 'n'),
                 "dsr gen-model: cannot create '" + std::string(60, 'n') + "...': File name too long"});
    // Folders of 200 characters, 5,000 in all: made one by one until the path is too long for
    // the system, then every one of them removed.
    c.push_back({"gen_model_path_too_long", nullptr, "gen-model " + long_path(5000),
                 "dsr gen-model: cannot create '" + std::string(60, 'd') + "...': File name too long"});
    // A folder whose path leaves room for windmill.obj but not for the longer map names beside
    // the hidden folder: the files written first are removed again, with the folders made.
    c.push_back({"gen_model_fails_after_some_files", nullptr, "gen-model " + long_path(4066),
                 "dsr gen-model: cannot write '"});
    // ---- gen-textures and figures: a file where the folder goes is named as one
    c.push_back({"gen_textures_into_a_file", [](D d) { write(d, "tex", "x"); }, "gen-textures tex",
                 "dsr gen-textures: DIR: expected a folder, got 'tex', a file"});
    c.push_back({"figures_into_a_file", [](D d) { write(d, "figs", "x"); }, "figures -o figs --size 64x64",
                 "dsr figures: -o: expected a folder, got 'figs', a file"});
    // ---- camera fit: the framed camera is checked as a written one, naming its line
    c.push_back(render_case("camera_fit_fov_near_180", scene_with("camera fit fov 179.99", ""), "",
                            "a.scene:1: camera fit: expected far / near at most 1e7, got "));
    // ---- shadow maps: 1 GiB for all of them, checked before any is made
    {
        std::string eight;
        for (int i = 0; i < 8; ++i) eight += "light point pos 0 2 0 color 1 1 1 radius 5 shadow size 8192\n";
        c.push_back(render_case("shadow_point_lights_8192", scene_with(kCamera, eight), "",
                                "a.scene:5: expected shadow maps within the budget of 1073741824 bytes (1 GiB), got a "
                                "point light's 6 faces of 8192 x 8192 texels (3221225472 bytes at 8 a texel) after 0 bytes"));
        std::string spots;
        for (int i = 0; i < 9; ++i) spots += "light spot pos 0 3 0 dir 0 -1 0 angle 30 color 1 1 1 radius 5 shadow size 4096\n";
        c.push_back(render_case("shadow_ninth_spot_4096", scene_with(kCamera, spots), "",
                                "a.scene:13: expected shadow maps within the budget of 1073741824 bytes (1 GiB), got a "
                                "spot light's map of 4096 x 4096 texels (134217728 bytes at 8 a texel) after 1073741824 bytes"));
    }
    c.push_back(render_case("lights_65536_shadow", scene_with(kCamera, ""), "--lights 65536-shadow",
                            "dsr render: --lights: expected shadow maps within the budget of 1073741824 bytes (1 GiB), got a "
                            "spot light's map of 1024 x 1024 texels"));
    // ---- --caps: a refusal says the capability was hidden, never that the GL lacks it
    const std::string hidden = "which --caps or $DSR_CAPS hides (forced off: ";
    const std::string scene = scene_with(kCamera, "light point pos 1 3 2 color 1 1 1 radius 10\n");
    c.push_back(render_case("caps_no_glsl", scene, "--caps no-glsl", "GLSL 1.20 is required, " + hidden + "no-glsl)"));
    c.push_back(render_case("caps_no_depth_texture", scene, "--depth texture --caps no-depth-texture",
                            "--depth texture needs ARB_depth_texture, " + hidden + "no-depth-texture) (use --depth packed)"));
    c.push_back(render_case("caps_no_float_gbuffer", scene, "--gbuffer half --caps no-float",
                            "half-float G-buffer targets need ARB_texture_float and ARB_half_float_pixel, " + hidden + "no-float)"));
    c.push_back(render_case("caps_no_float_accum", scene, "--accum half --caps no-float",
                            "--accum half needs float targets (ARB_texture_float and ARB_half_float_pixel), " + hidden + "no-float)"));
    c.push_back(render_case("caps_no_float_blend", scene, "--accum float --caps no-float-blend",
                            "--accum float needs additive blending into RGBA32F targets, " + hidden + "no-float-blend)"));
    c.push_back(render_case("caps_no_fbo_render_target", scene, "--render-target fbo --caps no-fbo",
                            "--render-target fbo needs EXT_framebuffer_object, " + hidden + "no-fbo)"));
    c.push_back(render_case("caps_no_depth_bounds", scene, "--depth-bounds on --caps no-depth-bounds",
                            "--depth-bounds on needs EXT_depth_bounds_test, " + hidden + "no-depth-bounds)"));
    c.push_back(render_case("caps_no_framebuffer_blit", scene, "--depth-handoff blit --show-lights --caps no-framebuffer-blit",
                            "--depth-handoff blit needs EXT_framebuffer_blit between framebuffer objects, " + hidden +
                                "no-framebuffer-blit) (use --depth-handoff pass)"));
    c.push_back(render_case("caps_no_glsl130", scene, "--light-geometry tiles --tile-fetch vertex --caps no-glsl130",
                            "--tile-fetch vertex needs GLSL 1.30 (flat varyings), " + hidden + "no-glsl130)"));
    return c;
}

INSTANTIATE_TEST_SUITE_P(Surfaces, Hostile, ::testing::ValuesIn(cases()), CaseName());

}  // namespace
}  // namespace dsr::hostile
