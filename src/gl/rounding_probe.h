// How this GL turns a fragment's colour into an RGBA8 target's bytes, measured (issue 12: the
// tiles geometry sums several lights in a shader and rounds each as its own pass would be rounded;
// that is exact only if the GL rounds the way the shader assumes). `dsr info` prints it.
#pragma once
#include <string>

namespace dsr {

struct Unorm8Rounding {
    bool measured = false;   // false without framebuffer objects
    // v/255 written (no blending) into an RGBA8 target with GL_DITHER off: the byte read back,
    // for v = 0.4, 0.6, 1.5, 2.5 (round to nearest gives 0, 1, 2 or 3 (ties), 3 or 2 (ties)).
    int plain[4] = {0, 0, 0, 0};
    // 0.6/255 added 10 times (GL_ONE, GL_ONE) onto 0: 10 where each pass rounds to nearest.
    int added_ten = 0;
    // The same 1.5/255 write over a 4x4 block with GL_DITHER on: the smallest and largest byte
    // (equal where the GL does not dither 8-bit targets).
    int dither_min = 0, dither_max = 0;
};

// Needs a current context with EXT_framebuffer_object; draws into a 4x4 target of its own and
// leaves the state cache reset (gl_state().reset()).
Unorm8Rounding probe_unorm8_rounding();
std::string describe(const Unorm8Rounding& r);

}  // namespace dsr
