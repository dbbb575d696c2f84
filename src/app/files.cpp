#include "app/files.h"

#include <sys/stat.h>

#include "dsr_error.h"
#include "scene/user_file.h"

namespace dsr {

void add_scene_inputs(OutputSet& out, const std::vector<std::string>& scene_inputs) {
    for (size_t i = 0; i < scene_inputs.size(); ++i)
        out.add_input(scene_inputs[i], i == 0 ? "the scene file" : "a file the scene reads,");
}

// An output folder that exists as something else is refused by what it is ("a file").
void require_folder(const std::string& command, const std::string& flag, const std::string& dir) {
    struct stat st {};
    if (::stat(dir.c_str(), &st) != 0 || S_ISDIR(st.st_mode)) return;
    throw Error(command + ": " + flag + ": expected a folder, got " + quote(dir) + ", " +
                (S_ISREG(st.st_mode) ? std::string("a file") : kind_of(st.st_mode)));
}

}  // namespace dsr
