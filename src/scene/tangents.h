// Tangent frames from texture coordinates (Listing 10's a2v): one generic routine for every mesh,
// the OBJ loader's and the built-in shapes'. Pure, no GL.
#pragma once
#include "scene/scene.h"

namespace dsr {

// Sets every vertex's tangent (direction of +u) and binormal (direction of +v) from the
// triangles' positions and uvs, keeping each vertex's normal:
//   - per triangle, dP/du and dP/dv solved in double, each normalised and weighted by the
//     triangle's area, summed per vertex;
//   - per vertex, the tangent is Gram-Schmidt orthonormalised against the normal and the
//     binormal is sign * cross(normal, tangent), sign = -1 where the uv map is mirrored
//     (dP/dv points against cross(n, t)), so handedness is kept and the frame is orthonormal;
//   - triangles with degenerate uvs (zero uv area) or zero area contribute nothing; a vertex with
//     no usable triangle, a tangent parallel to its normal or no uvs at all gets an arbitrary
//     frame perpendicular to the normal (never NaN).
// A zero or non-finite normal is replaced by the area-weighted face normal, else +Z.
void compute_tangents(Mesh& mesh);

}  // namespace dsr
