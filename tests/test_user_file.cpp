// The reader every user file goes through (scene/user_file.h), the outputs of a run
// (scene/output_set.h) and the capture of decoders' stderr (scene/stderr_capture.h), piece by
// piece; tests/hostile/ runs the same promises through the commands.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.h"
#include "dsr_error.h"
#include "scene/image.h"
#include "scene/output_set.h"
#include "scene/stderr_capture.h"
#include "scene/user_file.h"

namespace fs = std::filesystem;
using namespace dsr;

namespace {

class UserFiles : public ::testing::Test {
protected:
    void SetUp() override { dir_ = test::temp_dir(); }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    std::string path(const std::string& name) const { return dir_ + "/" + name; }
    std::string write(const std::string& name, const std::string& bytes) const {
        std::ofstream(path(name), std::ios::binary) << bytes;
        return path(name);
    }
    std::string error_of(const std::function<void()>& f) const {
        try {
            f();
        } catch (const Error& e) {
            return e.what();
        }
        ADD_FAILURE() << "no error";
        return "";
    }
    // Every entry of the folder, sorted.
    std::string listing() const {
        std::string s;
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        for (const std::string& n : names) s += n + " ";
        return s;
    }
    static Image grey(int w, int h) {
        Image img;
        img.width = w, img.height = h;
        img.rgba.assign(size_t(w) * size_t(h) * 4, 0.5f);
        for (size_t i = 0; i < img.rgba.size(); i += 4) img.rgba[i] = float(i % 89) / 89.0f;
        return img;
    }

