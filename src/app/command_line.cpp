// The command-line table's parser and flag makers (command_line.h).
#include "app/command_line.h"
#include "scene/user_file.h"

#include <cstdio>
#include <sstream>

#include "app/render_flags.h"
#include "dsr_error.h"
#include "dsr_text.h"

namespace dsr {

namespace {

std::string format_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace

const Flag* find_flag(const Command& c, const std::string& word) {
    for (const Flag& f : c.flags)
        for (const std::string& n : f.names)
            if (n == word) return &f;
    return nullptr;
}

void parse_command_line(const Command& c, const std::vector<std::string>& argv) {
    Args args(c.name, argv);
    while (!args.done()) {
        const std::string a = args.next();
        if (const Flag* f = find_flag(c, a)) {
            f->parse(args, a);
        } else if (c.renderer && parse_render_flag(args, a, *c.renderer)) {
            // an option table flag, set in *c.renderer
        } else if (!a.empty() && a[0] == '-') {
            args.fail("unknown option " + quote(a) + " (dsr " + c.name + " --help lists them)");
        } else if (!c.operand) {
            args.fail("expected options only, got " + quote(a));
        } else {
            c.operand(args, a);
        }
    }
}

Flag text_flag(std::vector<std::string> names, std::string arg, std::string& field, std::string help, std::string def) {
    return Flag{std::move(names), std::move(arg), "", def.empty() ? field : def, std::move(help), {},
                [&field](Args& a, const std::string& flag) { field = a.value(flag); }};
}

Flag switch_flag(std::string name, bool& field, std::string help) {
    return Flag{{std::move(name)}, "", "", "", std::move(help), {}, [&field](Args&, const std::string&) { field = true; }};
}

Flag int_flag(std::string name, std::string arg, int lo, int hi, int& field, std::string help, std::string def) {
    return Flag{{std::move(name)}, std::move(arg), std::to_string(lo) + ".." + std::to_string(hi),
                def.empty() ? std::to_string(field) : def, std::move(help), {},
                [&field, lo, hi](Args& a, const std::string& flag) { field = a.int_value(flag, lo, hi); }};
}

Flag float_flag(std::string name, std::string arg, float lo, float hi, double& field, std::string help, std::string def) {
    return Flag{{std::move(name)}, std::move(arg), format_number(lo) + ".." + format_number(hi),
                def.empty() ? format_number(field) : def, std::move(help), {},
                [&field, lo, hi](Args& a, const std::string& flag) { field = a.float_value(flag, lo, hi); }};
}

Flag size_flag(std::string name, int& w, int& h, std::string help, std::string def) {
    return Flag{{std::move(name)}, "WxH", "each 1..8192", def.empty() ? std::to_string(w) + "x" + std::to_string(h) : def,
                std::move(help), {}, [&w, &h](Args& a, const std::string& flag) { a.size_value(flag, w, h); }};
}

Flag choice_flag(std::string name, const std::vector<std::string>& values, std::string& field, std::string help,
                 std::string def) {
    return Flag{{std::move(name)}, joined(values, "|"), "", def.empty() ? field : def, std::move(help), {},
                [&field, values](Args& a, const std::string& flag) { field = a.choice(flag, values); }};
}

Flag list_flag(std::string name, std::string arg, const std::vector<std::string>& values, std::vector<std::string>& field,
               std::string help, std::string def) {
    return Flag{{std::move(name)}, std::move(arg), joined(values, ", ") + " (comma-separated)",
                def.empty() ? joined(field, ",") : def, std::move(help), {},
                [&field, values](Args& a, const std::string& flag) {
                    const std::string v = a.value(flag);
                    std::vector<std::string> items;
                    std::stringstream ss(v);
                    for (std::string item; std::getline(ss, item, ',');) {
                        bool known = false;
                        for (const std::string& k : values) known |= item == k;
                        if (!known)
                            a.fail(flag + ": expected a comma-separated list of " + joined(values, ", ") + ", got " + quote(v));
                        items.push_back(item);
                    }
                    if (items.empty()) a.fail(flag + ": expected a comma-separated list of " + joined(values, ", ") + ", got ''");
                    field = items;
                }};
}

Flag option_flag(const std::string& option, RenderOptions& into) {
    const RenderOption* o = find_render_option(option);
    if (!o) throw Error("option_flag: " + quote(option) + " is not in the option table");  // a slip in a command table
    std::vector<std::string> names = {"--" + o->name};
    if (o->kind == OptionKind::toggle) names.push_back("--no-" + o->name);
    return Flag{names, option_arg(*o), option_range(*o), option_default(*o), o->help, {},
                [&into](Args& a, const std::string& flag) {
                    if (!parse_render_flag(a, flag, into)) a.fail("unknown option " + quote(flag));
                }};
}

}  // namespace dsr
