// Reading files and scanning OBJ/MTL text for the OBJ loader (obj_text.h).
#include "scene/obj_text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "scene/obj_loader.h"

namespace dsr::obj {

using std::string;
using std::string_view;

string read_regular_file(const string& path, const string& what) { return read_user_text(path, what, kMaxObjBytes); }

Image read_regular_image(const string& path, size_t max_texels) { return load_image(path, max_texels); }

// ---- line scanning -------------------------------------------------------------------------

bool LineScanner::next() {
    if (pos_ >= text_.size()) return false;
    ++number_;
    size_t end = pos_;
    while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') ++end;
    size_t after = end + 1;
    if (end < text_.size() && text_[end] == '\r' && end + 1 < text_.size() && text_[end + 1] == '\n') ++after;
    size_t stop = end;
    const void* nul = std::memchr(text_.data() + pos_, '\0', end - pos_);
    if (nul) fail("expected text, got a NUL byte");
    const void* hash = std::memchr(text_.data() + pos_, '#', end - pos_);
    if (hash) {
        stop = size_t(static_cast<const char*>(hash) - text_.data());
        std::fill(text_.begin() + long(stop), text_.begin() + long(end), ' ');
    }
    tokens_.clear();
    size_t i = pos_;
    while (i < stop) {
        while (i < stop && is_space(text_[i])) ++i;
        const size_t b = i;
        while (i < stop && !is_space(text_[i])) ++i;
        if (i > b) tokens_.emplace_back(text_.data() + b, i - b);
    }
    line_begin_ = pos_;
    line_end_ = stop;
    pos_ = after;
    return true;
}

string_view LineScanner::rest_after_keyword() const {
    string_view line(text_.data() + line_begin_, line_end_ - line_begin_);
    size_t i = 0;
    while (i < line.size() && is_space(line[i])) ++i;
    while (i < line.size() && !is_space(line[i])) ++i;
    while (i < line.size() && is_space(line[i])) ++i;
    size_t e = line.size();
    while (e > i && is_space(line[e - 1])) --e;
    return line.substr(i, e - i);
}

void LineScanner::expected(const string& what, size_t token) const {
    if (token < tokens_.size()) fail("expected " + what + ", got " + quote(tokens_[token]));
    fail("expected " + what + ", got end of line");
}

double LineScanner::number(size_t i, const string& subject) const {
    if (i >= tokens_.size()) expected("a number for " + subject, i);
    const string_view t = tokens_[i];
    bool digit = false;
    for (char c : t) {
        if (c >= '0' && c <= '9') digit = true;
        else if (!(c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E')) expected("a number for " + subject, i);
    }
    if (!digit || t.size() > 64) expected("a number for " + subject, i);
    char buf[80];
    std::memcpy(buf, t.data(), t.size());
    buf[t.size()] = '\0';
    char* end = nullptr;
    const double d = std::strtod(buf, &end);
    if (end != buf + t.size()) expected("a number for " + subject, i);
    if (!std::isfinite(d)) expected("a finite number for " + subject, i);
    if (std::fabs(d) > kMaxObjCoordinate)
        fail("expected " + subject + " within +-1e12, got " + quote(t) + " (an absurd size)");
    return d;
}

long LineScanner::integer(string_view t, const string& subject) const {
    bool digit = false;
    for (size_t k = 0; k < t.size(); ++k) {
        const char c = t[k];
        if (c >= '0' && c <= '9') digit = true;
        else if (!(k == 0 && (c == '-' || c == '+'))) fail("expected an integer " + subject + ", got " + quote(t));
    }
    if (!digit || t.size() > 18) fail("expected an integer " + subject + " of at most 18 digits, got " + quote(t));
    return std::strtol(string(t).c_str(), nullptr, 10);
}

void Ignored::add(const string& k, int line) {
    auto it = seen.find(k);
    if (it == seen.end()) seen[k] = {line, 1};
    else ++it->second.second;
}

void Ignored::report(const string& file, const string& why, std::vector<string>& warnings) const {
    for (const auto& [k, v] : seen)
        warnings.push_back(file + ":" + std::to_string(v.first) + ": '" + k + "' ignored (" + why + "; " +
                           std::to_string(v.second) + (v.second == 1 ? " line)" : " lines)"));
}

}  // namespace dsr::obj
