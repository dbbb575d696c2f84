// How this GL turns a fragment's colour into an RGBA8 target's bytes, measured (docs/light_geometry.md:
// the tiles geometry sums several lights in a shader and rounds each as its own pass would be rounded;
// that is exact only if the GL rounds the way the shader assumes). `dsr info` prints it.
#pragma once
#include <algorithm>
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
    // Where the rounding turns up: for (k + f)/255 written with f swept over [0.35, 0.65] in steps
    // of 0.0005, the smallest f that gives byte k + 1, for every k in 0..254 (0.5 for round to
    // nearest, ties up; 0.5005 where exact ties go down; -1 where no f in the sweep did).
    float threshold[255];
    // The same for (k + f)/255 added (GL_ONE, GL_ONE) onto j/255, for j in kAddJ and k in kAddK:
    // byte j + k + 1 from f = added[j][k]. Equal to threshold[k] where the GL rounds the source
    // before the add, to threshold[j + k] where it rounds the sum.
    static constexpr int kAddJ[5] = {0, 50, 100, 150, 200};
    static constexpr int kAddK[3] = {0, 1, 20};
    float added[5][3];
    Unorm8Rounding() {
        std::fill(threshold, threshold + 255, -1.0f);
        std::fill(&added[0][0], &added[0][0] + 15, -1.0f);
    }
};

// Needs a current context with EXT_framebuffer_object; draws into a 4x4 target of its own and
// leaves the state cache reset (gl_state().reset()).
Unorm8Rounding probe_unorm8_rounding();
// The probe's result for this process, measured on first call (the GL's rounding does not change).
const Unorm8Rounding& unorm8_rounding();
// What to add to t * 255 before floor() to round as this GL does: 0.5 where the sweep's
// thresholds lie within a step of the half (round to nearest, whatever the ties), else 1 minus
// their median; 0.5 when not measured. The fallback where no model below fits.
float unorm8_round_offset(const Unorm8Rounding& r);

// The conversion model that reproduces every measured threshold (to the sweep's step):
//   0   round to nearest: byte = round(t * 255) (llvmpipe)
//   n   t first truncated to n fractional bits, then rounded: byte = round(floor(t * 2^n) / 2^n * 255)
//       (n = 12 on the GPU of docs/gpu.md, "Images on a GPU", which shows its thresholds)
//   -1  none of n = 8..16 fits but for at most 8 thresholds (or nothing was measured)
// The thresholds each model predicts come from the same float arithmetic the probe's points had.
int unorm8_truncate_bits(const Unorm8Rounding& r);
// How many of the 255 thresholds model `bits` misses by more than a step (`which`: the first few).
int unorm8_model_misfits(const Unorm8Rounding& r, int bits, std::string* which = nullptr);
// The threshold model n predicts for k, on the probe's grid of f (-1: none on the grid).
float predicted_threshold(int bits, int k);
std::string describe(const Unorm8Rounding& r);

}  // namespace dsr
