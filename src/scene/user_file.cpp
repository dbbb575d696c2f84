// Reading user files (user_file.h): the checks every reader shares.
#include "scene/user_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "dsr_error.h"

namespace dsr {

std::string kind_of(mode_t m) {
    if (S_ISDIR(m)) return "a directory";
    if (S_ISFIFO(m)) return "a FIFO";
    if (S_ISCHR(m)) return "a character device";
    if (S_ISBLK(m)) return "a block device";
    if (S_ISSOCK(m)) return "a socket";
    return "something that is not a file";
}

namespace {

// Checks a stat result: regular and at most max_bytes; returns the reason to refuse, or "".
std::string refusal(const struct stat& st, size_t max_bytes) {
    if (S_ISDIR(st.st_mode)) return "expected a file, got a directory";
    if (!S_ISREG(st.st_mode)) return "expected a regular file, got " + kind_of(st.st_mode);
    if (uintmax_t(st.st_size) > max_bytes)
        return "expected at most " + std::to_string(max_bytes) + " bytes, got " + std::to_string(uintmax_t(st.st_size));
    return "";
}

[[noreturn]] void cannot_open(const std::string& path, const std::string& what, const std::string& why) {
    if (path.empty()) throw Error("cannot open " + what + ": expected a file name, got ''");
    throw Error("cannot open " + what + " " + path + ": " + why);
}

// One UTF-8 sequence at s[i]: its length, and whether it is a well-formed printable character
// (not a C0 or C1 control, not DEL, no overlong form or surrogate). Length 1 when malformed.
struct Char {
    size_t len;
    bool printable;
};
Char char_at(std::string_view s, size_t i) {
    const unsigned char c = (unsigned char)s[i];
    if (c < 0x80) return {1, c >= 32 && c != 127};
    size_t len = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 0;
    if (len == 0 || c > 0xF4 || i + len > s.size()) return {1, false};
    uint32_t cp = c & (0x7F >> len);
    for (size_t k = 1; k < len; ++k) {
        const unsigned char d = (unsigned char)s[i + k];
        if ((d & 0xC0) != 0x80) return {1, false};
        cp = (cp << 6) | (d & 0x3F);
    }
    const uint32_t min[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < min[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return {1, false};
    return {len, !(cp >= 0x80 && cp <= 0x9F)};
}

}  // namespace

int open_user_file(const std::string& path, const std::string& what, size_t max_bytes) {
    if (path.empty()) cannot_open(path, what, "");
    // stat first, so a device is never opened; fstat again after, for what was really opened.
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) cannot_open(path, what, std::strerror(errno));
    std::string why = refusal(st, max_bytes);
    if (!why.empty()) cannot_open(path, what, why);
    // O_NONBLOCK: a FIFO put in the file's place since the stat opens without waiting for a writer.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) cannot_open(path, what, std::strerror(errno));
    if (::fstat(fd, &st) != 0) {
        const int e = errno;
        ::close(fd);
        cannot_open(path, what, std::strerror(e));
    }
    why = refusal(st, max_bytes);
    if (!why.empty()) {
        ::close(fd);
        cannot_open(path, what, why);
    }
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    return fd;
}

void check_user_file(const std::string& path, const std::string& what, size_t max_bytes) {
    ::close(open_user_file(path, what, max_bytes));
}

std::string read_user_bytes(const std::string& path, const std::string& what, size_t max_bytes) {
    const int fd = open_user_file(path, what, max_bytes);
    struct stat st {};
    ::fstat(fd, &st);
    std::string data;
    data.reserve(size_t(st.st_size));
    // Read to the end, not to st_size: files under /proc say 0 and have text; one byte past the
    // limit is enough to refuse a file that grew.
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
        data.append(buf, size_t(n));
        if (data.size() > max_bytes) {
            ::close(fd);
            throw Error("cannot read " + what + " " + path + ": expected at most " + std::to_string(max_bytes) +
                        " bytes, got more");
        }
    }
    ::close(fd);
    return data;
}

std::string read_user_text(const std::string& path, const std::string& what, size_t max_bytes) {
    std::string text = read_user_bytes(path, what, max_bytes);
    check_user_text(path, text);
    return text;
}

void check_user_text(const std::string& path, std::string& text) {
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
    int line = 1;
    size_t column = 1;
    for (size_t i = 0; i < text.size(); ++i) {
        const unsigned char c = (unsigned char)text[i];
        if (c == '\n' || c == '\r') {
            if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
            ++line;
            column = 1;
        } else if ((c < 32 && c != '\t') || c == 127) {
            char code[8];
            std::snprintf(code, sizeof code, "0x%02X", c);
            throw Error(path + ":" + std::to_string(line) + ": expected text, got " +
                        (c == 0 ? std::string("a NUL byte") : "the control byte " + std::string(code)) +
                        " at column " + std::to_string(column));
        } else if ((c & 0xC0) != 0x80) {
            ++column;  // columns count characters, not the continuation bytes of UTF-8
        }
    }
}

std::string quote(std::string_view s) {
    const size_t max = 60;
    std::string out = "'";
    size_t i = 0, chars = 0;
    while (i < s.size()) {
        if (chars == max) {
            out += "...";
            break;
        }
        const Char ch = char_at(s, i);
        if (ch.printable) out.append(s.data() + i, ch.len);
        else out += '?';
        i += ch.len;
        ++chars;
    }
    return out + "'";
}

std::string one_line(std::string_view message) {
    std::string out;
    out.reserve(message.size());
    size_t i = 0;
    while (i < message.size()) {
        const Char ch = char_at(message, i);
        if (ch.printable) out.append(message.data() + i, ch.len);
        else out += (unsigned char)message[i] < 0x80 ? ' ' : '?';
        i += ch.len;
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

bool TextLines::next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    size_t end = pos_;
    while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') ++end;
    line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    if (end + 1 < text_.size() && text_[end] == '\r' && text_[end + 1] == '\n') ++pos_;
    ++number_;
    return true;
}

std::vector<std::string_view> split_tokens(std::string_view line) {
    const size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const size_t b = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > b) out.push_back(line.substr(b, i - b));
    }
    return out;
}

std::optional<FileId> file_id(const std::string& path) {
    struct stat st {};
    if (path.empty() || ::stat(path.c_str(), &st) != 0) return std::nullopt;
    return FileId{st.st_dev, st.st_ino};
}

}  // namespace dsr
