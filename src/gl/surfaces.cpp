#include "gl/surfaces.h"

namespace dsr {

namespace {
OffscreenSurfaces* g_surfaces = nullptr;
}

OffscreenSurfaces* offscreen_surfaces() { return g_surfaces; }
void set_offscreen_surfaces(OffscreenSurfaces* s) { g_surfaces = s; }

}  // namespace dsr
