#include <cstdio>

#include "app/args.h"
#include "app/commands.h"
#include "scene/image.h"
#include "scene/output_set.h"
#include "scene/procedural_textures.h"

namespace dsr {

int cmd_gen_textures(const std::vector<std::string>& argv) {
    Args args("gen-textures", argv);
    if (args.done()) args.fail("expected an output folder, got nothing");
    std::string dir = args.next();
    if (!args.done()) args.fail("expected one output folder, got also '" + args.peek() + "'");
    OutputSet outputs("dsr gen-textures");  // all or none (scene/output_set.h)
    outputs.make_dir("DIR", dir);
    for (const auto& [name, img] : default_textures()) outputs.put_image("DIR", dir + "/" + name, img);
    outputs.commit();
    for (const std::string& w : outputs.written()) std::printf("wrote %s\n", w.c_str());
    return 0;
}

}  // namespace dsr
