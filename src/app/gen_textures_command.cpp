#include <cstdio>
#include <sys/stat.h>

#include "app/args.h"
#include "app/commands.h"
#include "scene/image.h"
#include "scene/procedural_textures.h"

namespace dsr {

int cmd_gen_textures(const std::vector<std::string>& argv) {
    Args args("gen-textures", argv);
    if (args.done()) args.fail("expected an output folder, got nothing");
    std::string dir = args.next();
    if (!args.done()) args.fail("expected one output folder, got also '" + args.peek() + "'");
    mkdir(dir.c_str(), 0755);
    for (const auto& [name, img] : default_textures()) {
        write_image(dir + "/" + name, img);
        std::printf("wrote %s/%s\n", dir.c_str(), name.c_str());
    }
    return 0;
}

}  // namespace dsr
