// The option table (option_table.h). Each entry reads and writes one field of RenderOptions;
// the values and their spelling are exactly those `dsr render` has always taken.
#include "deferred/option_table.h"

#include "scene/scene.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace dsr {

namespace {

std::string on_off(bool b) { return b ? "on" : "off"; }

std::string joined(const std::vector<std::string>& v, const char* sep) {
    std::string s;
    for (const std::string& x : v) s += (s.empty() ? "" : sep) + x;
    return s;
}

std::vector<std::string> split_commas(const std::string& list) {
    std::vector<std::string> out;
    std::stringstream ss(list);
    for (std::string item; std::getline(ss, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

std::string format_number(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(v));
    return buf;
}

RenderOption choice(std::string name, std::vector<std::string> values, std::function<std::string(const RenderOptions&)> get,
                    std::function<void(RenderOptions&, const std::string&)> put) {
    return RenderOption{std::move(name), OptionKind::choice, std::move(values), 0, 0, true, std::move(get), std::move(put)};
}

// A float field of one ShaderOptions group (post, ssao): --NAME X in [lo, hi].
template <class Group>
RenderOption number(std::string name, float lo, float hi, Group ShaderOptions::*group, float Group::*field) {
    return RenderOption{std::move(name), OptionKind::number, {}, lo, hi, true,
                        [group, field](const RenderOptions& r) { return format_number(r.shader.*group.*field); },
                        [group, field](RenderOptions& r, const std::string& v) {
                            r.shader.*group.*field = std::strtof(v.c_str(), nullptr);
                        }};
}

// The skips of --no-skip, by name, and the SkipOptions field each turns off.
const std::pair<const char*, bool SkipOptions::*> kSkips[] = {
    {"variants", &SkipOptions::material_variants},
    {"empty-lights", &SkipOptions::empty_lights},
    {"light-depth-test", &SkipOptions::light_depth_test},
    {"light-sphere-test", &SkipOptions::light_sphere_test},
};

std::vector<RenderOption> make_table() {
    std::vector<RenderOption> t;
    t.push_back(choice(
        "depth", {"auto", "texture", "packed", "position16", "position32"},
        [](const RenderOptions& r) { return std::string(depth_path_name(r.shader.depth)); },
        [](RenderOptions& r, const std::string& v) { r.shader.depth = depth_path_from_name(v); }));
    t.push_back(choice(
        "depth-encoding", {"corrected", "literal", "linear", "log"},
        [](const RenderOptions& r) { return std::string(encoding_name(r.shader.encoding)); },
        [](RenderOptions& r, const std::string& v) { r.shader.encoding = encoding_from_name(v); }));
    t.push_back(choice(
        "gbuffer", {"rgba8", "half"}, [](const RenderOptions& r) { return r.shader.gbuffer_half ? "half" : "rgba8"; },
        [](RenderOptions& r, const std::string& v) { r.shader.gbuffer_half = v == "half"; }));
    t.push_back(switch_option("scissor", &ShaderOptions::scissor));
    t.push_back(choice(
        "light-geometry", {"quad", "volume", "stencil", "tiles"},
        [](const RenderOptions& r) { return std::string(light_geometry_name(r.shader.light_geometry)); },
        [](RenderOptions& r, const std::string& v) { r.shader.light_geometry = light_geometry_from_name(v); }));
    t.push_back(switch_option("depth-bounds", &ShaderOptions::depth_bounds));
    t.push_back(choice(
        "render-target", {"auto", "fbo", "copy", "pbuffer"},
        [](const RenderOptions& r) {
            static const char* names[] = {"auto", "fbo", "copy", "pbuffer"};
            return std::string(names[int(r.shader.render_target)]);
        },
        [](RenderOptions& r, const std::string& v) {
            r.shader.render_target = v == "fbo" ? RenderTarget::fbo : v == "copy" ? RenderTarget::copy
                                     : v == "pbuffer" ? RenderTarget::pbuffer : RenderTarget::automatic;
        }));
    t.push_back(integer_option("tile-size", 8, 512, &ShaderOptions::tile_size, true));
    t.push_back(integer_option("tile-lights", 1, 32, &ShaderOptions::tile_lights, true));
    t.push_back(choice(
        "tile-plan", {"lists", "groups"},
        [](const RenderOptions& r) { return std::string(r.shader.tile_plan == TileGrouping::groups ? "groups" : "lists"); },
        [](RenderOptions& r, const std::string& v) { r.shader.tile_plan = v == "groups" ? TileGrouping::groups : TileGrouping::lists; }));
    t.push_back(switch_option("tile-depth", &ShaderOptions::tile_depth));
    t.push_back(choice(
        "lighting", {"equations", "listing"},
        [](const RenderOptions& r) { return r.shader.listing2_literal ? "listing" : "equations"; },
        [](RenderOptions& r, const std::string& v) { r.shader.listing2_literal = v == "listing"; }));
    std::vector<std::string> skips;
    for (const auto& s : kSkips) skips.push_back(s.first);
    t.push_back(RenderOption{"no-skip", OptionKind::subset, skips, 0, 0, true,
                             [](const RenderOptions& r) {
                                 std::vector<std::string> off;
                                 for (const auto& s : kSkips)
                                     if (!(r.shader.skip.*s.second)) off.push_back(s.first);
                                 return off.empty() ? std::string("none") : joined(off, ",");
                             },
                             [](RenderOptions& r, const std::string& v) {
                                 const std::vector<std::string> off = split_commas(v);
                                 for (const auto& s : kSkips) {
                                     bool listed = false;
                                     for (const std::string& k : off) listed |= k == s.first;
                                     r.shader.skip.*s.second = !listed;
                                 }
                             }});
    RenderOption view = choice(
        "view", view_names(), [](const RenderOptions& r) { return std::string(view_name(r.view)); },
        [](RenderOptions& r, const std::string& v) { r.view = view_from_name(v); });
    view.rebuild = false;  // every view reads buffers the frame already has (the bloom view: see resolved)
    t.push_back(view);
    t.push_back(RenderOption{"bloom", OptionKind::toggle, {"on", "off"}, 0, 0, true,
                             [](const RenderOptions& r) { return on_off(r.bloom == 1); },
                             [](RenderOptions& r, const std::string& v) { r.bloom = v == "on"; }});
    t.push_back(choice(
        "bloom-scale", {"2", "4"}, [](const RenderOptions& r) { return std::to_string(r.shader.post.bloom_scale); },
        [](RenderOptions& r, const std::string& v) { r.shader.post.bloom_scale = std::atoi(v.c_str()); }));
    t.push_back(choice(
        "bloom-taps", {"3", "5", "7", "9", "11", "13", "15"},
        [](const RenderOptions& r) { return std::to_string(r.shader.post.bloom_taps); },
        [](RenderOptions& r, const std::string& v) { r.shader.post.bloom_taps = std::atoi(v.c_str()); }));
    t.push_back(number("bloom-strength", 0.0f, 16.0f, &ShaderOptions::post, &PostOptions::bloom_strength));
    t.push_back(choice(
        "bloom-mode", {"color", "listing"}, [](const RenderOptions& r) { return r.shader.post.bloom_listing ? "listing" : "color"; },
        [](RenderOptions& r, const std::string& v) { r.shader.post.bloom_listing = v == "listing"; }));
    t.push_back(RenderOption{"aa", OptionKind::toggle, {"on", "off"}, 0, 0, true,
                             [](const RenderOptions& r) { return on_off(r.aa == 1); },
                             [](RenderOptions& r, const std::string& v) { r.aa = v == "on"; }});
    t.push_back(choice(
        "aa-source", {"normal", "depth", "both"},
        [](const RenderOptions& r) {
            const AaSource s = r.shader.post.aa_source;
            return s == AaSource::normal ? "normal" : s == AaSource::depth ? "depth" : "both";
        },
        [](RenderOptions& r, const std::string& v) {
            r.shader.post.aa_source = v == "normal" ? AaSource::normal : v == "depth" ? AaSource::depth : AaSource::both;
        }));
    t.push_back(choice(
        "aa-kernel", {"text", "listing"},
        [](const RenderOptions& r) { return r.shader.post.aa_kernel == AaKernel::listing ? "listing" : "text"; },
        [](RenderOptions& r, const std::string& v) {
            r.shader.post.aa_kernel = v == "listing" ? AaKernel::listing : AaKernel::text;
        }));
    t.push_back(number("aa-weight", 0.0f, 8.0f, &ShaderOptions::post, &PostOptions::aa_weight));
    // SSAO (issue 13): --ssao / --no-ssao, then its four parameters (ranges: usage.cpp).
    t.push_back(RenderOption{"ssao", OptionKind::toggle, {"on", "off"}, 0, 0, true,
                             [](const RenderOptions& r) { return on_off(r.shader.ssao.on); },
                             [](RenderOptions& r, const std::string& v) { r.shader.ssao.on = v == "on"; }});
    t.push_back(choice(
        "ssao-scale", {"1", "2"}, [](const RenderOptions& r) { return std::to_string(r.shader.ssao.scale); },
        [](RenderOptions& r, const std::string& v) { r.shader.ssao.scale = std::atoi(v.c_str()); }));
    t.push_back(number("ssao-radius", 0.01f, 100.0f, &ShaderOptions::ssao, &SsaoOptions::radius));
    t.push_back(number("ssao-strength", 0.0f, 4.0f, &ShaderOptions::ssao, &SsaoOptions::strength));
    t.push_back(RenderOption{"ssao-samples", OptionKind::integer, {}, 4, 64, true,
                             [](const RenderOptions& r) { return std::to_string(r.shader.ssao.samples); },
                             [](RenderOptions& r, const std::string& v) { r.shader.ssao.samples = std::atoi(v.c_str()); }});
    // The forward stage after the lights (issue 13).
    t.push_back(RenderOption{"show-lights", OptionKind::toggle, {"on", "off"}, 0, 0, true,
                             [](const RenderOptions& r) { return on_off(r.shader.show_lights); },
                             [](RenderOptions& r, const std::string& v) { r.shader.show_lights = v == "on"; }});
    t.push_back(choice(
        "depth-handoff", {"auto", "blit", "pass"},
        [](const RenderOptions& r) { return std::string(depth_handoff_name(r.shader.depth_handoff)); },
        [](RenderOptions& r, const std::string& v) { r.shader.depth_handoff = depth_handoff_from_name(v); }));
    return t;
}

}  // namespace

RenderOption switch_option(std::string name, bool ShaderOptions::*field) {
    return RenderOption{std::move(name), OptionKind::on_off, {"on", "off"}, 0, 0, true,
                        [field](const RenderOptions& r) { return on_off(r.shader.*field); },
                        [field](RenderOptions& r, const std::string& v) { r.shader.*field = v == "on"; }};
}

RenderOption integer_option(std::string name, int lo, int hi, int ShaderOptions::*field, bool with_auto) {
    std::vector<std::string> words;
    if (with_auto) words.push_back("auto");  // stored as 0: the GL's default (choose_paths)
    return RenderOption{std::move(name), OptionKind::integer, words, float(lo), float(hi), true,
                        [field](const RenderOptions& r) {
                            return r.shader.*field == 0 ? std::string("auto") : std::to_string(r.shader.*field);
                        },
                        [field](RenderOptions& r, const std::string& v) {
                            r.shader.*field = v == "auto" ? 0 : std::atoi(v.c_str());
                        }};
}

ShaderOptions RenderOptions::resolved(const Scene& scene) const {
    ShaderOptions s = shader;
    s.post.bloom = bloom < 0 ? scene.post_bloom : bloom == 1;
    s.post.aa = aa < 0 ? scene.post_aa : aa == 1;
    if (view == View::bloom) s.post.bloom = true;  // the view shows the bloom blur
    if (view == View::ssao) s.ssao.on = true;      // the view shows the AO buffer
    for (const Material& m : scene.materials) s.forward_surfaces = s.forward_surfaces || m.transparent();
    return s;
}

const std::vector<RenderOption>& render_options() {
    static const std::vector<RenderOption> t = make_table();
    return t;
}

const RenderOption* find_render_option(const std::string& name) {
    for (const RenderOption& o : render_options())
        if (o.name == name) return &o;
    return nullptr;
}

std::string check_render_option(const RenderOption& o, const std::string& v) {
    switch (o.kind) {
        case OptionKind::choice:
        case OptionKind::on_off:
        case OptionKind::toggle:
            for (const std::string& a : o.values)
                if (v == a) return "";
            return "expected " + joined(o.values, "|") + ", got '" + v + "'";
        case OptionKind::number: {
            char* end = nullptr;
            errno = 0;
            const double d = v.empty() ? 0 : std::strtod(v.c_str(), &end);
            if (v.empty() || errno != 0 || *end != '\0' || !(d >= o.lo && d <= o.hi))
                return "expected a number in [" + std::to_string(o.lo) + ", " + std::to_string(o.hi) + "], got '" + v + "'";
            return "";
        }
        case OptionKind::integer: {
            for (const std::string& a : o.values)  // words it also takes (auto)
                if (v == a) return "";
            char* end = nullptr;
            errno = 0;
            const long n = v.empty() ? 0 : std::strtol(v.c_str(), &end, 10);
            if (v.empty() || errno != 0 || *end != '\0' || n < long(o.lo) || n > long(o.hi))
                return "expected " + (o.values.empty() ? std::string() : joined(o.values, "|") + " or ") +
                       "an integer in [" + std::to_string(long(o.lo)) + ", " + std::to_string(long(o.hi)) +
                       "], got '" + v + "'";
            return "";
        }
        case OptionKind::subset: {
            if (v == "none") return "";
            const std::vector<std::string> items = split_commas(v);
            for (const std::string& k : items) {
                bool known = false;
                for (const std::string& a : o.values) known |= k == a;
                if (!known) return "expected " + joined(o.values, ", ") + " (comma-separated) or none, got '" + k + "'";
            }
            if (items.empty()) return "expected " + joined(o.values, ", ") + " (comma-separated) or none, got '" + v + "'";
            return "";
        }
    }
    return "unknown option kind";
}

std::string set_render_option(RenderOptions& ro, const RenderOption& o, const std::string& value) {
    std::string err = check_render_option(o, value);
    if (err.empty()) o.put(ro, value);
    return err;
}

std::vector<std::string> render_option_flags() {
    std::vector<std::string> f;
    for (const RenderOption& o : render_options()) {
        f.push_back("--" + o.name);
        if (o.kind == OptionKind::toggle) f.push_back("--no-" + o.name);
    }
    return f;
}

}  // namespace dsr
