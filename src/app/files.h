// Whole-file output that is never half-written: write a temporary beside the target, rename.
#pragma once
#include <string>

namespace dsr {

// Throws dsr::Error naming the path on failure.
void write_file_atomic(const std::string& path, const std::string& contents);

}  // namespace dsr
