// `--show-lights` (forward_stage.h): the size of a light's marker. Pure, no GL.
#pragma once

namespace dsr {

// The marker's share of the viewport height (its radius): 0.008 is 4 pixels at 512 rows, small
// beside the tutorial's scenes and big enough for bloom (§3.5.2) to pick up, as Figure 11's
// highlights are.
constexpr float kMarkerScreenFraction = 0.008f;

// The world radius of a sphere at eye distance `eye_distance` whose projection is `fraction` of
// the viewport's height, for a perspective projection with P[1][1] = `proj11` (cot of half the
// vertical field of view): the visible height at that distance is 2 d / P[1][1]. Markers keep one
// size on screen however far their light is. 0 for a point at or behind the eye.
float marker_radius(float eye_distance, float proj11, float fraction = kMarkerScreenFraction);

}  // namespace dsr
