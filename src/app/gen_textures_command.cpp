// `dsr gen-textures DIR`: the default scene's procedural textures (scene/procedural_textures.h)
// written as files, as data/ holds them.
#include <sys/stat.h>

#include <cstdio>

#include "app/args.h"
#include "app/command_table.h"
#include "app/commands.h"
#include "app/files.h"
#include "dsr_error.h"
#include "scene/image.h"
#include "scene/output_set.h"
#include "scene/procedural_textures.h"
#include "scene/user_file.h"

namespace dsr {

int cmd_gen_textures(const std::vector<std::string>& argv) {
    GenTexturesSettings flags;  // the gen-textures command's table (app/command_table.h)
    parse_command_line(gen_textures_command(flags), argv);
    if (flags.dir.empty()) fail_command("gen-textures", "expected an output folder, got nothing");
    const std::string dir = flags.dir;
    require_folder("dsr gen-textures", "DIR", dir);
    OutputSet outputs("dsr gen-textures");  // all or none (scene/output_set.h)
    outputs.make_dir("DIR", dir);
    for (const auto& [name, img] : default_textures()) outputs.put_image("DIR", dir + "/" + name, img);
    outputs.commit();
    for (const std::string& w : outputs.written()) std::printf("wrote %s\n", w.c_str());
    return 0;
}

}  // namespace dsr
