// The configurations that reach the shader table's rows, shared by the desktop table test
// (test_frame_def.cpp) and the GLSL ES one (test_gles2.cpp): each is options plus the
// capabilities forced off (--caps names).
#pragma once
#include <string>
#include <vector>

#include "deferred/options.h"

namespace dsr::test {

struct TableConfig {
    ShaderOptions options;
    std::vector<std::string> off;
};

// Bloom and SSAO; each light geometry but quad with the light markers (the depth hand-off's pass),
// packed depth and shadowed lights (the shadow forms); the hand-off writing the ambient term (no
// ambient target); one material program per G-buffer target (no MRT).
inline std::vector<TableConfig> common_table_configs() {
    std::vector<TableConfig> out;
    ShaderOptions o;
    o.post.bloom = true;
    o.ssao.on = true;
    out.push_back({o, {}});
    for (LightGeometry g : {LightGeometry::volume, LightGeometry::stencil, LightGeometry::tiles, LightGeometry::screen}) {
        ShaderOptions t;
        t.light_geometry = g;
        t.show_lights = true;
        t.depth_handoff = DepthHandoff::pass;
        t.depth = DepthPath::packed;
        t.shadow_lights = true;
        t.shadows.filter = g == LightGeometry::volume ? ShadowFilter::pcf5 : ShadowFilter::hard;
        out.push_back({t, g == LightGeometry::stencil ? std::vector<std::string>{"no-depth-texture"} : std::vector<std::string>{}});
    }
    ShaderOptions handoff;
    handoff.light_geometry = LightGeometry::volume;
    handoff.depth_handoff = DepthHandoff::pass;
    handoff.skip.ambient_target = false;
    out.push_back({handoff, {}});
    out.push_back({ShaderOptions{}, {"no-mrt"}});
    return out;
}

}  // namespace dsr::test
