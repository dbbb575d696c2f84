// The ideal light-pass fragment count of the frame a DeferredShader just rendered (`render
// --stats` "ideal_fragments"): from the G-buffer's 24-bit depth codes decoded in double on the
// depth-texture path (as the bench's `depth24` source), from the packed target's positions as
// the light shader reconstructs them on the packed path. Reads the G-buffer back: call only when
// the count is asked for.
#pragma once
#include <optional>
#include <string>

#include "deferred/deferred_shader.h"
#include "scene/scene.h"

namespace dsr {

struct FrameIdeal {
    std::optional<long long> fragments;  // null where it cannot be read back (packed without float targets)
    std::string source;                  // "depth24" | "packed" | why not
};

FrameIdeal frame_ideal_fragments(DeferredShader& ds, const Scene& scene);

}  // namespace dsr
