// Text helpers the parts share (help, flags, the option table, the bench's report): one copy each.
#pragma once
#include <string>
#include <vector>

namespace dsr {

// v's items with sep between each two: joined({"a", "b"}, ", ") is "a, b"; "" for none.
inline std::string joined(const std::vector<std::string>& v, const std::string& sep) {
    std::string s;
    for (size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
    return s;
}

}  // namespace dsr
