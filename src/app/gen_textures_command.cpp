// `dsr gen-textures DIR`: the default scene's procedural textures (scene/procedural_textures.h)
// written as files, as data/ holds them.
#include <cstdio>
#include <sys/stat.h>

#include "app/args.h"
#include "app/command_table.h"
#include "app/commands.h"
#include "scene/image.h"
#include "scene/procedural_textures.h"

namespace dsr {

int cmd_gen_textures(const std::vector<std::string>& argv) {
    GenTexturesSettings flags;  // the gen-textures command's table (app/command_table.h)
    parse_command_line(gen_textures_command(flags), argv);
    if (flags.dir.empty()) fail_command("gen-textures", "expected an output folder, got nothing");
    const std::string dir = flags.dir;
    mkdir(dir.c_str(), 0755);
    for (const auto& [name, img] : default_textures()) {
        write_image(dir + "/" + name, img);
        std::printf("wrote %s/%s\n", dir.c_str(), name.c_str());
    }
    return 0;
}

}  // namespace dsr
