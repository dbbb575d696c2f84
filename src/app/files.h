// Helpers of the commands' outputs (scene/output_set.h): a folder an output goes into, and the
// scene's files as inputs no output may overwrite.
#pragma once
#include <string>

#include "scene/output_set.h"

namespace dsr {

// An output folder that exists as something else is refused by what it is: throws
// "COMMAND: FLAG: expected a folder, got 'DIR', a file" (nothing when it is a folder or absent).
void require_folder(const std::string& command, const std::string& flag, const std::string& dir);

// The scene's files (Scene::inputs: the scene file first, then what it reads) as inputs of `out`.
void add_scene_inputs(OutputSet& out, const std::vector<std::string>& scene_inputs);

}  // namespace dsr
