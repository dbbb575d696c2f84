// Whole-file output that is never half-written, and never one of the run's inputs: an
// OutputSet of one (scene/output_set.h), for a command with a single text output.
#pragma once
#include <string>

#include "scene/output_set.h"

namespace dsr {

// Throws dsr::Error naming the path and the system's reason on failure.
void write_file_atomic(const std::string& path, const std::string& contents);

// An output folder that exists as something else is refused by what it is: throws
// "COMMAND: FLAG: expected a folder, got 'DIR', a file" (nothing when it is a folder or absent).
void require_folder(const std::string& command, const std::string& flag, const std::string& dir);

// The scene's files (Scene::inputs: the scene file first, then what it reads) as inputs of `out`.
void add_scene_inputs(OutputSet& out, const std::vector<std::string>& scene_inputs);

}  // namespace dsr
