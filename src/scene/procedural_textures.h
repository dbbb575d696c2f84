// The default scene's material maps, generated rather than shipped from elsewhere so their
// origin is known and they can be regenerated bit for bit (`dsr gen-textures DIR`).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "scene/image.h"

namespace dsr {

// Size of every generated texture (square, power of two so mipmaps and wrapping are exact).
constexpr int kProceduralTextureSize = 256;

// Named 256x256 images, in a fixed order: brick_, stone_ and metal_ with _diffuse, _normal and
// _specular each (e.g. "brick_normal.png"). Every family comes from one periodic height field:
// the diffuse colour follows it, the tangent-space normal map is its gradient
// (RGB = n*0.5+0.5, +x along increasing column = +u, +y along increasing row = +v since rows
// are bottom first, +z out of the surface) and the grey specular map is low in the joints.
// All tile seamlessly. Values are already quantized to k/255, so writing them as 8-bit PNG
// and loading them back gives the same floats. Deterministic: an integer hash drives the
// noise, and only + - * / sqrt touch the floats.
std::vector<std::pair<std::string, Image>> default_textures();

// The same for the generated model's own materials (scene/generated_model.h): wood_ (vertical
// boards) and shingle_ (roof shingles), each _diffuse, _normal and _specular, made the same way.
std::vector<std::pair<std::string, Image>> model_textures();

}  // namespace dsr
