// The one reader of the files a user hands dsr: scene files, OBJ and MTL files, viewer scripts
// (read_user_text), and the check every image file passes before a decoder sees it
// (open_user_file). Regular files only (a FIFO would block, a device or directory has no end),
// a size limit per kind, a UTF-8 byte-order mark skipped, control bytes refused with their
// position. Every error is one dsr::Error line:
//   cannot open scene file a.scene: expected a regular file, got a FIFO
//   a.scene:3: expected text, got a NUL byte at column 17
// The limits are documented in docs/files.md, "Files dsr reads".
#pragma once
#include <sys/types.h>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dsr {

constexpr size_t kMaxSceneBytes = size_t(64) << 20;   // a scene file
constexpr size_t kMaxScriptBytes = size_t(16) << 20;  // a viewer script
constexpr size_t kMaxImageFileBytes = size_t(2) << 30; // an image file (its pixels have their own limits)

// Opens `path` for reading (links followed, never blocking) when it is a regular file of at most
// `max_bytes`, and returns the descriptor; anything else throws "cannot open WHAT PATH: REASON"
// (the system's reason, or "expected a regular file, got a FIFO"). The caller closes it.
int open_user_file(const std::string& path, const std::string& what, size_t max_bytes);

// The same check for a file another library opens by name (image decoders): throws as above.
void check_user_file(const std::string& path, const std::string& what, size_t max_bytes);

// The whole file as bytes, after open_user_file's checks (binary files: a .glb, its buffers).
std::string read_user_bytes(const std::string& path, const std::string& what, size_t max_bytes);

// The whole file: open_user_file's checks, then check_user_text's.
std::string read_user_text(const std::string& path, const std::string& what, size_t max_bytes);

// For text already in memory (the parsers' in-memory entry points call it too): drops a
// leading UTF-8 byte-order mark and refuses every control byte but tab, CR and LF:
// "PATH:LINE: expected text, got a NUL byte at column C" (lines as TextLines counts them).
void check_user_text(const std::string& path, std::string& text);

// What a file is when it is not a regular file, for "expected a regular file, got ...": "a
// directory", "a FIFO", "a character device", ...
std::string kind_of(mode_t m);

// `s` in single quotes, at most 60 characters ("..." after a cut, at a character boundary);
// control characters and bytes that are not UTF-8 shown as '?'. Every token or file name a
// message echoes goes through it, so no input can make an error line long or several lines.
std::string quote(std::string_view s);

// A message as one line: control characters (newlines included) become spaces and bytes that are
// not UTF-8 '?'. main() prints every error through it.
std::string one_line(std::string_view message);

// Lines of checked text: "\n", "\r\n" or a lone "\r" ends a line (as tinyobjloader ends them).
class TextLines {
public:
    explicit TextLines(std::string_view text) : text_(text) {}
    // The next line without its end; false after the last.
    bool next(std::string_view& line);
    int number() const { return number_; }  // of the line next() returned, from 1

private:
    std::string_view text_;
    size_t pos_ = 0;
    int number_ = 0;
};

// A line's tokens: separated by spaces and tabs, '#' to the end of the line a comment.
std::vector<std::string_view> split_tokens(std::string_view line);

// A file's identity: device and inode after following links. Two spellings of one file (a
// link, "./a", "../x/a") compare equal; nullopt when it does not exist (yet).
struct FileId {
    dev_t dev = 0;
    ino_t ino = 0;
    bool operator==(const FileId& o) const { return dev == o.dev && ino == o.ino; }
};
std::optional<FileId> file_id(const std::string& path);

}  // namespace dsr