    std::string dir_;
};

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << "message: " << (msg)

TEST(UserText, QuoteCutsAtSixtyCharactersAndShowsOnlyPrintableUtf8) {
    EXPECT_EQ(quote("teapot"), "'teapot'");
    EXPECT_EQ(quote(std::string(61, 'x')), "'" + std::string(60, 'x') + "...'");
    EXPECT_EQ(quote(std::string(60, 'x')), "'" + std::string(60, 'x') + "'");
    // Sixty characters, not bytes: a cut never splits a UTF-8 sequence.
    std::string e;
    for (int i = 0; i < 70; ++i) e += "\xC3\xA9";
    const std::string q = quote(e);
    EXPECT_EQ(q.size(), 2 + 120 + 3u) << q;
    EXPECT_EQ(q.substr(q.size() - 5), "\xA9...'");
    EXPECT_EQ(quote(std::string("a\0b\nc\x1b\x7f", 7)), "'a?b?c?\?'");
    EXPECT_EQ(quote("\xff\xfe ok \xC3"), "'?\? ok ?'");     // not UTF-8: a '?' per byte
    EXPECT_EQ(quote("\xC2\x85"), "'?'");                  // NEL, a C1 control
    EXPECT_EQ(quote("\xED\xA0\x80"), "'?\?\?'");            // a surrogate is not UTF-8
    EXPECT_EQ(quote("\xE2\x82\xAC"), "'\xE2\x82\xAC'");   // the euro sign is
}

TEST(UserText, OneLineTurnsControlCharactersIntoSpaces) {
    EXPECT_EQ(one_line("a\nb\r\nc\td"), "a b  c d");
    EXPECT_EQ(one_line("ends with newline\n"), "ends with newline");
    EXPECT_EQ(one_line("\xff.scene"), "?.scene");
}

TEST(UserText, ByteOrderMarkDroppedAndControlBytesRefusedWithLineAndColumn) {
    std::string t = "\xEF\xBB\xBF" "camera\n";
    check_user_text("a.scene", t);
    EXPECT_EQ(t, "camera\n");
    auto error = [](std::string text) {
        try {
            check_user_text("a.scene", text);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error(std::string("ab\0", 3)), "a.scene:1: expected text, got a NUL byte at column 3");
    // Lines end at \n, \r\n and a lone \r, as TextLines counts them.
    EXPECT_EQ(error("1\n2\r\n3\r4 \x01"), "a.scene:4: expected text, got the control byte 0x01 at column 3");
    // Columns count characters: the two-byte é is one.
    EXPECT_EQ(error("\xC3\xA9\x7f"), "a.scene:1: expected text, got the control byte 0x7F at column 2");
    EXPECT_EQ(error("tab\tand\rcr\n"), "no error");
    EXPECT_EQ(error("\f"), "a.scene:1: expected text, got the control byte 0x0C at column 1");
}

TEST(UserText, LinesAndTokens) {
    TextLines lines("a b\r\nc\rd\n\ne");
    std::vector<std::string> got;
    for (std::string_view l; lines.next(l);) got.push_back(std::to_string(lines.number()) + ":" + std::string(l));
    EXPECT_EQ(got, (std::vector<std::string>{"1:a b", "2:c", "3:d", "4:", "5:e"}));
    const auto t = split_tokens("  sphere\tradius 1 # at 0 0 0");
    EXPECT_EQ(std::vector<std::string>(t.begin(), t.end()), (std::vector<std::string>{"sphere", "radius", "1"}));
}

TEST_F(UserFiles, OnlyRegularFilesAreRead) {
    ASSERT_EQ(mkfifo(path("f.scene").c_str(), 0644), 0);
    // Refused without blocking: the open does not wait for a writer.
    EXPECT_EQ(error_of([&] { read_user_text(path("f.scene"), "scene file", 1000); }),
              "cannot open scene file " + path("f.scene") + ": expected a regular file, got a FIFO");
    fs::create_directories(path("d.scene"));
    EXPECT_HAS(error_of([&] { read_user_text(path("d.scene"), "scene file", 1000); }), "expected a file, got a directory");
    EXPECT_EQ(error_of([&] { read_user_text("/dev/zero", "scene file", 1000); }),
              "cannot open scene file /dev/zero: expected a regular file, got a character device");
    EXPECT_EQ(error_of([&] { read_user_text(path("none"), "OBJ file", 1000); }),
              "cannot open OBJ file " + path("none") + ": No such file or directory");
    ASSERT_EQ(symlink("loop", path("loop").c_str()), 0);
    EXPECT_HAS(error_of([&] { read_user_text(path("loop"), "OBJ file", 1000); }), "Too many levels of symbolic links");
    EXPECT_EQ(error_of([&] { read_user_text("", "scene file", 1000); }), "cannot open scene file: expected a file name, got ''");
    write("big", std::string(1001, 'x'));
    EXPECT_EQ(error_of([&] { read_user_text(path("big"), "viewer script", 1000); }),
              "cannot open viewer script " + path("big") + ": expected at most 1000 bytes, got 1001");
    // A file that says it is empty (under /proc) is read to its end, and the limit still holds.
    const std::string status = read_user_text("/proc/self/status", "file", 1 << 20);
    EXPECT_NE(status.find("Name:"), std::string::npos);
    EXPECT_HAS(error_of([] { read_user_text("/proc/self/status", "file", 10); }), "expected at most 10 bytes, got more");
    // A byte-order mark is gone from what the parsers see.
    write("bom", "\xEF\xBB\xBFok\n");
    EXPECT_EQ(read_user_text(path("bom"), "file", 100), "ok\n");
}

TEST_F(UserFiles, FileIdSeesThroughSpellingsAndLinks) {
    write("a", "x");
    fs::create_directories(path("sub"));
    ASSERT_EQ(symlink("a", path("s").c_str()), 0);
    ASSERT_EQ(link(path("a").c_str(), path("h").c_str()), 0);
    const auto a = file_id(path("a"));
    ASSERT_TRUE(a.has_value());
    EXPECT_TRUE(*a == *file_id(path("sub/../a")));
    EXPECT_TRUE(*a == *file_id(path("s")));
    EXPECT_TRUE(*a == *file_id(path("h")));
    write("b", "x");
    EXPECT_FALSE(*a == *file_id(path("b")));
    EXPECT_FALSE(file_id(path("none")).has_value());
}

TEST_F(UserFiles, AnOutputIsNeverAnInputWhateverItsSpelling) {
    write("a.scene", "camera");
    ASSERT_EQ(symlink("a.scene", path("link.png").c_str()), 0);
    ASSERT_EQ(link(path("a.scene").c_str(), path("hard.png").c_str()), 0);
    fs::create_directories(path("sub"));
    for (const char* out : {"a.scene", "sub/../a.scene", "link.png", "hard.png"}) {
        OutputSet o("dsr test");
        o.add_input(path("a.scene"), "the scene file");
        EXPECT_EQ(error_of([&] { o.add("-o", path(out)); }),
                  "dsr test: -o: expected a file that is not an input of this run, got " + quote(path(out)) +
                      " (the scene file " + path("a.scene") + ")");
    }
    // The same when the output is declared first and the input found later (a scene's texture).
    OutputSet late("dsr test");
    late.add("-o", path("hard.png"));
    EXPECT_HAS(error_of([&] { late.add_input(path("a.scene"), "a file the scene reads,"); }), "-o: expected a file that is not an input");
    EXPECT_EQ(listing(), "a.scene hard.png link.png sub ");
}

TEST_F(UserFiles, TwoOutputsOfOneFileFoldersAndDevicesAreRefused) {
    OutputSet o("dsr test");
    fs::create_directories(path("sub"));
    o.add("--json", path("x.png"));
    EXPECT_EQ(error_of([&] { o.add("--plot", path("sub/../x.png")); }),
              "dsr test: --plot: expected a file no other output names, got " + quote(path("sub/../x.png")) +
                  " (also --json " + path("x.png") + ")");
    fs::create_directories(path("d.png"));
    EXPECT_HAS(error_of([&] { o.add("-o", path("d.png")); }), "-o: expected a file to write, got");
    EXPECT_HAS(error_of([&] { o.add("-o", "/dev/null"); }), "a character device");
    EXPECT_EQ(error_of([&] { o.add("-o", path("nodir/x.png")); }),
              "dsr test: -o: cannot write " + path("nodir/x.png") + ": No such file or directory");
    EXPECT_EQ(error_of([&] { o.add("-o", ""); }), "dsr test: -o: expected a file name, got ''");
}

TEST_F(UserFiles, NothingIsLeftUnlessCommitted) {
    {
        OutputSet o("dsr test");
        o.put_image("-o", path("a.png"), grey(4, 4));
        o.put_text("--stats", path("s.json"), "{}\n");
        EXPECT_FALSE(fs::exists(path("a.png")));
        EXPECT_EQ(listing().find("s.json"), std::string::npos);
    }  // no commit: an error skipped it
    EXPECT_EQ(listing(), "");
    OutputSet o("dsr test");
    o.make_dir("-o", path("figs"));
    o.put_image("-o", path("figs/a.png"), grey(4, 4));
    o.put_text("--stats", path("s.json"), "{}\n");
    o.commit();
    EXPECT_EQ(listing(), "figs s.json ");
    EXPECT_EQ(o.written(), (std::vector<std::string>{path("figs/a.png"), path("s.json")}));
    EXPECT_EQ(load_image(path("figs/a.png")).width, 4);
}

TEST_F(UserFiles, AFolderMadeForOutputsGoesWithThem) {
    {
        OutputSet o("dsr test");
        o.make_dir("-o", path("figs"));
        o.put_image("-o", path("figs/a.png"), grey(4, 4));
    }
    EXPECT_EQ(listing(), "");
}

TEST_F(UserFiles, CommitIsAllOrNone) {
    write("b.json", "old");
    OutputSet o("dsr test");
    o.put_image("-o", path("a.png"), grey(4, 4));
    o.put_text("--stats", path("b.json"), "{}\n");
    // The second target turns into a folder before the end: its rename fails, and the first
    // output, already in place, is taken back.
    fs::remove(path("b.json"));
    fs::create_directories(path("b.json/x"));
    const std::string e = error_of([&] { o.commit(); });
    EXPECT_EQ(e.rfind("dsr test: --stats: cannot write " + path("b.json") + ": ", 0), 0u) << e;
    EXPECT_EQ(e.find(".dsr-"), std::string::npos) << "names a temporary file: " << e;
    EXPECT_FALSE(fs::exists(path("a.png")));
    EXPECT_EQ(listing(), "b.json ");
}

TEST_F(UserFiles, WriteErrorsNameTheUsersPathAndTheSystemsReason) {
    fs::create_directories(path("gone"));
    OutputSet o("dsr test");
    o.add("-o", path("gone/a.png"));
    fs::remove(path("gone"));
    const std::string e = error_of([&] { o.put_image("-o", path("gone/a.png"), grey(4, 4)); });
    EXPECT_EQ(e, "dsr test: -o: cannot write " + path("gone/a.png") + ": No such file or directory");
    // The image writer's own failures name the user's path too, never the temporary file.
    const std::string f = error_of([&] { write_image(path("x.not_an_image_format"), grey(2, 2)); });
    EXPECT_EQ(f.rfind("cannot write " + path("x.not_an_image_format") + ": ", 0), 0u) << f;
    EXPECT_EQ(f.find(".dsr-"), std::string::npos) << f;
    EXPECT_EQ(listing(), "");
}

TEST(StderrCapture, WhatLibrariesPrintBecomesOneLine) {
    std::string said;
    {
        StderrCapture capture;
        std::fprintf(stderr, "libpng warning: iCCP: known incorrect sRGB profile\n");
        const char raw[] = "second line\n";
        ASSERT_EQ(::write(2, raw, sizeof raw - 1), ssize_t(sizeof raw - 1));
        said = capture.text();
    }
    EXPECT_EQ(said, "libpng warning: iCCP: known incorrect sRGB profile; second line");
}

// A path that is not UTF-8 is a valid scene file name: --stats writes it with U+FFFD, where it
// was refused with nlohmann's raw type_error after the image had been written.
TEST_F(UserFiles, StatsOfASceneWhoseNameIsNotUtf8) {
    std::ifstream in(std::string(DSR_SOURCE_DIR) + "/tests/data/analytic.scene");
    std::stringstream ss;
    ss << in.rdbuf();
    write("\xfe\xff.scene", ss.str());
    const test::RunResult r = test::run("render '" + path("\xfe\xff.scene") + "' --size 16x16 -o " + path("a.png") +
                                        " --stats " + path("s.json"));
    EXPECT_EQ(r.status, 0) << r.output;
    std::ifstream j(path("s.json"));
    std::stringstream js;
    js << j.rdbuf();
    EXPECT_NE(js.str().find("\xEF\xBF\xBD\xEF\xBF\xBD.scene"), std::string::npos) << js.str();
}

}  // namespace
