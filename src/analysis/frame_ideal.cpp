#include "analysis/frame_ideal.h"

#include "analysis/ideal_fragments.h"
#include "dsr_error.h"

namespace dsr {

FrameIdeal frame_ideal_fragments(DeferredShader& ds, const Scene& scene) {
    const int w = ds.width(), h = ds.height();
    FrameIdeal r;
    if (ds.options().depth == DepthPath::texture) {
        const glm::dvec2 p = projection_scale(scene.camera, w, h);
        const SurfacePoints pts = surface_from_depth_codes(ds.read_gbuffer_depth_codes(), w, h,
                                                           scene.camera.near_plane, scene.camera.far_plane, p);
        r.fragments = ideal_fragments(pts, eye_lights(scene));
        r.source = "depth24";
        return r;
    }
    std::vector<glm::vec4> lights;
    for (const glm::dvec4& l : eye_lights(scene)) lights.emplace_back(l);
    try {
        r.fragments = ideal_fragments(ds.reconstructed_positions(), lights);
        r.source = depth_path_name(ds.options().depth);  // "packed", "position16", "position32"
    } catch (const Error& e) {  // the read-back needs float targets; the count is then unknown
        r.source = e.what();
    }
    return r;
}

}  // namespace dsr
