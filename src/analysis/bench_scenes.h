// N-light variants of a scene for `dsr bench`: the scene's geometry, camera and materials kept,
// its lights replaced by N generated ones spread over the floor of its bounding box. No GL.
#pragma once
#include <cstdint>

#include "scene/scene.h"

namespace dsr {

// `scene` with exactly n lights. Centres are stratified over the x-z extent of the meshes'
// bounding box (one jittered cell per light, so they cover the floor evenly), floating a fraction
// of their radius above its bottom so every sphere meets the floor. Radii make each floor point
// lie in about 2.5 spheres on average (moderate overlap, independent of n); colours are
// saturated hues whose brightness falls with that overlap so sums stay mostly below 1.
// Every 8th light is switched off (colour 0), as in a scene whose lights are toggled: the work
// the empty-light skip avoids. n = 0 gives a scene with no lights. Throws dsr::Error for a scene
// without meshes or n < 0.
Scene with_generated_lights(const Scene& scene, int n);

}  // namespace dsr
