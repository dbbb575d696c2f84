// Reading files, scanning OBJ/MTL text and collecting warnings for the OBJ loader (obj_text.h).
#include "scene/obj_text.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "scene/obj_loader.h"

namespace dsr::obj {

using std::string;
using std::string_view;

string dquote(string_view s) {
    string q = quote(s);
    q.front() = '"';
    q.back() = '"';
    return q;
}

string read_regular_file(const string& path, const string& what) {
    // The size limit is checked here, not by open_user_file, so that it is told apart from a
    // file that cannot be read at all.
    const int fd = open_user_file(path, what, SIZE_MAX);
    struct stat st {};
    ::fstat(fd, &st);
    auto too_large = [&](const string& got) {
        ::close(fd);
        throw FileTooLarge("cannot open " + what + " " + path + ": expected at most " + std::to_string(kMaxObjBytes) +
                           " bytes, got " + got);
    };
    if (uintmax_t(st.st_size) > kMaxObjBytes) too_large(std::to_string(uintmax_t(st.st_size)));
    string text;
    text.reserve(size_t(st.st_size));
    // Read to the end, not to st_size: one byte past the limit is enough to refuse a file that grew.
    char buf[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0) {
            if (errno == EINTR) continue;
            const int e = errno;
            ::close(fd);
            throw Error("cannot read " + what + " " + path + ": " + std::strerror(e));
        }
        if (n == 0) break;
        text.append(buf, size_t(n));
        if (text.size() > kMaxObjBytes) too_large("more");
    }
    ::close(fd);
    return text;
}

void decode_text(const string& path, string& text, std::vector<string>& warnings) {
    const bool be = text.size() >= 2 && (unsigned char)text[0] == 0xFE && (unsigned char)text[1] == 0xFF;
    const bool le = text.size() >= 2 && (unsigned char)text[0] == 0xFF && (unsigned char)text[1] == 0xFE;
    if (be || le) {
        int line = 1;
        auto fail = [&](const string& why) {
            throw Error(path + ":" + std::to_string(line) + ": expected UTF-16 text (it begins with a UTF-16 " +
                        "byte-order mark), got " + why);
        };
        if (text.size() % 2) fail("an odd number of bytes");
        string out;
        out.reserve(text.size() / 2);
        auto unit = [&](size_t i) {
            const unsigned a = (unsigned char)text[i], b = (unsigned char)text[i + 1];
            return be ? (a << 8 | b) : (b << 8 | a);
        };
        for (size_t i = 2; i < text.size(); i += 2) {
            uint32_t cp = unit(i);
            if (cp >= 0xDC00 && cp <= 0xDFFF) fail("an unpaired surrogate");
            if (cp >= 0xD800 && cp <= 0xDBFF) {
                if (i + 2 >= text.size()) fail("an unpaired surrogate");
                const uint32_t lo = unit(i + 2);
                if (lo < 0xDC00 || lo > 0xDFFF) fail("an unpaired surrogate");
                cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                i += 2;
            }
            if (cp == '\n') ++line;
            if (cp < 0x80) {
                out += char(cp);
            } else if (cp < 0x800) {
                out += char(0xC0 | (cp >> 6));
                out += char(0x80 | (cp & 0x3F));
            } else if (cp < 0x10000) {
                out += char(0xE0 | (cp >> 12));
                out += char(0x80 | ((cp >> 6) & 0x3F));
                out += char(0x80 | (cp & 0x3F));
            } else {
                out += char(0xF0 | (cp >> 18));
                out += char(0x80 | ((cp >> 12) & 0x3F));
                out += char(0x80 | ((cp >> 6) & 0x3F));
                out += char(0x80 | (cp & 0x3F));
            }
            if (out.size() > kMaxObjBytes)
                throw Error(path + ": expected at most " + std::to_string(kMaxObjBytes) + " bytes of UTF-8 text, got more");
        }
        text.swap(out);
        warnings.push_back(path + ":1: UTF-16 text (" + (be ? "big" : "little") +
                           "-endian, by its byte-order mark) read as UTF-8");
    }
    check_user_text(path, text);
}

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

void LineScanner::blank() {
    tokens_.clear();
    std::fill(text_.begin() + long(line_begin_), text_.begin() + long(line_end_), ' ');
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

// ---- warnings ------------------------------------------------------------------------------

void Notes::add(const string& file, int line, const string& kind, const string& message, size_t times) {
    auto [it, fresh] = index_.try_emplace({file, kind}, entries_.size());
    if (fresh) entries_.push_back(Entry{file, message, line, 0});
    entries_[it->second].count += times;
}

void Notes::flush(std::vector<string>& warnings) {
    for (const Entry& e : entries_) {
        string w = e.file + (e.line > 0 ? ":" + std::to_string(e.line) : string()) + ": " + e.message;
        if (e.count > 1)
            w += " (and " + std::to_string(e.count - 1) + (e.count == 2 ? " more line)" : " more lines)");
        warnings.push_back(std::move(w));
    }
    entries_.clear();
    index_.clear();
}

bool backslashes_to_slashes(string& name) {
    bool any = false;
    for (char& c : name)
        if (c == '\\') c = '/', any = true;
    return any;
}

}  // namespace dsr::obj
