// One error type for the whole renderer: every failure becomes a dsr::Error
// whose message names where it happened (file:line for input, the stage for GL).
#pragma once
#include <stdexcept>
#include <string>

namespace dsr {

struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace dsr
