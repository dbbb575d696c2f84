// Light geometry `volume` (LearnOpenGL "Light volumes"; Vasilovici §4.2): each light draws the
// back faces of a closed mesh enclosing its sphere, front faces culled, with the depth test
// GL_GREATER against the scene's depth (handed to P-buffer 0 by the depth hand-off): a pixel
// enters the light shader only where the scene surface lies in front of the volume's far side.
// Back faces rather than front ones so the camera may stand inside the volume (its front faces
// are then behind the eye and clipped away). A light whose mesh reaches past the far plane would
// lose its clipped back faces: it is drawn as its scissored quad instead (light_mesh.h).
#include "deferred/light_geometry.h"
#include "deferred/light_mesh.h"
#include "deferred/light_pass.h"

namespace dsr {

namespace {

class VolumeGeometry final : public LightGeometryPass {
public:
    VolumeGeometry(const ShaderConfig& c, ProgramSet& programs)
        : quads_(programs, false), progs_(programs, "light_volume"), batch_(programs, c.tile_batch, meshes_) {}

    void draw(const FrameDef& f, RenderTargets&, LightQueries& q, FrameStats& stats) override {
        meshes_.draw_quads_past_far(f, quads_, q, stats);
        std::vector<const LightDraw*> lights;
        for (const LightDraw& l : f.lights)
            if (!meshes_.past_far(f, l)) lights.push_back(&l);
        meshes_.shade_volumes(f, lights, batch_, progs_, q, stats);
    }

private:
    LightQuads quads_;
    LightMeshes meshes_;
    LightPrograms progs_;
    LightVolumeBatch batch_;
};

}  // namespace

std::unique_ptr<LightGeometryPass> make_volume_geometry(const ShaderConfig& c, ProgramSet& programs) {
    return std::make_unique<VolumeGeometry>(c, programs);
}

}  // namespace dsr
