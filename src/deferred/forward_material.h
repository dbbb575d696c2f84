// A material as forward.frag takes it (Listings 3-4): the forward renderers and the transparent
// pass set it the same way.
#pragma once
#include "deferred/gpu_scene.h"
#include "gl/program.h"

namespace dsr {

// Sets the bound program's diffuse, specular, shininess (exact, not the G-buffer's 8-bit code)
// and tile uniforms, and binds the material's normal, diffuse and specular maps on units 0-2;
// leaves unit 0 active.
void set_forward_material(Program& prog, const GpuMaterial& m, float shininess);

}  // namespace dsr
