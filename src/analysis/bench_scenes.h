// N-light variants of a scene for `dsr bench`: the scene's geometry, camera and materials kept,
// its lights replaced by N generated ones spread over the floor of its bounding box. No GL.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

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

// `--lights` items beyond plain counts (docs/light_geometry.md measures the geometries on them):
//   spread   N         with_generated_lights (above)
//   overlap  N-overlap with_overlapping_lights: every lit pixel inside at least 8 lights
//   large    N-large   large_lights_scene: LearnOpenGL's demo, the base scene replaced
//   shadow   N-shadow  with_shadowed_spots: N spot lights casting shadows (docs/shadows.md);
//            own-shadow: the scene's own lights, each casting shadows
enum class LightSet { spread, overlap, large, shadow };
struct LightSpec {
    int count = -1;  // -1: the scene's own lights ("own")
    LightSet set = LightSet::spread;
};
// "own", "own-shadow", "N", "N-overlap", "N-large" or "N-shadow" with N in [0, 65536] (overlap: a multiple of 8); nullopt
// for anything else.
std::optional<LightSpec> parse_light_spec(const std::string& item);
// The bench variant of `base` a spec stands for, and its name in the tables: the base name,
// "NAME-overlap", or "large" (not a variant of the base: the same for every base).
Scene bench_scene(const Scene& base, const LightSpec& spec);
std::string bench_scene_name(const std::string& base_name, const LightSpec& spec);

// n lights (a multiple of 8, else dsr::Error) in n / 8 clusters of 8 that share a centre and a
// radius (placed as with_generated_lights places n / 8 lights, so clusters overlap about 2.5-fold
// too), each of the 8 its own hue at 1/8 of the brightness: a pixel inside one light is inside its
// 7 cluster mates, so every lit pixel lies in at least 8 lights (16.7 on average at sampled points), the
// many-lights-per-pixel case that multi-light passes exist for. No light is switched off.
Scene with_overlapping_lights(const Scene& scene, int n);

// LearnOpenGL's deferred shading demo (5.8.1) as a dsr scene, as its source sets it up: its 9
// objects as unit boxes at its object positions (a 3 x 3 grid of spacing 3 at y = -0.5; constant
// materials, so the scene has an analytic reference), its camera at (0, 0, 5) looking down -z with
// a 45 degree fov, its hard-coded ambient (0.1 x the diffuse colour), and n lights drawn as the
// demo draws them after srand(13) (glibc's rand(), reproduced here on every platform): positions
// in [-3, 3) x [-4, 2) x [-3, 3), colours in [0.5, 1) per channel, LearnOpenGL's attenuation
// (1, 0.7, 1.8) cut at the threshold 5/256 (radii 3.9-5.1, rectangles over most of the screen:
// tests/test_bench_scenes.cpp). n = 32 is the demo's own set; larger n continue the same sequence.
Scene large_lights_scene(int n);

// `scene` with every light of the attenuation law given Equation 2's linear law at the same radius
// (its volume, scissor rectangle and pixels unchanged; only the law's arithmetic differs): the
// bench's linear-law rows on N-large, which price the attenuation law's light programs against the
// tutorial's on the same pixel-light pairs (goal `law`).
Scene linear_law_twin(Scene scene);

// `scene` with every Phong material made metallic-roughness (docs/metal_rough.md): its diffuse
// colour and map as the base colour and map, its normal map kept, metallic 0, and the roughness
// whose GGX width matches its shininess n, (2 / (n + 2))^(1/4) (Walter et al. 2007's Beckmann
// width sqrt(2 / (n + 2)) taken as glTF's alpha = roughness^2). Geometry and lights are unchanged,
// so every light reaches the same pixels: the bench's metallic-roughness rows price the material
// model's light shader against Phong's on the same pixel-light pairs (bench_run.h Row::metal_rough).
Scene metal_rough_twin(Scene scene);
// Whether `scene` has a Phong material, which metal_rough_twin would change.
bool has_phong_material(const Scene& scene);

// with_generated_lights' n lights made spot lights with `shadow` (the default map): each at its
// place raised by half its radius, shining straight down with a 50-degree half-angle, so the
// objects between it and the floor cast shadows on it. The bench's shadow rows.
Scene with_shadowed_spots(const Scene& scene, int n);
// `scene` with every light casting shadows (the default scene's point lights: six faces each).
Scene with_shadowed_lights(Scene scene);
// The demo's window (its SCR_WIDTH x SCR_HEIGHT): the size `dsr bench` runs N-large at unless
// --size is given (bench_run.h variant_size).
constexpr int kDemoWidth = 800, kDemoHeight = 600;

}  // namespace dsr
