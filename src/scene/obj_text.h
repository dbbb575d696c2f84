// Internal to the OBJ loader (obj_loader.cpp and its parts): reading files and scanning OBJ/MTL
// text line by line, so every check names the file and line.
#pragma once
#include <map>
#include <streambuf>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "dsr_error.h"
#include "scene/image.h"
#include "scene/user_file.h"

namespace dsr::obj {

// `s` in single quotes, at most 60 characters (scene/user_file.h).
using dsr::quote;

// Reads a whole OBJ or MTL file through the user-file reader (scene/user_file.h): a directory,
// device, missing file or one over kMaxObjBytes is an error naming `what` (e.g. "OBJ file") and
// the path; a byte-order mark is dropped and control bytes refused.
std::string read_regular_file(const std::string& path, const std::string& what);

// load_image under `max_texels` (a regular file only).
Image read_regular_image(const std::string& path, size_t max_texels);

// A read-only streambuf over a string, so tinyobjloader reads the checked text without a copy.
struct MemBuf : std::streambuf {
    MemBuf(const char* b, size_t n) {
        char* p = const_cast<char*>(b);
        setg(p, p, p + n);
    }
};

// ---- line scanning -------------------------------------------------------------------------

// Walks a text line by line. Comments ('#' to end of line) are blanked in place, so the parser
// that reads the text afterwards sees exactly the tokens checked here.
class LineScanner {
public:
    LineScanner(const std::string& file, std::string& text) : file_(file), text_(text) {}

    // Next line's tokens (separated by spaces and tabs); false at the end. A line ends at "\n",
    // "\r\n" or a lone "\r", as tinyobjloader's reader ends it.
    bool next();

    const std::vector<std::string_view>& tokens() const { return tokens_; }
    int number() const { return number_; }
    std::string where() const { return file_ + ":" + std::to_string(number_); }
    // The line after its first token, trimmed (file names may hold spaces).
    std::string_view rest_after_keyword() const;

    [[noreturn]] void fail(const std::string& problem) const { throw Error(where() + ": " + problem); }
    [[noreturn]] void expected(const std::string& what, size_t token) const;

    // Token `i` as a finite number within kMaxObjCoordinate. Only the characters both strtod
    // and tinyobjloader read the same way are accepted (no hex, no "nan"/"inf").
    double number(size_t i, const std::string& subject) const;

    // Token `i` as a (possibly negative) integer; empty tokens are not integers.
    long integer(std::string_view t, const std::string& subject) const;

    // tinyobjloader's separators; anything else is part of a token.
    static bool is_space(char c) { return c == ' ' || c == '\t'; }

private:
    const std::string& file_;
    std::string& text_;
    size_t pos_ = 0, line_begin_ = 0, line_end_ = 0;
    int number_ = 0;
    std::vector<std::string_view> tokens_;
};

// "first line and count" of statements that are skipped, for one warning per keyword.
struct Ignored {
    std::map<std::string, std::pair<int, int>> seen;  // keyword -> (first line, count)
    void add(const std::string& k, int line);
    void report(const std::string& file, const std::string& why, std::vector<std::string>& warnings) const;
};

}  // namespace dsr::obj
