// Help and docs/cli.md from the tables (help_text.h).
#include "app/help_text.h"
#include "scene/user_file.h"

#include <sstream>
#include <vector>

#include "app/command_table.h"
#include "dsr_text.h"
#include "deferred/option_table.h"
#include "gl/cap_names.h"

namespace dsr {

namespace {

constexpr size_t kWidth = 100;  // help lines wrap before this column
constexpr size_t kColumn = 26;  // where an option's text starts

// `text`'s words wrapped before kWidth; the first line starts at column `first`, the others at `indent`.
std::string wrap(const std::string& text, size_t first, size_t indent) {
    std::string out, line;
    size_t col = first;
    std::istringstream words(text);
    for (std::string w; words >> w;) {
        if (!line.empty() && col + 1 + w.size() > kWidth) {
            out += line + "\n" + std::string(indent, ' ');
            line.clear();
            col = indent;
        }
        if (!line.empty()) line += ' ', ++col;
        line += w;
        col += w.size();
    }
    return out + line;
}

// "  HEAD   text" with the text at kColumn (on the next line when HEAD reaches it).
std::string entry(const std::string& head, const std::string& text, size_t lead = 2, size_t column = kColumn) {
    std::string s = std::string(lead, ' ') + head;
    s += s.size() + 2 <= column ? std::string(column - s.size(), ' ') : "\n" + std::string(column, ' ');
    return s + wrap(text, column, column) + "\n";
}

// " (8..512; default auto)": what help adds after a flag's text.
std::string qualifiers(const std::string& range, const std::string& def) {
    std::vector<std::string> q;
    if (!range.empty()) q.push_back(range);
    if (!def.empty()) q.push_back("default " + def);
    return q.empty() ? "" : " (" + joined(q, "; ") + ")";
}

std::string flag_head(const Flag& f) { return joined(f.names, ", ") + (f.arg.empty() ? "" : " " + f.arg); }

std::string option_head(const RenderOption& o) {
    return o.kind == OptionKind::toggle ? "--" + o.name + ", --no-" + o.name : "--" + o.name + " " + option_arg(o);
}

std::string operand_word(const Operand& o) { return o.optional ? "[" + o.name + "]" : o.name; }

// "render [SCENE] [-o FILE] ... [renderer options]", wrapped under `lead`.
std::string synopsis(const Command& c, const std::string& lead) {
    std::vector<std::string> words;
    for (const Operand& o : c.operands) words.push_back(operand_word(o));
    for (const Flag& f : c.flags) words.push_back("[" + f.names.front() + (f.arg.empty() ? "" : " " + f.arg) + "]");
    if (c.renderer) words.push_back("[renderer options]");
    const size_t indent = lead.size() + c.name.size() + 1;
    std::string s = lead + c.name;
    size_t col = s.size();
    for (const std::string& w : words) {
        if (col + 1 + w.size() > kWidth) s += "\n" + std::string(indent - 1, ' '), col = indent - 1;
        s += " " + w;
        col += 1 + w.size();
    }
    return s + "\n";
}

const char* kRendererHeading =
    "renderer options (also the viewer's panel and `set NAME VALUE`, by the name without dashes)";

// Markdown: a table cell's text, its pipes escaped.
std::string cell(const std::string& s) {
    std::string out;
    for (char ch : s) out += ch == '|' ? std::string("\\|") : std::string(1, ch);
    return out;
}
std::string code(const std::string& s) { return s.empty() ? "" : "`" + cell(s) + "`"; }

std::string markdown_flag_row(const Flag& f) {
    std::vector<std::string> names;
    for (const std::string& n : f.names) names.push_back(code(n));
    std::string value = code(f.arg);
    if (!f.range.empty()) value += (value.empty() ? "" : ", ") + cell(f.range);
    std::string help = cell(f.help);
    std::vector<std::string> items;
    for (const auto& item : f.items) items.push_back(code(item.first));
    if (!items.empty()) help += " " + joined(items, ", ");
    return "| " + joined(names, ", ") + " | " + value + " | " + code(f.def) + " | " + help + " |\n";
}

}  // namespace

bool is_help_flag(const std::string& arg) { return arg == "--help" || arg == "-h"; }

std::string command_help(const Command& c) {
    std::string s = synopsis(c, "usage: dsr ") + wrap(c.summary, 0, 0) + "\n\noptions:\n";
    for (const Operand& o : c.operands) s += entry(o.name, o.help);
    for (const Flag& f : c.flags) {
        s += entry(flag_head(f), f.help + qualifiers(f.range, f.def));
        for (const auto& [name, what] : f.items) s += entry(name, what, 4, kColumn + 6);
    }
    if (c.renderer) {
        s += std::string("\n") + kRendererHeading + ":\n";
        for (const RenderOption& o : render_options())
            s += entry(option_head(o), o.help + qualifiers(option_range(o), option_default(o)));
    }
    if (!c.notes.empty()) s += "\n" + c.notes;
    return s;
}

std::string top_help() {
    std::string s = "usage: dsr COMMAND [options]   (dsr COMMAND --help: that command's options)\n";
    for (const Command& c : command_table()) {
        s += "  " + c.name;
        for (const Operand& o : c.operands) s += " " + operand_word(o);
        s += std::string(c.flags.empty() && !c.renderer ? "" : " [options]") + "\n      " + wrap(c.summary, 6, 6) + "\n";
    }
    return s + "dsr help --markdown: every command's options as markdown (docs/cli.md)\n";
}

std::string unknown_command_line(const std::string& name) {
    std::vector<std::string> names;
    for (const Command& c : command_table()) names.push_back(c.name);
    return "dsr: unknown command " + quote(name) + " (expected " + joined(names, ", ") + "; dsr --help lists them)";
}

std::string cli_markdown() {
    std::string s =
        "# Command line\n\n"
        "<!-- Generated by `build/dsr help --markdown > docs/cli.md` (`make docs-cli`) from the command tables\n"
        "     (src/app/command_table.cpp), the renderer option table (src/deferred/option_table.cpp) and the\n"
        "     --caps table (src/gl/cap_names.cpp). Edit those, not this file: a test fails when it differs. -->\n\n"
        "Every `dsr` command with its flags, the values each takes, its default and what it does;\n"
        "`dsr COMMAND --help` prints the same. An invalid value is one error line naming the flag and what\n"
        "it accepts, and a non-zero exit.\n\n";
    for (const Command& c : command_table()) s += "- [`dsr " + c.name + "`](#dsr-" + c.name + "): " + c.summary + "\n";
    s += "- [Renderer options](#renderer-options): the options `render` and `view` share with the viewer's panel\n"
         "- [Capability names](#capability-names): what `--caps` can hide\n";
    for (const Command& c : command_table()) {
        s += "\n## dsr " + c.name + "\n\n```\n" + synopsis(c, "dsr ") + "```\n\n" + c.summary + ".\n\n";
        s += "| Flag | Value | Default | What it does |\n|---|---|---|---|\n";
        for (const Operand& o : c.operands) s += "| " + code(o.name) + " | | | " + cell(o.help) + " |\n";
        for (const Flag& f : c.flags) s += markdown_flag_row(f);
        if (c.renderer) s += "\nIt also takes every [renderer option](#renderer-options).\n";
        if (!c.notes.empty())  // a table in columns (view's keys) as it prints, prose as prose
            s += c.notes.find("\n  ") != std::string::npos ? "\n```\n" + c.notes + "```\n" : "\n" + c.notes;
    }
    s += "\n## Renderer options\n\n"
         "`render` and `view` take each as a flag; the viewer's panel shows each, and its script's\n"
         "`set NAME VALUE` takes each by the name without dashes (a switch `--NAME` / `--no-NAME` as\n"
         "`set NAME on|off`). `bench` takes the `--tile-*` ones for its tiles rows.\n\n"
         "| Flag | Value | Default | What it does |\n|---|---|---|---|\n";
    for (const RenderOption& o : render_options()) {
        std::string flags = o.kind == OptionKind::toggle ? code("--" + o.name) + ", " + code("--no-" + o.name) : code("--" + o.name);
        std::string value = code(option_arg(o));
        if (!option_range(o).empty()) value += (value.empty() ? "" : ", ") + cell(option_range(o));
        s += "| " + flags + " | " + value + " | " + code(option_default(o)) + " | " + cell(o.help) + " |\n";
    }
    s += "\n## Capability names\n\n"
         "`--caps LIST` (`render`, `info`, `view`) and the environment variable `DSR_CAPS` (the same\n"
         "syntax, comma-separated) make the capability probe report these missing, so the fallback paths\n"
         "can be forced; docs/legacy.md measures them.\n\n"
         "| Name | Hides | Then |\n|---|---|---|\n";
    for (const CapName& c : cap_names()) s += "| " + code(c.name) + " | " + cell(c.hides) + " | " + cell(c.effect) + " |\n";
    return s;
}

}  // namespace dsr
