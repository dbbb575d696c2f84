// The usage table (usage.h). Keep each entry in step with its command's flag loop: tests/test_cli.cpp
// checks that every flag a command file parses is listed here, and nothing else.
#include "app/usage.h"

namespace dsr {

namespace {

const char* kContextOption =
    "  --context NAME          GL context backend: osmesa or egl (default: $DSR_CONTEXT, else osmesa)\n";
const char* kEglDeviceOption =
    "  --egl-device N          with --context egl: the EGL device (default: $DSR_EGL_DEVICE, else 0)\n";

const char* kCapsOption =
    "  --caps LIST             capabilities to hide: no-mrt, no-depth-texture, no-fbo, no-arb-fbo,\n"
    "                          no-npot, no-float, no-glsl, no-occlusion-query, no-pipeline-stats,\n"
    "                          no-stencil, no-packed-depth-stencil, no-stencil-separate,\n"
    "                          no-stencil-two-side, no-depth-bounds (added to $DSR_CAPS)\n";
// The option table's flags (deferred/option_table.h): `render` and `view` take them all, and the
// viewer's `set NAME VALUE` takes each by its name without dashes.
const char* kRendererOptions =
    "  --depth auto|texture|packed|position16|position32\n"
    "                          depth path; auto: the depth texture where the GL has ARB_depth_texture\n"
    "                          (never a position path); position16/32: eye-space position stored in\n"
    "                          an RGBA16F/RGBA32F target instead of rebuilt from depth\n"
    "  --depth-encoding corrected|literal|linear|log\n"
    "                          what the packed depth target holds (default corrected)\n"
    "  --gbuffer rgba8|half    G-buffer target precision (default rgba8, as the tutorial)\n"
    "  --scissor on|off        light scissor rectangles, Listing 16 (default on)\n"
    "  --lighting equations|listing\n"
    "                          Listing 2 as the equations say (default) or as printed\n"
    "  --no-skip LIST          skips to turn off: variants, empty-lights, light-depth-test,\n"
    "                          light-sphere-test (all on by default)\n"
    "  --view NAME             final, normal, diffuse, specular, depth, blur-factor, bloom or ssao\n"
    "  --bloom, --no-bloom     bloom on or off (default: the scene's post line)\n"
    "  --bloom-scale 2|4       bloom buffers at 1/2 or 1/4 of the frame (default 2)\n"
    "  --bloom-taps N          blur taps, odd, 3..15 (default 7)\n"
    "  --bloom-strength S      weight of the bloom added to the image, 0..16 (default 1;\n"
    "                          above 1 it adds what 1 adds: GL clamps the colour it scales)\n"
    "  --bloom-mode color|listing\n"
    "                          blur intense colours (default) or Listing 22 as printed\n"
    "  --aa, --no-aa           anti-alias on or off (default: the scene's post line)\n"
    "  --aa-source normal|depth|both\n"
    "                          what the edge factor of Equation 7 measures (default normal)\n"
    "  --aa-kernel text|listing\n"
    "                          all 8 neighbours as the text says (default) or Listing 21's 4\n"
    "  --aa-weight W           largest anti-alias offset in pixels, 0..8 (default 1)\n"
    "  --tile-plan lists|groups\n"
    "                          tiles: each tile its exact light list (default), or lights in\n"
    "                          screen-order groups drawn over the union of their tiles\n"
    "  --tile-depth on|off     tiles: leave out each tile's lights whose sphere misses the depth\n"
    "                          span of its surfaces (default on; needs float targets)\n"
    "  --render-target auto|fbo|copy|pbuffer\n"
    "                          where the G-buffer and P-buffers are drawn: framebuffer objects,\n"
    "                          the main buffer copied to textures, or EGL pbuffer surfaces copied\n"
    "                          to textures (needs --context egl); auto: fbo, else copy\n"
    "  --light-geometry quad|volume|stencil|tiles\n"
    "                          how each light reaches its pixels: scissored quad (default, the\n"
    "                          tutorial's), volume mesh back faces, stencil-masked volume, or\n"
    "                          screen tiles with several lights per pass\n"
    "  --depth-bounds on|off   quad: EXT_depth_bounds_test on each light's depth span (default off;\n"
    "                          refused where the GL lacks it, as llvmpipe does)\n"
    "  --tile-size auto|N      tiles: pixels per tile side, 8..512 (default auto: 16 on a CPU\n"
    "                          rasteriser such as llvmpipe, else 32; `info` says which)\n"
    "  --tile-lights auto|N    tiles: lights per pass, 1..32 (default auto: 32 on a CPU rasteriser, else 8)\n"
    "  --ssao, --no-ssao       screen-space ambient occlusion scaling the ambient pass (default off)\n"
    "  --ssao-scale 1|2        AO buffer at full or half resolution (default 1)\n"
    "  --ssao-radius R         hemisphere radius in eye-space units, 0.01..100 (default 0.5)\n"
    "  --ssao-strength S       ao = 1 - S x occluded fraction, 0..4 (default 1)\n"
    "  --ssao-samples N        hemisphere samples per pixel, 4..64 (default 16)\n"
    "  --show-lights, --no-show-lights\n"
    "                          an emissive marker at each point and spot light, drawn forward into\n"
    "                          P-buffer 0 after the lights, so bloom makes it glow (default off)\n"
    "  --depth-handoff auto|blit|pass\n"
    "                          how the G-buffer's depth reaches P-buffer 0 for the passes that test\n"
    "                          against it: EXT_framebuffer_blit, or a gl_FragDepth pass (default auto:\n"
    "                          blit where present)\n";
const char* kStateOptions =
    "  --gl-state-cache on|off\n"
    "                          off: every pass sets all of its GL state, so a cache bug can be\n"
    "                          told from a pass bug (default on)\n"
    "  --debug-gl              check GL errors after every stage (also DSR_DEBUG_GL=1)\n";

std::vector<CommandUsage> make_table() {
    std::vector<CommandUsage> t;
    t.push_back({"render",
                 {"[SCENE] [-o OUT] [--size WxH] [--depth auto|texture|packed|position16|position32]",
                  "[--depth-encoding corrected|literal|linear|log] [--no-skip variants,empty-lights,light-depth-test,light-sphere-test]",
                  "[--scissor on|off] [--lighting equations|listing] [--gbuffer rgba8|half]",
                  "[--frames N] [--stats FILE.json] [--lights own|N|N-overlap|N-large] [--caps no-mrt,no-depth-texture,...]",
                  "[--out-size WxH] [--view final|normal|diffuse|specular|depth|blur-factor|bloom|ssao]",
                  "[--bloom|--no-bloom] [--bloom-scale 2|4] [--bloom-taps N] [--bloom-strength S]",
                  "[--bloom-mode color|listing] [--aa|--no-aa] [--aa-source normal|depth|both]",
                  "[--aa-kernel text|listing] [--aa-weight W]",
                  "[--light-geometry quad|volume|stencil|tiles] [--depth-bounds on|off] [--tile-size auto|N] [--tile-lights auto|N]",
                  "[--tile-plan lists|groups] [--tile-depth on|off] [--render-target auto|fbo|copy|pbuffer]",
                  "[--ssao|--no-ssao] [--ssao-scale 1|2] [--ssao-radius R] [--ssao-strength S] [--ssao-samples N]",
                  "[--show-lights|--no-show-lights] [--depth-handoff auto|blit|pass]",
                  "[--context NAME] [--egl-device N] [--gl-state-cache on|off] [--debug-gl]"},
                 "render SCENE (default data/default.scene) with the deferred shader into one image",
                 "  SCENE                   scene file (default data/default.scene), or a model FILE.obj\n"
                 "                          framed with a ground and three lights\n"
                 "  -o, --output FILE       image to write: .png, .exr, .tif, .jpg or .ppm (default out.png)\n"
                 "  --size WxH              G-buffer and P-buffer size (default 512x512)\n"
                 "  --out-size WxH          main frame buffer the final stage scales to (default: --size)\n"
                 "  --frames N              frames to render; --stats reports the medians (default 1)\n"
                 "  --stats FILE.json       per-stage times, light counts and fragments, paths chosen\n"
                 "  --lights SPEC           the scene's lights replaced as one item of the bench's --lights:\n"
                 "                          N spread, N-overlap or N-large (that one replaces the scene too)\n" +
                     std::string(kCapsOption) + kRendererOptions +
                     std::string(kContextOption) + kEglDeviceOption + kStateOptions});
    t.push_back({"figures",
                 {"[SCENE] [-o DIR] [--size NxN] [--context NAME]"},
                 "the tutorial's figures 4, 6, 8-11 as PNGs, and beside Figure 6 the windmill gen-model writes",
                 "  SCENE                   scene file (default data/default.scene)\n"
                 "  -o DIR                  folder to write the PNGs into (default docs/figures)\n"
                 "  --size NxN              square size, at least 64x64 (default 512x512)\n" +
                     std::string(kContextOption)});
    t.push_back({"bench",
                 {"[SCENE] [--quick] [--json FILE.json] [--report FILE.md] [--size WxH] [--frames N]",
                  "[--lights own,32,256,1024,1024-overlap,32-large] [--light-geometry LIST]\n"
                 "                 [--tile-size N] [--tile-lights N] [--tile-plan lists|groups] [--tile-depth on|off]\n"
                 "                 [--context NAME]"},
                 "depth path x scissor x skips x encodings x lights vs forward: times, fragments, error",
                 "  SCENE                   scene to measure (default: data/default.scene and\n"
                 "                          tests/data/analytic.scene)\n"
                 "  --quick                 128x128, 1 warm-up + 3 timed frames, lights own,32,256\n"
                 "  --json FILE.json        every row, the goals and the machine (docs/benchmarks.json)\n"
                 "  --report FILE.md        markdown report, with the plot beside it as FILE_plot.png\n"
                 "  --size WxH              frame size (default 512x512)\n"
                 "  --frames N              timed frames per row, 1..1000 (default 10)\n"
                 "  --lights LIST           comma-separated light counts; own: the scene's own lights;\n"
                 "                          N-overlap: N lights (a multiple of 8) in clusters of 8, every\n"
                 "                          lit pixel inside at least 8; N-large: 9 boxes and N lights\n"
                 "                          covering most of the screen, as LearnOpenGL's demo\n"
                 "                          (default own,32,256,1024,1024-overlap,32-large)\n"
                 "  --light-geometry LIST   light geometries to measure: quad, volume, stencil, tiles\n"
                 "                          (default all four)\n"
                 "  --tile-size N           the tiles rows' tile side in pixels, 8..512 (default: render's auto)\n"
                 "  --tile-lights N         the tiles rows' lights per pass, 1..32 (default: render's auto)\n"
                 "  --tile-plan lists|groups  the tiles rows' plan (default lists)\n"
                 "  --tile-depth on|off     the tiles rows' depth culling (default on)\n" +
                     std::string(kContextOption)});
    t.push_back({"stress",
                 {"[--quick] [--json FILE] [--report FILE.md] [--plot FILE.png] [--only TEXT]",
                  "[--light-geometry quad|volume|stencil|tiles] [--context NAME]"},
                 "numerical stress sweep; exit 1 if an invariant fails",
                 "  --quick                 the quick subset (what `make test` runs)\n"
                 "  --json FILE             every case's fields (docs/stress.json)\n"
                 "  --report FILE.md        rewrite the file's generated block (docs/accuracy.md)\n"
                 "  --plot FILE.png         relative z error against far/near\n"
                 "  --only TEXT             only the cases whose name contains TEXT\n"
                 "  --light-geometry NAME   every case through that light geometry (default quad)\n" +
                     std::string(kContextOption)});
    t.push_back({"info",
                 {"[--caps LIST] [--context NAME] [--egl-device N]"},
                 "GL vendor/renderer/version, capabilities, paths chosen",
                 std::string(kCapsOption) + kContextOption + kEglDeviceOption});
    t.push_back({"gen-textures",
                 {"DIR"},
                 "write the default scene's procedural textures",
                 "  DIR                     folder to write the textures into\n"});
    t.push_back({"gen-model",
                 {"DIR"},
                 "write a windmill dsr makes itself: OBJ + MTL + diffuse, normal and specular PNG maps",
                 "  DIR                     folder to write the model into (created when missing)\n"});
    t.push_back({"compare",
                 {"A B [--threshold LSB] [--max-lsb LSB]"},
                 "compare two image files (RGB, 8-bit LSB) as the image tests do: one line on stdout",
                 "  A B                     the two images, same size (any format dsr reads)\n"
                 "  --threshold LSB         count pixels with a channel over this difference (default 2)\n"
                 "  --max-lsb LSB           exit 1 when the largest difference is over LSB\n"});
    t.push_back({"view",
                 {"[SCENE] [--size WxH] [--script FILE] [--caps LIST] [render's renderer options:",
                  "--depth, --depth-encoding, --gbuffer, --scissor, --lighting, --no-skip, --view,",
                  "--bloom|--no-bloom, --bloom-*, --aa|--no-aa, --aa-*] [--gl-state-cache on|off] [--debug-gl]"},
                 "the renderer in a window (GLFW, GL 2.1) with a panel of every option, buffer and cost",
                 "  SCENE                   scene file (default data/default.scene), or a model FILE.obj\n"
                 "                          framed with a ground and three lights\n"
                 "  --size WxH              the window's size at start (default 512x512)\n"
                 "  --script FILE           run FILE's commands, one a line: size W H (0 0 minimises),\n"
                 "                          camera pos X Y Z target X Y Z up X Y Z, set NAME VALUE (an\n"
                 "                          option below by its name without dashes: set scissor off,\n"
                 "                          set view normal, set bloom on; or panel, overlay, animate\n"
                 "                          on|off), frames N, screenshot FILE, quit\n" +
                     std::string(kCapsOption) + kRendererOptions + kStateOptions +
                     "\nkeys:\n"
                     "  W A S D, Q E            move; Q/E down/up; shift: 4x faster; scroll: speed\n"
                     "  right mouse button      hold and drag to look around\n"
                     "  R                       back to the scene's camera\n"
                     "  F                       frame the scene: look at its centre along the current view\n"
                     "                          direction, its bounding sphere 70% of the window\n"
                     "  F1 or Tab               show or hide the panel\n"
                     "  1..7, V (shift+V)       buffer shown: final, normal, diffuse, specular, depth,\n"
                     "                          blur-factor, bloom (next, previous)\n"
                     "  C                       scissor on/off      O   scissor-rectangle overlay\n"
                     "  B                       bloom on/off        N   anti-alias on/off\n"
                     "  P                       depth path: texture/packed\n"
                     "  L                       animate the lights (turn about the scene's target)\n"
                     "  F12                     screenshot of the deferred image (no panel) into\n"
                     "                          ./dsr_view_DATE_TIME.png; its path is printed\n"
                     "  Esc                     quit\n"});
    return t;
}

std::string synopsis_text(const CommandUsage& u, const std::string& lead) {
    std::string s;
    const std::string indent(lead.size() + u.name.size() + 1, ' ');
    for (size_t i = 0; i < u.synopsis.size(); ++i)
        s += (i == 0 ? lead + u.name + " " : indent) + u.synopsis[i] + "\n";
    return s;
}

}  // namespace

const std::vector<CommandUsage>& command_usages() {
    static const std::vector<CommandUsage> t = make_table();
    return t;
}

const CommandUsage* find_command_usage(const std::string& name) {
    for (const CommandUsage& u : command_usages())
        if (u.name == name) return &u;
    return nullptr;
}

std::string command_usage_text(const CommandUsage& u) {
    return synopsis_text(u, "usage: dsr ") + u.summary + "\n\noptions:\n" + u.options;
}

std::string top_usage_text() {
    std::string s = "usage: dsr COMMAND [options]   (dsr COMMAND --help: that command's options)\n";
    for (const CommandUsage& u : command_usages()) s += synopsis_text(u, "  ") + "      " + u.summary + "\n";
    return s;
}

std::string unknown_command_line(const std::string& name) {
    std::string list;
    for (const CommandUsage& u : command_usages()) list += (list.empty() ? "" : ", ") + u.name;
    return "dsr: unknown command '" + name + "' (expected " + list + "; dsr --help lists them)";
}

bool is_help_flag(const std::string& arg) { return arg == "--help" || arg == "-h"; }

}  // namespace dsr
