// `dsr gen-model DIR`: the windmill dsr makes itself (scene/generated_model.h), OBJ + MTL + maps.
#include <cstdio>

#include "app/args.h"
#include "app/command_table.h"
#include "app/commands.h"
#include "scene/generated_model.h"

namespace dsr {

int cmd_gen_model(const std::vector<std::string>& argv) {
    GenModelSettings flags;  // the gen-model command's table (app/command_table.h)
    parse_command_line(gen_model_command(flags), argv);
    if (flags.dir.empty()) fail_command("gen-model", "expected an output folder, got nothing");
    const std::string dir = flags.dir;
    const GeneratedModel model = windmill_model();
    std::string obj;
    try {
        obj = write_model(model, dir);  // all or nothing; errors name DIR as given
    } catch (const Error& e) {
        throw Error(std::string("dsr gen-model: ") + e.what());
    }
    std::printf("wrote %zu files into %s; render the model with: dsr render %s\n", model.files.size(), dir.c_str(),
                obj.c_str());
    return 0;
}

}  // namespace dsr
