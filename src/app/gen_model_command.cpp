// `dsr gen-model DIR`: the windmill dsr makes itself (scene/generated_model.h), OBJ + MTL + maps.
#include <cstdio>

#include "app/args.h"
#include "app/commands.h"
#include "scene/generated_model.h"

namespace dsr {

int cmd_gen_model(const std::vector<std::string>& argv) {
    Args args("gen-model", argv);
    if (args.done()) args.fail("expected an output folder, got nothing");
    const std::string dir = args.next();
    if (!args.done()) args.fail("expected one output folder, got also '" + args.peek() + "'");
    const GeneratedModel model = windmill_model();
    const std::string obj = write_model(model, dir);
    std::printf("wrote %zu files into %s; render the model with: dsr render %s\n", model.files.size(), dir.c_str(),
                obj.c_str());
    return 0;
}

}  // namespace dsr
