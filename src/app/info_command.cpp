#include <cstdio>
#include <cstdlib>

#include "app/args.h"
#include "app/commands.h"
#include "gl/caps.h"
#include "platform/context.h"

namespace dsr {

std::vector<std::string> split_caps(const std::string& list) {
    std::vector<std::string> out;
    size_t a = 0;
    while (a <= list.size()) {
        size_t b = list.find(',', a);
        if (b == std::string::npos) b = list.size();
        if (b > a) out.push_back(list.substr(a, b - a));
        a = b + 1;
    }
    return out;
}

int cmd_info(const std::vector<std::string>& argv) {
    Args args("info", argv);
    std::string caps_list = std::getenv("DSR_CAPS") ? std::getenv("DSR_CAPS") : "";
    while (!args.done()) {
        std::string a = args.next();
        if (a == "--caps")
            caps_list += "," + args.value("--caps");
        else
            args.fail("unknown option '" + a + "'");
    }
    auto ctx = create_context(ContextDesc{"osmesa", 64, 64});
    Caps caps = probe_caps(split_caps(caps_list));
    std::printf("context        %s\n%s", ctx->backend().c_str(), describe(caps).c_str());
    std::printf("paths chosen:\n");
    if (!caps.glsl120) {
        std::printf("  none: GLSL 1.20 is required and this GL offers %s; dsr cannot render here\n",
                    caps.glsl_version.empty() ? "none" : caps.glsl_version.c_str());
        return 0;
    }
    std::printf("  depth          %s\n", caps.depth_texture ? "texture (ARB_depth_texture)"
                                                            : "packed (float_to_color into an RGB8 target, §3.3.2)");
    std::printf("  G-buffer       %s\n", caps.fbo && caps.draw_buffers && caps.max_draw_buffers >= 4
                                             ? "mrt: one material pass into all targets (ARB_draw_buffers)"
                                             : "per-target: one material pass per G-buffer target (§3.2)");
    std::printf("  render target  %s\n", caps.fbo ? "fbo: render to texture (EXT_framebuffer_object)"
                                                  : "copy: main buffer region + glCopyTexSubImage2D");
    std::printf("  textures       %s\n", caps.npot ? "npot: any size"
                                                   : "pow2: targets padded, material maps rescaled to powers of two");
    std::printf("  light counting %s\n", caps.occlusion_query ? "occlusion queries" : "off (no occlusion queries)");
    return 0;
}

}  // namespace dsr
