// The material model's cost in `dsr bench`: each variant's metallic-roughness row (bench_run.h
// Row::metal_rough, the scene's metal_rough_twin) against its default quad row (the scene as it
// is), timed in the same rounds on the same pixel-light pairs. The figure is the light stage's
// median ms of each and their ratio, which is the ratio per pair where both passed the same
// samples (docs/metal_rough.md, "Measured").
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "analysis/bench_run.h"

namespace dsr::bench {

struct MaterialCost {
    const Row* phong = nullptr;        // dsr's default configuration with quad, on the scene
    const Row* metal_rough = nullptr;  // the same, every material metallic-roughness
    double ratio = 0;                  // metal_rough's lights_ms / phong's
    // The light stage's ns per pixel-light pair (lights_ms / light_fragments), where counted.
    std::optional<double> phong_ns, metal_rough_ns;
};

// Every variant's pair, in the rows' order; a variant without both rows or their light stages has none.
std::vector<MaterialCost> material_costs(const std::vector<Row>& rows);
// One line for the terminal: "default at 256 lights, quad: light stage 2.45 ms metallic-roughness /
// 2.01 ms Phong = 1.22 on the same 123456 pixel-light pairs (19.8 / 16.3 ns a pair)".
std::string material_cost_text(const MaterialCost& c);
// The report's section: a table of every pair, and how the rows are made.
std::string material_cost_markdown(const std::vector<Row>& rows);

}  // namespace dsr::bench
