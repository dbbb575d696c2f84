#include "deferred/light_marker.h"

namespace dsr {

float marker_radius(float eye_distance, float proj11, float fraction) {
    if (!(eye_distance > 0) || !(proj11 > 0)) return 0;
    return fraction * 2.0f * eye_distance / proj11;
}

}  // namespace dsr
