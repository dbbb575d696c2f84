#include "deferred/view_names.h"

#include "dsr_error.h"

namespace dsr {

const std::vector<std::string>& view_names() {
    static const std::vector<std::string> names = {"final", "normal", "diffuse", "specular",
                                                   "depth", "blur-factor", "bloom", "ssao",
                                                   "shadow-map"};
    return names;
}

View view_from_name(const std::string& name) {
    const auto& n = view_names();
    for (size_t i = 0; i < n.size(); ++i)
        if (name == n[i]) return View(i);
    std::string list;
    for (const auto& v : n) list += (list.empty() ? "" : "|") + v;
    throw Error("expected a view name (" + list + "), got '" + name + "'");
}

const char* view_name(View v) { return view_names()[size_t(v)].c_str(); }

}  // namespace dsr
