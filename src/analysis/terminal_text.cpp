// Terminal text fitted to a width (terminal_text.h).
#include "analysis/terminal_text.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace dsr {

namespace {

// Columns a string takes: its UTF-8 characters (continuation bytes take none).
size_t columns(const std::string& s) {
    size_t n = 0;
    for (unsigned char c : s) n += (c & 0xC0) != 0x80;
    return n;
}

// The byte offset of column `col` in s (s.size() past its end).
size_t byte_at(const std::string& s, size_t col) {
    size_t n = 0;
    for (size_t i = 0; i < s.size(); ++i)
        if ((static_cast<unsigned char>(s[i]) & 0xC0) != 0x80 && n++ == col) return i;
    return s.size();
}

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::string line;
    std::istringstream in(text);
    while (std::getline(in, line)) lines.push_back(line);
    return lines;
}

// The column continuation lines start at: the second column of "  key    value" (two or more
// spaces after the first word group, within the left half), else the indent plus four.
size_t hanging_indent(const std::string& line, size_t width) {
    const size_t lead = line.find_first_not_of(' ');
    if (lead == std::string::npos) return 0;
    const size_t gap = line.find("  ", lead);
    if (gap != std::string::npos) {
        const size_t value = line.find_first_not_of(' ', gap);
        if (value != std::string::npos && columns(line.substr(0, value)) <= width / 2) return columns(line.substr(0, value));
    }
    return std::min(lead + 4, width / 2);
}

std::string wrap_line(const std::string& line, size_t width) {
    if (columns(line) <= width) return line;
    const size_t indent = hanging_indent(line, width);
    std::string out, rest = line;
    bool first = true;
    while (columns(rest) > width) {
        // The last space at or before the width, past the indent; else the word is cut at the width.
        const size_t limit = byte_at(rest, width);
        size_t cut = rest.rfind(' ', limit);
        const size_t floor = first ? rest.find_first_not_of(' ') : indent;
        size_t next;
        if (cut == std::string::npos || cut <= floor) {
            cut = limit;
            next = limit;
        } else {
            next = cut + 1;
            while (cut > 0 && rest[cut - 1] == ' ') --cut;
        }
        out += rest.substr(0, cut) + "\n";
        rest = std::string(indent, ' ') + rest.substr(next);
        first = false;
    }
    return out + rest;
}

// A header cell stacked into lines no wider than `w` (a longer word stays whole).
std::vector<std::string> stack(const std::string& header, size_t w) {
    std::vector<std::string> lines;
    std::istringstream in(header);
    std::string word, line;
    while (in >> word) {
        if (!line.empty() && columns(line) + 1 + columns(word) > w) lines.push_back(line), line.clear();
        line += (line.empty() ? "" : " ") + word;
    }
    if (!line.empty() || lines.empty()) lines.push_back(line);
    return lines;
}

// A markdown cell as plain text: emphasis and code marks dropped, escaped pipes as pipes.
std::string plain(std::string s) {
    for (const std::string mark : {"**", "`"})
        for (size_t at = s.find(mark); at != std::string::npos; at = s.find(mark, at)) s.erase(at, mark.size());
    for (size_t at = s.find("\\|"); at != std::string::npos; at = s.find("\\|", at)) s.erase(at, 1);
    return s;
}

std::string pad(const std::string& s, size_t w, bool right) {
    const size_t n = columns(s);
    if (n >= w) return s;
    return right ? std::string(w - n, ' ') + s : s + std::string(w - n, ' ');
}

// One part of a table: the columns `cols` (their widths `w`).
std::string table_part(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
                       const std::vector<bool>& right, const std::vector<size_t>& cols, const std::vector<size_t>& w,
                       size_t indent) {
    std::vector<std::vector<std::string>> stacked;
    size_t depth = 1;
    for (size_t c : cols) stacked.push_back(stack(header[c], w[c])), depth = std::max(depth, stacked.back().size());
    std::string out;
    auto emit = [&](const std::vector<std::string>& cells) {
        std::string line(indent, ' ');
        for (size_t k = 0; k < cols.size(); ++k) line += (k ? "  " : "") + pad(cells[k], w[cols[k]], right[cols[k]]);
        while (!line.empty() && line.back() == ' ') line.pop_back();
        out += line + "\n";
    };
    for (size_t d = 0; d < depth; ++d) {  // headers bottom-aligned over their columns
        std::vector<std::string> cells;
        for (auto& s : stacked) cells.push_back(d + s.size() >= depth ? s[d + s.size() - depth] : "");
        emit(cells);
    }
    for (const auto& r : rows) {
        std::vector<std::string> cells;
        for (size_t c : cols) cells.push_back(c < r.size() ? r[c] : "");
        emit(cells);
    }
    return out;
}

}  // namespace

