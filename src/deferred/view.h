// What `--view` shows (the same names in every interface): the final image, a G-buffer
// target (Figure 4), the anti-alias blur factor (Figure 8), the bloom blur (Figure 10c) or the
// blurred ambient-occlusion buffer. Pure data, no GL.
#pragma once
#include <string>
#include <vector>

namespace dsr {

enum class View { final, normal, diffuse, specular, depth, blur_factor, bloom, ssao };
// "final", "normal", …, "blur-factor", "bloom"; throws dsr::Error listing the names otherwise.
View view_from_name(const std::string& name);
const char* view_name(View v);
// Every view's name, in View order (what `--view` accepts).
const std::vector<std::string>& view_names();

}  // namespace dsr
