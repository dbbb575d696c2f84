// The ambient pass's fold into a full-screen light (ambient_fold.h).
#include "deferred/ambient_fold.h"

namespace dsr {

std::optional<size_t> full_screen_light(const FrameDef& f) {
    for (size_t i = 0; i < f.lights.size(); ++i)
        if (f.lights[i].full && f.lights[i].shadow < 0) return i;  // the fold's pass has no shadow lookup
    return std::nullopt;
}

FrameDef without_light(const FrameDef& f, size_t i) {
    FrameDef out = f;
    if (i < out.lights.size()) out.lights.erase(out.lights.begin() + std::ptrdiff_t(i));
    return out;
}

}  // namespace dsr
