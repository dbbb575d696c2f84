// The hostile-input suite: every case makes its inputs in a fresh folder, runs one `dsr`
// command there (cwd = the folder, so messages name files as written), and asserts what the
// project promises for bad input (docs/scene-format.md):
//   - the exit status (1 unless the case says otherwise), within a timeout: a hang fails;
//   - stderr is exactly one line, and it names the file (or flag) the case expects;
//   - afterwards the folder holds exactly what it held before, byte for byte: no output, no
//     temporary file, no changed input.
// Cases are tables, one file per reader or command (test_hostile_*.cpp), run as gtest
// parameters: `dsr_tests --gtest_filter='Scene/Hostile.*'`.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace dsr::hostile {

struct Case {
    std::string name;                                  // letters, digits, '_' (the gtest name)
    std::function<void(const std::string& dir)> setup;  // makes the inputs in `dir`
    std::string args;                                  // after `dsr`, shell words, run in `dir`
    std::string expect;                                // part of the one stderr line
    int status = 1;
    bool display = false;  // needs an X server (the viewer's window): run under this suite's Xvfb
};

// ---- making inputs (every path relative to the case's folder) -------------------------------

void write(const std::string& dir, const std::string& name, const std::string& bytes);
void fifo(const std::string& dir, const std::string& name);
void folder(const std::string& dir, const std::string& name);
void symlink_to(const std::string& dir, const std::string& name, const std::string& target);
void hardlink_to(const std::string& dir, const std::string& name, const std::string& target);
void sparse(const std::string& dir, const std::string& name, long long bytes);  // zeros, no disk
// A w x h image of one colour in the format of `name`'s extension (dsr's own writer).
void image(const std::string& dir, const std::string& name, int w, int h);
// The first `keep` bytes of `from` as `name` (keep < 0: size + keep).
void truncated(const std::string& dir, const std::string& name, const std::string& from, long long keep);
// A copy of `from` with `bytes` written over it at `offset`.
void damaged(const std::string& dir, const std::string& name, const std::string& from, long long offset,
             const std::string& bytes);
// An 8-bit grey PNG of w x h pixels with stored (uncompressed) deflate blocks: any size, no zlib.
void grey_png(const std::string& dir, const std::string& name, int w, int h);
// A PNG whose header claims w x h pixels and whose data is empty.
void header_only_png(const std::string& dir, const std::string& name, unsigned w, unsigned h);

// A valid scene: one camera line, a material `m` (with `extra` appended to its line), a light and
// a plane, then `more` lines.
std::string scene_text(const std::string& more = "", const std::string& material_extra = "");
constexpr const char* kCamera = "camera pos 0 1 5 target 0 0 0 up 0 1 0 fov 60 near 0.1 far 100\n";
// A two-triangle OBJ using material `a` of `mtl` (no mtllib when mtl is empty).
std::string quad_obj(const std::string& mtl = "");

// ---- running --------------------------------------------------------------------------------

// Runs the case and records every failed promise as a gtest failure.
void run_case(const Case& c);

class Hostile : public ::testing::TestWithParam<Case> {};

// For INSTANTIATE_TEST_SUITE_P: the case's name.
struct CaseName {
    std::string operator()(const ::testing::TestParamInfo<Case>& info) const { return info.param.name; }
};

}  // namespace dsr::hostile
