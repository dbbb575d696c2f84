// The ambient pass folded into a light pass (SkipOptions::ambient_pass): where the frame draws a
// light over the whole screen (a directional light, or any light with the scissors off), that
// light's pass can write what the clear and Listing 15's ambient pass would have left under it,
// blending off, and the ambient pass is not drawn. Pure: which light, and the frame without it
// that the light geometry draws after it.
#pragma once
#include <cstddef>
#include <optional>

#include "deferred/frame.h"

namespace dsr {

// The first of the frame's lights drawn over the whole screen (LightDraw::full), by its index in
// f.lights; none where no light is.
std::optional<size_t> full_screen_light(const FrameDef& f);

// A copy of `f` without f.lights[i] (every other value kept, lights_total included).
FrameDef without_light(const FrameDef& f, size_t i);

}  // namespace dsr
