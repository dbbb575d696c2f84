// What each skip saves: the every-skip quad row of a variant against each row with skips turned off.
#include "analysis/bench_skips.h"

#include <algorithm>
#include <sstream>

#include "analysis/number_format.h"
#include "dsr_text.h"
#include "deferred/option_table.h"

namespace dsr::bench {

namespace {

// The default configuration's settings with the quad geometry, whatever the skips.
bool quad_default_but_skips(const Row& r) {
    Row all_on = r;
    all_on.skip = SkipOptions{};
    return default_configuration(all_on) && r.light_geometry == LightGeometry::quad;
}

bool same_variant(const Row& a, const Row& b) {
    return a.scene == b.scene && a.lights_label == b.lights_label && a.lights == b.lights && a.w == b.w && a.h == b.h;
}

}  // namespace

std::vector<SkipSaving> skip_savings(const std::vector<Row>& rows) {
    std::vector<const Row*> bases;  // the every-skip quad rows, one per variant
    for (const Row& r : rows)
        if (default_configuration(r) && r.light_geometry == LightGeometry::quad) bases.push_back(&r);
    std::vector<SkipSaving> out;
    for (const Row& off : rows) {
        if (skips_off(off.skip).empty() || !quad_default_but_skips(off)) continue;
        const auto it = std::find_if(bases.begin(), bases.end(), [&](const Row* b) { return same_variant(*b, off); });
        if (it == bases.end()) continue;
        const Row* base = *it;
        SkipSaving s;
        s.scene = off.scene;
        s.lights_label = off.lights_label;
        s.skips_off = skip_names_off(off.skip, &SkipName::flag);
        s.with_ms = base->ms_median, s.with_min = base->ms_min, s.with_max = base->ms_max;
        s.without_ms = off.ms_median;
        s.with_lights_ms = base->lights_ms;
        s.without_lights_ms = off.lights_ms;
        out.push_back(s);
    }
    return out;
}

std::string skip_savings_markdown(const std::vector<SkipSaving>& savings) {
    std::ostringstream md;
    md << "## What each skip saves\n\n"
          "Each skip (`--no-skip NAME` turns it off; docs/cli.md) on the default configuration with the tutorial's "
          "per-light quads (`--light-geometry quad`, where every skip applies): the frame's median with that skip "
          "off less the median with every skip on, in ms; above 0 the skip saves time. Each cell is the difference "
          "of two medians, so a saving smaller than the every-skip row's min-max spread (its own column) is "
          "within the noise. `ambient-target + ambient` is the tutorial's ambient pass (Listing 15) against the "
          "ambient term the material pass writes; `ambient-target` alone, the ambient pass folded into a light "
          "pass where one covers the screen.\n\n";
    if (savings.empty()) return md.str() + "(no row with a skip turned off in this run)\n\n";
    std::vector<std::string> columns;  // the skips, in the rows' order
    for (const SkipSaving& s : savings) {
        const std::string c = joined(s.skips_off, " + ");
        if (std::find(columns.begin(), columns.end(), c) == columns.end()) columns.push_back(c);
    }
    md << "| scene | lights | every skip on, ms (min-max) |";
    for (const std::string& c : columns) md << " " << c << " |";
    md << "\n| --- | --- | ---: |";
    for (size_t i = 0; i < columns.size(); ++i) md << " ---: |";
    md << "\n";
    for (size_t i = 0; i < savings.size(); ++i) {
        const SkipSaving& first = savings[i];
        if (i > 0 && savings[i - 1].scene == first.scene && savings[i - 1].lights_label == first.lights_label) continue;
        md << "| " << first.scene << " | " << first.lights_label << " | " << format_number("%.2f", first.with_ms) << " ("
           << format_number("%.2f", first.with_min) << "-" << format_number("%.2f", first.with_max) << ") |";
        for (const std::string& c : columns) {
            const auto it = std::find_if(savings.begin(), savings.end(), [&](const SkipSaving& s) {
                return s.scene == first.scene && s.lights_label == first.lights_label && joined(s.skips_off, " + ") == c;
            });
            md << " " << (it == savings.end() ? std::string("-") : format_number("%+.2f", it->saved_ms())) << " |";
        }
        md << "\n";
    }
    return md.str() + "\n";
}

nlohmann::ordered_json skip_savings_json(const std::vector<SkipSaving>& savings) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (const SkipSaving& s : savings) {
        nlohmann::ordered_json j;
        j["scene"] = s.scene;
        j["lights"] = s.lights_label;
        j["skips_off"] = s.skips_off;
        j["with_ms"] = s.with_ms;
        j["without_ms"] = s.without_ms;
        j["saved_ms"] = s.saved_ms();
        j["with_lights_ms"] = s.with_lights_ms ? nlohmann::ordered_json(*s.with_lights_ms) : nlohmann::ordered_json(nullptr);
        j["without_lights_ms"] = s.without_lights_ms ? nlohmann::ordered_json(*s.without_lights_ms) : nlohmann::ordered_json(nullptr);
        a.push_back(j);
    }
    return a;
}

}  // namespace dsr::bench
