// The order transparent objects are blended in (docs/forward.md): back to front by object, the
// distance from the eye to each object's bounding-sphere centre, farthest first (LearnOpenGL's
// "Blending": sort by distance, draw the farthest first). Per object, not per triangle: two
// objects that interpenetrate, or one object that overlaps itself, blend in a fixed order that
// can be wrong for some of their pixels (docs/guide.md, "Transparent surfaces"). Pure, no GL.
#pragma once
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "scene/bounds.h"

namespace dsr {

// `objects`: indices into `bounds`; returns them farthest first from `eye` (world space, the
// distances in double). Equal distances keep their order in `objects` (a stable sort), so
// the result never depends on the sort's whims.
std::vector<size_t> transparent_order(const std::vector<size_t>& objects, const std::vector<ObjectBounds>& bounds,
                                      const glm::dvec3& eye);

}  // namespace dsr
