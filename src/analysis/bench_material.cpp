// The material model's cost in `dsr bench` (bench_material.h).
#include "analysis/bench_material.h"

#include <sstream>

#include "analysis/number_format.h"

namespace dsr::bench {

namespace {
std::optional<double> ns_per_pair(const Row& r) {
    const std::optional<long long> f = light_fragments(r);
    if (!f || *f <= 0 || !r.lights_ms) return std::nullopt;
    return *r.lights_ms * 1e6 / double(*f);
}

std::string pairs_text(const MaterialCost& c) {
    const std::optional<long long> a = light_fragments(*c.metal_rough), b = light_fragments(*c.phong);
    if (!a || !b) return "";
    if (*a == *b) return " on the same " + std::to_string(*a) + " pixel-light pairs";
    return " on " + std::to_string(*a) + " and " + std::to_string(*b) + " pixel-light pairs";
}
}  // namespace

std::vector<MaterialCost> material_costs(const std::vector<Row>& rows) {
    std::vector<MaterialCost> out;
    for (const Row& r : rows) {
        if (!r.metal_rough || !r.lights_ms || *r.lights_ms <= 0) continue;
        for (const Row& p : rows) {
            if (metal_rough_name(p.scene) != r.scene || p.lights != r.lights || p.w != r.w || p.h != r.h) continue;
            if (!default_configuration(p) || p.light_geometry != r.light_geometry || !p.lights_ms || *p.lights_ms <= 0)
                continue;
            MaterialCost c;
            c.phong = &p;
            c.metal_rough = &r;
            c.ratio = *r.lights_ms / *p.lights_ms;
            c.phong_ns = ns_per_pair(p);
            c.metal_rough_ns = ns_per_pair(r);
            out.push_back(c);
            break;
        }
    }
    return out;
}

std::string material_cost_text(const MaterialCost& c) {
    const Row& p = *c.phong;
    std::string s = p.scene + " at " + std::to_string(p.lights) + " lights, " + light_geometry_name(p.light_geometry) +
                    ": light stage " + format_number("%.2f", *c.metal_rough->lights_ms) + " ms metallic-roughness / " +
                    format_number("%.2f", *p.lights_ms) + " ms Phong = " + format_number("%.2f", c.ratio) + pairs_text(c);
    if (c.metal_rough_ns && c.phong_ns)
        s += " (" + format_number("%.1f", *c.metal_rough_ns) + " / " + format_number("%.1f", *c.phong_ns) + " ns a pair)";
    return s;
}

std::string material_cost_markdown(const std::vector<Row>& rows) {
    const std::vector<MaterialCost> costs = material_costs(rows);
    if (costs.empty()) return "";
    std::ostringstream md;
    md << "## Material model\n\n"
          "The light stage of dsr's default configuration with quad, on each scene as it is (Phong) and with every "
          "material metallic-roughness (the `metal-rough` rows, `SCENE-metal-rough`: the base colour and map from "
          "the diffuse ones, metallic 0, the roughness from the shininess; `src/analysis/bench_scenes.h` "
          "metal_rough_twin), timed in the same rounds on the same pixel-light pairs: the medians and their ratio, "
          "and each per pair passed (*light frags*).\n\n"
          "| scene | lights | metal-rough ms | Phong ms | ratio | metal-rough ns/pair | Phong ns/pair |\n"
          "| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    const auto ns = [](const std::optional<double>& v) { return v ? format_number("%.1f", *v) : std::string("-"); };
    for (const MaterialCost& c : costs)
        md << "| " << c.phong->scene << " | " << c.phong->lights_label << " (" << c.phong->lights << ") | "
           << format_number("%.2f", *c.metal_rough->lights_ms) << " | " << format_number("%.2f", *c.phong->lights_ms)
           << " | " << format_number("%.2f", c.ratio) << " | " << ns(c.metal_rough_ns) << " | " << ns(c.phong_ns) << " |\n";
    md << "\n";
    return md.str();
}

}  // namespace dsr::bench
