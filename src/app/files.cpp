#include "app/files.h"

namespace dsr {

void write_file_atomic(const std::string& path, const std::string& contents) {
    OutputSet out("");
    out.put_text("", path, contents);
    out.commit();
}

void add_scene_inputs(OutputSet& out, const std::vector<std::string>& scene_inputs) {
    for (size_t i = 0; i < scene_inputs.size(); ++i)
        out.add_input(scene_inputs[i], i == 0 ? "the scene file" : "a file the scene reads,");
}

}  // namespace dsr
