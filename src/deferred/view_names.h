// What `--view` shows (the same names in every interface): the final image, a G-buffer
// target (Figure 4), the anti-alias blur factor (Figure 8), the bloom blur (Figure 10c) or the
// blurred ambient-occlusion buffer or a light's shadow map. Pure data, no GL.
#pragma once
#include <string>
#include <vector>

namespace dsr {

// shadow_map: the first shadowed visible light's map, depth as grey (white: far or empty).
enum class View { final, normal, diffuse, specular, depth, blur_factor, bloom, ssao, shadow_map };
// "final", "normal", …, "blur-factor", "bloom"; throws dsr::Error listing the names otherwise.
View view_from_name(const std::string& name);
const char* view_name(View v);
// Every view's name, in View order (what `--view` accepts).
const std::vector<std::string>& view_names();

}  // namespace dsr
