// The environment variables dsr honours, read here and nowhere below src/app/: each is the
// default of a flag that names it (`dsr COMMAND --help`, docs/cli.md), handed down as that flag's
// value is, by parameter or by the setter the flag calls.
//   DSR_CAPS              --caps: capabilities hidden, before the flag's
//   DSR_CONTEXT           --context
//   DSR_EGL_DEVICE        --egl-device
//   DSR_LIGHT_COST_SCALE  --light-cost-scale
//   DSR_GL_STATE_CACHE    --gl-state-cache
//   DSR_DEBUG_GL          --debug-gl
//   DSR_TIMING            --timing
#pragma once
#include <array>
#include <optional>
#include <string>

#include "platform/context.h"

namespace dsr {

struct ContextSettings;

// $DSR_CAPS, then `flags` (--caps), comma-separated.
std::string caps_with_environment(const std::string& flags);

// The context to create: --context, else $DSR_CONTEXT, else the build's first backend; --egl-device,
// else $DSR_EGL_DEVICE, else 0.
ContextDesc context_desc(const ContextSettings& c, int width, int height);

// --light-cost-scale's default: $DSR_LIGHT_COST_SCALE's "Q,V,T", none where unset; throws
// dsr::Error naming the variable where it is not three positive numbers.
std::optional<std::array<double, 3>> light_cost_scale_from_environment();

// The GL switches' defaults, set before the command line is parsed (a flag then overrides):
// $DSR_GL_STATE_CACHE=off, $DSR_DEBUG_GL (set and not 0), $DSR_TIMING=wall|gpu-timer.
void apply_gl_environment();

}  // namespace dsr
