// The rectangles the light pass scissors each drawn light to (Listing 16-17), for the viewer's
// overlay: the same culling and the same light_scissor as DeferredShader::draw_lighting, from the
// matrices of the frame just drawn. Pure math.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "deferred/scissor.h"
#include "scene/scene.h"

namespace dsr {

struct LightRect {
    int light;       // index into scene.lights
    ScissorRect rect;  // GL window pixels, origin bottom-left
};

// One entry per light the pass draws: inside the frustum, with colour (when skip_empty) and a
// non-empty rectangle (when skip_empty; else the whole viewport). With scissors off, the whole
// viewport for each drawn light, as the pass shades it.
std::vector<LightRect> light_scissor_rects(const Scene& scene, const glm::mat4& view, const glm::mat4& proj, int width,
                                           int height, bool scissors, bool skip_empty);

}  // namespace dsr
