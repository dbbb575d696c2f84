// The numerical stress sweep's cases (`dsr stress`, docs/accuracy.md): scenes built in code, with
// constant materials so each has an analytic reference, each rendered on one depth path.
//
//   ratio/<far/near>/<path>   64 camera-facing tilted tiles whose eye depths run log-spaced from
//                             just past near to just short of far, one light per tile: the depth
//                             accuracy table (far/near 1e1..1e7)
//   radius/<r>/<path>         the "room" (floor, sphere, box, two lights) scaled so that its
//                             first light's radius is r (1e-4..1e6): camera, geometry, near/far
//                             and lights scale together
//   radius-fixed/<r>/<path>   the unit room with one light of radius 1e-4 (sub-pixel) or 1e6
//                             (camera deep inside it)
//   eye-plane/<path>          lights whose centre is exactly on the eye plane (eye z = 0)
//   behind/whole|partly/...   lights wholly behind the camera, touching the eye plane from
//                             behind, and partly behind reaching into the view
//   inside/<path>             the camera inside light spheres
//   grazing/<deg>/<path>      a floor seen at 89 and 89.9 degrees from its normal
//   coords/<offset>/<path>    the room translated by offset*(1, 0.25, -1), up to 1e6
//   limit/<far/near>/<path>   the tile scene past the goal's range (2e7, 1e8), full sweep only:
//                             where the float math breaks; recorded, never counted as a failure
//   zero-normal/<path>        a quad whose vertex normals are (0,0,0); light depth and sphere
//                             tests and scissor off, so every background pixel (zero normal in
//                             the G-buffer) also runs through Listing 20's len > 0.1 branch
//   shadow/<light>/x<m>/<size>/b<bias>,s<slope>/<path>
//                             the bias sweep: data/shadow.scene's box on a floor under one shadowed
//                             light (spot, directional, point) whose depth range is m times the
//                             scene's (spot, point: the light's radius; directional: the floor and
//                             the camera's far plane, which the fitted map spans), its map `size`
//                             texels a side, with LightShadow's bias and slope; measured against
//                             the traced shadow (shadow_metrics.h: edge, acne, contact leak).
//                             <path> is texture (depth-texture maps, ARB_shadow) or packed (RGB8
//                             maps and G-buffer, `--caps no-depth-texture`)
//
// <path> is texture (24-bit depth texture), one of the packed target's encodings: literal,
// corrected, linear, log, or a stored position: position16 (RGBA16F), position32 (RGBA32F)
// (ratio cases, and coords/0 and coords/1e6).
#pragma once
#include <string>
#include <vector>

#include "deferred/deferred_shader.h"
#include "scene/scene.h"

namespace dsr {

struct StressCase {
    std::string name;       // e.g. "ratio/1e6/log"
    std::string category;   // the part before the first '/'
    std::string path;       // "texture" or an encoding name
    Scene scene;
    int width = 256, height = 256;
    // depth path, encoding, skips, scissor (the runner sets --accum float); the tutorial's quad per
    // light unless `dsr stress --light-geometry` says otherwise
    ShaderOptions opts = [] {
        ShaderOptions o;
        o.light_geometry = LightGeometry::quad;
        return o;
    }();
    double far_near = 0;    // the camera's far/near
    double light_radius = 0;                // the first light's radius (0: no lights)
    std::vector<int> no_reference_meshes;   // meshes left out of the LSB comparison (zero normals
                                            // have no defined shading in the reference)
    bool limit = false;     // beyond the required range: its invariants are reported, not required
    std::vector<std::string> caps_off;  // capabilities forced off (probe_caps): the packed shadow maps
    // Shadow cases: the scene's one light casts the shadow of object shadow_occluder onto object
    // shadow_receiver; shadow_range is the depth range's multiple of the base scene's.
    bool shadow = false;
    std::string shadow_light;  // "spot", "directional", "point"
    int shadow_receiver = 0, shadow_occluder = 1;
    double shadow_range = 1;
};

// Depth paths in table order: texture, literal, corrected, linear, log, position16, position32.
const std::vector<std::string>& stress_paths();
// Sets opts.depth / opts.encoding for a name of stress_paths(); throws dsr::Error otherwise.
void set_depth_path(ShaderOptions& opts, const std::string& path);

// Far/near ratios of the accuracy table: 1e1 .. 1e7.
const std::vector<double>& stress_ratios();

// The full sweep, or the quick subset (the accuracy ratios 1e2, 1e4, 1e6 on every path and one
// of each special case on the depth-texture path). Cases are built on the call.
std::vector<StressCase> stress_cases(bool quick);

// The tile scene of the ratio cases (exposed for tests): near 0.1, far 0.1 * far_near.
Scene depth_range_scene(double far_near);

// The bias sweep's grid (the shadow cases): depth-range multiples, map sizes, and the bias and
// slope values; every pair of a bias and a slope is run at each (range, size) setting.
struct ShadowSweep {
    std::vector<double> ranges;                 // with the default map size
    std::vector<int> sizes;                     // at range 1
    std::vector<double> biases, slopes;
};
const ShadowSweep& shadow_sweep();
// The shadow cases' scene: data/shadow.scene's box on a floor with one of its lights ("spot",
// "directional", "point"; throws dsr::Error otherwise), its depth range `range` times the file's.
Scene shadow_case_scene(const std::string& light, double range, const LightShadow& shadow);

}  // namespace dsr