std::string wrap_lines(const std::string& text, size_t width) {
    std::string out;
    for (const std::string& line : split_lines(text)) out += wrap_line(line, width) + "\n";
    if (!text.empty() && text.back() != '\n' && !out.empty()) out.pop_back();
    return out;
}

std::string text_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
                       const std::vector<bool>& right_in, size_t width, size_t indent) {
    const size_t n = header.size();
    std::vector<bool> right = right_in;
    right.resize(n, false);
    // Each column as wide as its widest cell, or its header's longest word where that is wider.
    std::vector<size_t> w(n, 1);
    for (size_t c = 0; c < n; ++c) {
        std::istringstream in(header[c]);
        for (std::string word; in >> word;) w[c] = std::max(w[c], columns(word));
        for (const auto& r : rows)
            if (c < r.size()) w[c] = std::max(w[c], columns(r[c]));
    }
    // Columns into parts no wider than the width, each part after the first repeating column 0.
    std::vector<std::vector<size_t>> parts{{0}};
    size_t used = indent + w[0];
    for (size_t c = 1; c < n; ++c) {
        if (used + 2 + w[c] > width && parts.back().size() > 1) parts.push_back({0}), used = indent + w[0];
        parts.back().push_back(c);
        used += 2 + w[c];
    }
    std::string out;
    for (size_t p = 0; p < parts.size(); ++p) out += (p ? "\n" : "") + table_part(header, rows, right, parts[p], w, indent);
    return out;
}

std::string markdown_for_terminal(const std::string& markdown, size_t width) {
    const std::vector<std::string> lines = split_lines(markdown);
    std::string out;
    auto cells = [](const std::string& line) {
        std::vector<std::string> c;
        std::string cell;
        for (size_t i = 1; i < line.size(); ++i) {  // past the leading '|'
            if (line[i] == '|' && line[i - 1] != '\\') {
                const size_t a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
                c.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
                cell.clear();
            } else {
                cell += line[i];
            }
        }
        return c;
    };
    for (size_t i = 0; i < lines.size();) {
        if (lines[i].rfind("|", 0) != 0) {
            out += wrap_line(lines[i], width) + "\n";
            ++i;
            continue;
        }
        std::vector<std::string> header = cells(lines[i++]);
        std::vector<bool> right(header.size(), false);
        if (i < lines.size() && lines[i].find("---") != std::string::npos && lines[i].rfind("|", 0) == 0) {
            const std::vector<std::string> rule = cells(lines[i++]);
            for (size_t c = 0; c < rule.size() && c < right.size(); ++c) right[c] = !rule[c].empty() && rule[c].back() == ':';
        }
        std::vector<std::vector<std::string>> rows;
        for (; i < lines.size() && lines[i].rfind("|", 0) == 0; ++i) {
            rows.push_back(cells(lines[i]));
        }
        for (std::string& h : header) h = plain(h);
        for (auto& r : rows)
            for (std::string& c : r) c = plain(c);
        out += text_table(header, rows, right, width);
    }
    if (!markdown.empty() && markdown.back() != '\n' && !out.empty()) out.pop_back();
    return out;
}

std::vector<std::string> lines_over(const std::string& text, size_t width) {
    std::vector<std::string> over;
    for (const std::string& line : split_lines(text))
        if (columns(line) > width) over.push_back(line);
    return over;
}

void print_wrapped_warning(const std::string& warning) {
    std::fprintf(stderr, "%s\n", wrap_lines("warning: " + warning).c_str());
}

}  // namespace dsr
