#include "app/render_flags.h"

namespace dsr {

bool parse_render_flag(Args& args, const std::string& a, RenderOptions& ro) {
    if (a.rfind("--", 0) != 0) return false;
    const std::string name = a.substr(2);
    // The switches: --bloom / --no-bloom (their `set` form takes on|off).
    for (const char* prefix : {"", "no-"}) {
        const std::string p = prefix;
        if (name.rfind(p, 0) != 0) continue;
        const RenderOption* o = find_render_option(name.substr(p.size()));
        if (o && o->kind == OptionKind::toggle) {
            set_render_option(ro, *o, p.empty() ? "on" : "off");
            return true;
        }
    }
    const RenderOption* o = find_render_option(name);
    if (!o) return false;
    std::string v = args.value(a);
    // On a command line a subset adds to what earlier flags listed (--no-skip a --no-skip b).
    if (o->kind == OptionKind::subset && v != "none" && o->get(ro) != "none" && check_render_option(*o, v).empty())
        v = o->get(ro) + "," + v;
    const std::string err = set_render_option(ro, *o, v);
    if (!err.empty()) args.fail(a + ": " + err);
    return true;
}

}  // namespace dsr
