// Framing: what a scene holds in world space and a camera that shows it. Behind the `.obj`
// shortcut (a model is a scene: model_scene), the scene file's `camera fit`, the viewer's F key
// and the bounds `--stats` reports. Pure: no GL.
#pragma once
#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace dsr {

// Every vertex a triangle uses, after its object's transform, in double.
struct SceneBounds {
    glm::dvec3 min{0}, max{0};  // axis-aligned box
    glm::dvec3 centre{0};       // the box's centre
    double radius = 0;          // farthest vertex from centre: the bounding sphere framing uses
    size_t vertices = 0;        // counted (0: nothing to frame)
    bool finite = true;         // false when any transformed coordinate is NaN or infinite
};

SceneBounds scene_bounds(const Scene& scene);

// Why bounds cannot be framed ("no triangles", "a coordinate that is not finite", "every vertex
// at one point"); "" when they can.
std::string unframeable(const SceneBounds& b);

// The documented defaults: the camera looks at the centre from direction (1, 1, 2), i.e. from
// the front (+Z), to the right (+X) and above (+Y), about 27 degrees right and 24 up; a vertical
// field of view of 45 degrees; the bounding sphere's projection kFitFill of the image height (of
// the width when the image is taller than wide).
inline const glm::vec3 kFitFrom{1.0f, 1.0f, 2.0f};
constexpr float kFitFovDeg = 45.0f;
constexpr double kFitFill = 0.7;

// A camera on the ray centre + t * from that shows the bounding sphere at kFitFill of the
// image's smaller dimension, for an image of `aspect` (width / height). up is +Y (-Z when from
// is nearly vertical). near and far hug the sphere (near half the gap to its front, far 5%
// beyond its back), so far / near is about 4 at 45 degrees (8 at 90) and both depth paths keep
// their precision.
// Expects bounds that unframeable() accepts and a non-zero `from`.
Camera fit_camera(const SceneBounds& b, glm::vec3 from, float fov_deg, float aspect);

// The scene file's `camera fit [from X Y Z] [fov DEG]`, resolved once every object is placed.
struct CameraFit {
    glm::vec3 from = kFitFrom;
    float fov_deg = kFitFovDeg;
    std::string where;  // "FILE:LINE" of the camera line, for the error
};
// Frames what `scene` holds (aspect 1: landscape images keep the vertical fill). Throws
// dsr::Error "FILE:LINE: camera fit: expected something to frame, got <why>" when it cannot.
void apply_camera_fit(Scene& scene, const CameraFit& fit);

// The viewer's F key: `current` moved back along its own view direction so it frames `scene`
// (its fov kept, near and far from the bounds); `current` unchanged when nothing can be framed.
Camera reframe(const Scene& scene, const Camera& current, float aspect);

// The material model_scene gives its ground plane.
inline const char* const kGroundMaterial = "(ground)";

// A model is a scene: the OBJ or glTF file at `path` (glTF also when `gltf`, whatever its name)
// drawn as it is (object space = world space). The camera: the file's first camera
// (options.camera picks another), else fit_camera(options.from or kFitFrom, kFitFovDeg, aspect
// 1). The lights: the file's own (glTF's KHR_lights_punctual, with no ambient term), else a
// ground plane just under its lowest point (a square 8 bounding radii across, neutral grey,
// kGroundMaterial) and three point lights with Equation 2's radius, placed and sized from the
// bounding sphere: a warm key from the front-right above casting a shadow, a dim cool fill from
// the left, a rim light from behind. options.ambient replaces the ambient term. Throws dsr::Error
// naming the file: the reader's errors, or "PATH: expected a model with finite, non-empty bounds,
// got <why>", or a model too small, or too narrow for its distance from the origin, to draw in
// 32-bit floats (kModelPrecision, kMinModelRadius).
Scene model_scene(const std::string& path, const LoadOptions& options = {}, bool gltf = false);

// A model's bounding radius must be at least kModelPrecision times its farthest point's distance
// from the origin (about one step of a 32-bit float there), and at least kMinModelRadius.
constexpr double kModelPrecision = 1e-7;
constexpr double kMinModelRadius = 1e-12;

// True for a path ending ".obj", ".gltf" or ".glb" in any case: where a scene is expected, such a
// path is a model.
bool is_model_path(const std::string& path);

}  // namespace dsr
