// A run's outputs, whole or not at all, and never one of its inputs.
//
// Every output of a command (an image, --stats, --json, --report, a plot, figures' files, a
// viewer script's screenshots) is declared here, written to a temporary file beside its path as
// soon as it is ready, and renamed into place with the others by commit() at the end of the run;
// a failure anywhere before (or an exception that skips commit) removes the temporaries, so an
// unwritable --stats path leaves no image behind. An output that is the same file as an input of
// the run (device and inode, links followed: not the spelling), that another output already
// names, or that is a folder or a device is refused when it is declared, before any work.
// Errors are one line naming the user's path and the system's reason, never a temporary name:
//   dsr render: -o: expected a file that is not an input of this run, got 'a.scene' (the scene file a.scene)
//   dsr render: cannot write nodir/s.json: No such file or directory
#pragma once
#include <string>
#include <vector>

#include "scene/image.h"
#include "scene/user_file.h"

namespace dsr {

class OutputSet {
public:
    // `command` ("dsr render") starts every message; "" for none.
    explicit OutputSet(std::string command);
    ~OutputSet();  // removes every temporary file and new folder that commit() did not keep
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;

    // A file the run reads (`what` names it in messages, e.g. "the scene file"): no output may be it.
    void add_input(const std::string& path, const std::string& what);

    // Declares the output `path`, given by `flag` (for messages: "-o", "--stats", "screenshot").
    // Throws on an empty path, a folder or device, an input, or another output's file.
    void add(const std::string& flag, const std::string& path);

    // Creates folder `dir` (one level) when it does not exist; removed again unless committed.
    void make_dir(const std::string& flag, const std::string& dir);

    // Writes an output's content to its temporary file now (declaring `path` under `flag` if it
    // was not declared). Throws "cannot write PATH: REASON".
    void put_image(const std::string& flag, const std::string& path, const Image& img);
    void put_text(const std::string& flag, const std::string& path, const std::string& text);

    // Renames every temporary into place, in the order they were put. Throws (and removes what
    // it renamed) if one cannot be.
    void commit();

    // The outputs commit() wrote, in order.
    const std::vector<std::string>& written() const { return written_; }

private:
    struct Input {
        std::string path, what;
        FileId id;
    };
    struct Output {
        std::string flag, path, temp;  // temp: "" until put
    };
    [[noreturn]] void fail(const std::string& what) const;
    void check_against_inputs(const Output& out, const Input& in) const;
    Output& declared(const std::string& flag, const std::string& path);
    std::string create_temp(const Output& out);
    void discard();

    std::string command_;
    std::vector<Input> inputs_;
    std::vector<Output> outputs_;
    std::vector<std::string> new_dirs_, written_;
    bool committed_ = false;
};

}  // namespace dsr
