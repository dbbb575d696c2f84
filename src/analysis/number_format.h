// Numbers as the bench and stress tables print them and as their JSON stores them: one copy of
// the printf-to-string and finite-or-null helpers both reports use.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace dsr {

// One number through a printf format with one conversion, e.g. format_number("%.2f", 1.234).
std::string format_number(const char* printf_format, double v);

// v when it is finite, JSON null otherwise (JSON has no inf or NaN).
nlohmann::ordered_json finite_or_null(double v);

}  // namespace dsr
