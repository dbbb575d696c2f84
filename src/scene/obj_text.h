// Internal to the OBJ loader (obj_loader.cpp and its parts): reading files, scanning OBJ/MTL
// text line by line so every check names the file and line, and collecting warnings one line per
// kind of substitution.
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
// The same in double quotes.
std::string dquote(std::string_view s);

// A file over kMaxObjBytes: refused whoever reads it (an MTL that cannot be read is otherwise a
// warning, one over the limit stays an error).
struct FileTooLarge : Error {
    using Error::Error;
};

// Reads a whole OBJ or MTL file's bytes through the user-file checks (scene/user_file.h): a
// directory, device or missing file is an Error naming `what` (e.g. "OBJ file") and the path,
// one over kMaxObjBytes a FileTooLarge. The text is not checked here: decode_text does that.
std::string read_regular_file(const std::string& path, const std::string& what);

// Text as read to checked UTF-8: UTF-16 (a byte-order mark FE FF or FF FE) decoded to UTF-8
// with a warning, then check_user_text (a UTF-8 byte-order mark dropped, control bytes
// refused). Bad UTF-16 (an odd length, an unpaired surrogate) is an error naming file and line.
void decode_text(const std::string& path, std::string& text, std::vector<std::string>& warnings);

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
    // The line after its first token, trimmed (file and material names may hold spaces).
    std::string_view rest_after_keyword() const;
    // The line without its comment (as tinyobjloader reads it).
    std::string_view line() const { return std::string_view(text_.data() + line_begin_, line_end_ - line_begin_); }
    // Blanks the current line in place (spaces), so the parser after the check never sees it.
    void blank();

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

// The warnings of one load, one line per kind of substitution per file: the first occurrence's
// line and message, and how many more lines had the same kind ("(and 3 more lines)").
class Notes {
public:
    // `kind` groups occurrences (never shown); `message` is the first one's text; `times` lines.
    void add(const std::string& file, int line, const std::string& kind, const std::string& message, size_t times = 1);
    // Appends "FILE:LINE: MESSAGE[ (and N more lines)]" per kind, in the order kinds first came.
    void flush(std::vector<std::string>& warnings);

private:
    struct Entry {
        std::string file, message;
        int line = 0;
        size_t count = 0;
    };
    std::vector<Entry> entries_;
    std::map<std::pair<std::string, std::string>, size_t> index_;  // (file, kind) -> entries_
};

// `\` in a file name written on Windows read as `/`; true when there was one.
bool backslashes_to_slashes(std::string& name);

}  // namespace dsr::obj
