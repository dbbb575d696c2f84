#include "analysis/number_format.h"

#include <cmath>
#include <cstdio>

namespace dsr {

std::string format_number(const char* printf_format, double v) {
    char b[64];
    std::snprintf(b, sizeof b, printf_format, v);
    return b;
}

nlohmann::ordered_json finite_or_null(double v) {
    return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

}  // namespace dsr
