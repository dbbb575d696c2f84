// The light geometries' factory (light_geometry.h): the one place that names every geometry's class.
#include "deferred/light_geometry.h"

#include "dsr_error.h"

namespace dsr {

// Each defined in its geometry's file.
std::unique_ptr<LightGeometryPass> make_quad_geometry(const ShaderConfig& c, ProgramSet& programs);
std::unique_ptr<LightGeometryPass> make_volume_geometry(const ShaderConfig& c, ProgramSet& programs);
std::unique_ptr<LightGeometryPass> make_stencil_geometry(const ShaderConfig& c, ProgramSet& programs);
std::unique_ptr<LightGeometryPass> make_tiles_geometry(const ShaderConfig& c, ProgramSet& programs, int width,
                                                       int height);
std::unique_ptr<LightGeometryPass> make_auto_geometry(const ShaderConfig& c, ProgramSet& programs, int width,
                                                      int height);
std::unique_ptr<LightGeometryPass> make_screen_geometry(const ShaderConfig& c, ProgramSet& programs);

std::unique_ptr<LightGeometryPass> make_light_geometry(const ShaderConfig& c, ProgramSet& programs, int width,
                                                       int height) {
    switch (c.paths.light_geometry) {
        case LightGeometry::quad: return make_quad_geometry(c, programs);
        case LightGeometry::volume: return make_volume_geometry(c, programs);
        case LightGeometry::stencil: return make_stencil_geometry(c, programs);
        case LightGeometry::tiles: return make_tiles_geometry(c, programs, width, height);
        case LightGeometry::automatic: return make_auto_geometry(c, programs, width, height);
        case LightGeometry::screen: return make_screen_geometry(c, programs);
    }
    return nullptr;
}

}  // namespace dsr
