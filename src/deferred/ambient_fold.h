// The ambient pass folded into a light pass (SkipOptions::ambient_pass): where the frame draws a
// light over the whole screen (a directional light, or any light with the scissors off), that
// light's pass can write what the clear and Listing 15's ambient pass would have left under it,
// blending off, and the ambient pass is not drawn. Pure: which light, the frame without it that the
// light geometry draws after it, and the colours any pass that writes the ambient term takes.
#pragma once
#include <cstddef>
#include <optional>

#include "deferred/frame.h"

namespace dsr {

// Listing 15's colours wherever a pass other than the ambient pass writes its term: the colour
// P-buffer 0 is cleared to (where the G-buffer holds no surface) and the ambient colour the diffuse
// target is scaled by. The material pass (Paths::ambient_target), the fold's light pass and the
// screen geometry's first batch take it.
struct AmbientTerm {
    glm::vec3 background{0}, ambient{0};
};

// The first of the frame's lights drawn over the whole screen (LightDraw::full), by its index in
// f.lights; none where no light is.
std::optional<size_t> full_screen_light(const FrameDef& f);

// A copy of `f` without f.lights[i] (every other value kept, lights_total included).
FrameDef without_light(const FrameDef& f, size_t i);

}  // namespace dsr
