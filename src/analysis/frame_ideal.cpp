// `render --stats`' ideal count (frame_ideal.h): the G-buffer read back, then ideal_count.
#include "analysis/frame_ideal.h"

#include "analysis/ideal_fragments.h"
#include "dsr_error.h"

namespace dsr {

FrameIdeal frame_ideal_fragments(DeferredShader& ds, const Scene& scene) {
    const int w = ds.width(), h = ds.height();
    FrameIdeal r;
    // The path the renderer runs (choose_paths), not the one asked for: `--depth auto` asks for none.
    const DepthPath path = ds.paths().depth_path;
    if (path == DepthPath::texture) {
        r.fragments = ideal_count_from_depth_codes(ds.read_gbuffer_depth_codes(), w, h, scene.camera, scene.lights);
        r.source = "depth24";
        return r;
    }
    try {
        r.fragments = ideal_count(surface_from_positions(ds.reconstructed_positions(scene.camera)), scene.lights,
                                  scene.camera.view_d());
        r.source = depth_path_name(path);  // "packed", "position16", "position32"
    } catch (const Error& e) {  // the read-back needs float targets; the count is then unknown
        r.source = e.what();
    }
    return r;
}

}  // namespace dsr
