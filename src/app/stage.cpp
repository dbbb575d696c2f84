#include "app/stage.h"

namespace dsr {

namespace {
thread_local std::string failed_stage;
}

Stage::~Stage() {
    // More exceptions in flight than at construction: one is leaving this stage. The innermost
    // stage is destroyed first and wins.
    if (std::uncaught_exceptions() > unwinding_ && failed_stage.empty()) failed_stage = what_;
}

std::string take_failed_stage() {
    std::string s;
    s.swap(failed_stage);
    return s;
}

}  // namespace dsr
