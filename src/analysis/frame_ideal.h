// The ideal light-pass fragment count of the frame a DeferredShader just rendered (`render
// --stats` "ideal_fragments"), by the one count of ideal_fragments.h (ideal_count: each light's
// volume, cones for spot lights): on the depth-texture path from the G-buffer's 24-bit depth
// codes decoded in double (as the bench's `depth24` source and the viewer's panel), on the other
// paths from the positions the light shader reconstructs. Reads the G-buffer back: call only
// when the count is asked for.
#pragma once
#include <optional>
#include <string>

#include "deferred/deferred_shader.h"
#include "scene/scene.h"

namespace dsr {

struct FrameIdeal {
    std::optional<long long> fragments;  // null where it cannot be read back (packed without float targets)
    std::string source;                  // "depth24" | "packed" | "position16" | "position32" | why not
};

FrameIdeal frame_ideal_fragments(DeferredShader& ds, const Scene& scene);

}  // namespace dsr
