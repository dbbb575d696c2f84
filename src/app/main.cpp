// dsr: the tutorial's deferred shading renderer, headless under OSMesa.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "app/commands.h"
#include "dsr_error.h"

static const char* kUsage =
    "usage: dsr COMMAND [options]\n"
    "  render [SCENE] [-o OUT] [--size WxH] [--depth auto|texture|packed]\n"
    "         [--depth-encoding corrected|literal|linear|log] [--no-skip variants,empty-lights,light-depth-test,light-sphere-test]\n"
    "         [--scissor on|off] [--lighting equations|listing] [--gbuffer rgba8|half]\n"
    "         [--frames N] [--stats FILE.json] [--caps no-mrt,no-depth-texture,...]\n"
    "         [--out-size WxH] [--view final|normal|diffuse|specular|depth|blur-factor|bloom]\n"
    "         [--bloom|--no-bloom] [--bloom-scale 2|4] [--bloom-taps N] [--bloom-strength S]\n"
    "         [--bloom-mode color|listing] [--aa|--no-aa] [--aa-source normal|depth|both]\n"
    "         [--aa-kernel text|listing] [--aa-weight W]\n"
    "  figures [SCENE] [-o DIR] [--size NxN]   the tutorial's figures 4, 6, 8-11 as PNGs\n"
    "  bench [SCENE] [--quick] [--json FILE] [--report FILE.md] [--size WxH] [--frames N]\n"
    "        [--lights own,32,256,1024]   depth path x scissor x skips x encodings x lights vs forward\n"
    "  info [--caps LIST]      GL vendor/renderer/version, capabilities, paths chosen\n"
    "  gen-textures DIR        write the default scene's procedural textures\n"
    "  stress [--quick] [--json FILE] [--report FILE.md] [--plot FILE.png] [--only TEXT]\n"
    "                          numerical stress sweep; exit 1 if an invariant fails\n";

int main(int argc, char** argv) {
    if (argc < 2 || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "help")) {
        std::fputs(kUsage, argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    std::string cmd = argv[1];
    std::vector<std::string> args(argv + 2, argv + argc);
    try {
        if (cmd == "render") return dsr::cmd_render(args);
        if (cmd == "info") return dsr::cmd_info(args);
        if (cmd == "figures") return dsr::cmd_figures(args);
        if (cmd == "gen-textures") return dsr::cmd_gen_textures(args);
        if (cmd == "stress") return dsr::cmd_stress(args);
        if (cmd == "bench") return dsr::cmd_bench(args);
        std::fprintf(stderr, "dsr: unknown command '%s'\n%s", cmd.c_str(), kUsage);
        return 2;
    } catch (const dsr::Error& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "dsr %s: %s\n", cmd.c_str(), e.what());
        return 1;
    }
}
