// Where dsr's own files (glsl120/, data/) are found: beside the executable's
// parent (build/dsr -> ../glsl120), else in the source tree it was built from.
#pragma once
#include <string>

namespace dsr {

// Absolute path of the resource folder `name` ("glsl120", "data"); throws dsr::Error if absent.
std::string resource_dir(const std::string& name);

}  // namespace dsr
