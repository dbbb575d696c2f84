// Procedural textures (deterministic, valid normal maps, seamless, matching the committed
// PNGs) and the image-file interface they go through (flip, channel expansion, atomic write).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include <dirent.h>
#include <unistd.h>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "dsr_error.h"
#include "scene/image.h"
#include "scene/procedural_textures.h"

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

const std::vector<std::pair<std::string, dsr::Image>>& textures() {
    static const auto t = dsr::default_textures();
    return t;
}

TEST(ProceduralTextures, DeterministicAndWellFormed) {
    const auto again = dsr::default_textures();
    ASSERT_EQ(again.size(), textures().size());
    ASSERT_GE(textures().size(), 6u);
    for (size_t i = 0; i < again.size(); ++i) {
        SCOPED_TRACE(again[i].first);
        EXPECT_EQ(again[i].first, textures()[i].first);
        EXPECT_EQ(again[i].second.width, 256);
        EXPECT_EQ(again[i].second.height, 256);
        EXPECT_TRUE(again[i].second.rgba == textures()[i].second.rgba) << "two calls differ";
        for (float v : again[i].second.rgba) ASSERT_TRUE(v >= 0 && v <= 1);
    }
    std::map<std::string, int> names;
    for (const auto& t : textures()) names[t.first]++;
    for (const char* n : {"brick_diffuse.png", "brick_normal.png", "brick_specular.png", "stone_diffuse.png",
                          "stone_normal.png", "stone_specular.png"})
        EXPECT_EQ(names[n], 1) << n;
}

TEST(ProceduralTextures, NormalMapsDecodeToUnitVectorsFacingOut) {
    int maps = 0;
    for (const auto& [name, img] : textures()) {
        if (!ends_with(name, "_normal.png")) continue;
        SCOPED_TRACE(name);
        ++maps;
        double tilted = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                const float* p = img.at(x, y);
                const glm::vec3 n(p[0] * 2 - 1, p[1] * 2 - 1, p[2] * 2 - 1);
                ASSERT_NEAR(glm::length(n), 1.0f, 0.02f) << x << "," << y;
                ASSERT_GT(n.z, 0.0f);
                tilted += n.z < 0.95f;
            }
        // Not flat: the joints and bevels tilt a good share of the texels.
        EXPECT_GT(tilted / (img.width * img.height), 0.05);
    }
    EXPECT_GE(maps, 2);
}

TEST(ProceduralTextures, SpecularMapsAreGreyAndLowInJoints) {
    for (const auto& [name, img] : textures()) {
        if (!ends_with(name, "_specular.png")) continue;
        SCOPED_TRACE(name);
        float lo = 1, hi = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                const float* p = img.at(x, y);
                ASSERT_EQ(p[0], p[1]);
                ASSERT_EQ(p[1], p[2]);
                lo = std::min(lo, p[0]);
                hi = std::max(hi, p[0]);
            }
        EXPECT_LT(lo, 0.05f);  // joints
        EXPECT_GT(hi, 0.2f);   // faces
    }
}

// Seamless: the step across the wrap edge is no bigger than a typical step inside.
TEST(ProceduralTextures, TileSeamlessly) {
    for (const auto& [name, img] : textures()) {
        SCOPED_TRACE(name);
        const int w = img.width, h = img.height;
        auto col_step = [&](int x0, int x1) {
            double s = 0;
            for (int y = 0; y < h; ++y)
                for (int c = 0; c < 3; ++c) s += std::abs(img.at(x0, y)[c] - img.at(x1, y)[c]);
            return s / h;
        };
        auto row_step = [&](int y0, int y1) {
            double s = 0;
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c) s += std::abs(img.at(x, y0)[c] - img.at(x, y1)[c]);
            return s / w;
        };
        double inner_x = 0, inner_y = 0;
        for (int i = 0; i + 1 < w; ++i) inner_x += col_step(i, i + 1);
        for (int i = 0; i + 1 < h; ++i) inner_y += row_step(i, i + 1);
        inner_x /= w - 1;
        inner_y /= h - 1;
        EXPECT_LE(col_step(w - 1, 0), 2.5 * inner_x + 1e-3);
        EXPECT_LE(row_step(h - 1, 0), 2.5 * inner_y + 1e-3);
    }
}

// The committed PNGs are what the generator makes now (regenerate with
// `build/dsr gen-textures data/textures` after changing procedural_textures.cpp).
TEST(ProceduralTextures, CommittedPngsMatchGenerator) {
    const std::string dir = std::string(DSR_SOURCE_DIR) + "/data/textures/";
    for (const auto& [name, fresh] : textures()) {
        SCOPED_TRACE(name);
        const dsr::Image disk = dsr::load_image(dir + name);
        ASSERT_EQ(disk.width, fresh.width);
        ASSERT_EQ(disk.height, fresh.height);
        float worst = 0;
        for (size_t i = 0; i < disk.rgba.size(); ++i) worst = std::max(worst, std::abs(disk.rgba[i] - fresh.rgba[i]));
        EXPECT_LE(worst, 1.0f / 255.0f);
    }
}

// --- image files ---------------------------------------------------------------------------

class ImageIoTest : public ::testing::Test {
protected:
    void SetUp() override {
        char tmpl[] = "/tmp/dsr_image_test_XXXXXX";
        ASSERT_NE(mkdtemp(tmpl), nullptr);
        dir_ = tmpl;
    }
    void TearDown() override {
        // Remove whatever the test left, then the folder (which must then be empty).
        if (DIR* d = opendir(dir_.c_str())) {
            while (dirent* e = readdir(d))
                if (e->d_name[0] != '.') std::remove((dir_ + "/" + e->d_name).c_str());
            closedir(d);
        }
        rmdir(dir_.c_str());
    }
    std::vector<std::string> entries() const {
        std::vector<std::string> out;
        if (DIR* d = opendir(dir_.c_str())) {
            while (dirent* e = readdir(d))
                if (e->d_name[0] != '.') out.push_back(e->d_name);
            closedir(d);
        }
        return out;
    }
    std::string dir_;
};

dsr::Image gradient(int w, int h) {
    dsr::Image img;
    img.width = w;
    img.height = h;
    img.rgba.resize(size_t(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img.at(x, y);
            p[0] = float(x) / (w - 1);
            p[1] = float(y) / (h - 1);
            p[2] = 0.25f;
            p[3] = 1.0f;
        }
    return img;
}

TEST_F(ImageIoTest, PngRoundTripIs8BitAndKeepsRowOrder) {
    const dsr::Image img = gradient(5, 4);
    const std::string path = dir_ + "/g.png";
    dsr::write_image(path, img);
    EXPECT_EQ(entries(), std::vector<std::string>{"g.png"});  // no temp file left behind
    const dsr::Image back = dsr::load_image(path);
    ASSERT_EQ(back.width, 5);
    ASSERT_EQ(back.height, 4);
    for (size_t i = 0; i < img.rgba.size(); ++i) EXPECT_NEAR(back.rgba[i], img.rgba[i], 0.5f / 255 + 1e-6f);
    // Row 0 stays the bottom row (green 0) through the file's top-first order.
    EXPECT_EQ(back.at(0, 0)[1], 0.0f);
    EXPECT_EQ(back.at(0, 3)[1], 1.0f);
}

TEST_F(ImageIoTest, ExrRoundTripIsHalfFloat) {
    dsr::Image img = gradient(3, 2);
    img.at(1, 1)[0] = 7.5f;  // HDR survives
    const std::string path = dir_ + "/g.exr";
    dsr::write_image(path, img);
    const dsr::Image back = dsr::load_image(path);
    ASSERT_EQ(back.rgba.size(), img.rgba.size());
    for (size_t i = 0; i < img.rgba.size(); ++i) EXPECT_NEAR(back.rgba[i], img.rgba[i], 1e-3f * (1 + img.rgba[i]));
}

TEST_F(ImageIoTest, GreyBecomesRgbAndMissingAlphaIsOpaque) {
    // Hand-written PGM (grey, 2x2, top row first): 0 64 / 128 255.
    const std::string pgm = dir_ + "/grey.pgm";
    std::ofstream(pgm, std::ios::binary) << "P5\n2 2\n255\n" << std::string("\x00\x40\x80\xff", 4);
    const dsr::Image g = dsr::load_image(pgm);
    ASSERT_EQ(g.width, 2);
    ASSERT_EQ(g.height, 2);
    // File's top row (0, 64) is Image row 1.
    EXPECT_FLOAT_EQ(g.at(1, 1)[0], 64.0f / 255);
    EXPECT_FLOAT_EQ(g.at(1, 1)[1], 64.0f / 255);
    EXPECT_FLOAT_EQ(g.at(1, 1)[2], 64.0f / 255);
    EXPECT_FLOAT_EQ(g.at(0, 0)[0], 128.0f / 255);
    EXPECT_FLOAT_EQ(g.at(1, 0)[3], 1.0f);
    // RGB PPM: alpha 1.
    const std::string ppm = dir_ + "/rgb.ppm";
    std::ofstream(ppm, std::ios::binary) << "P6\n1 1\n255\n" << std::string("\x10\x20\x30", 3);
    const dsr::Image c = dsr::load_image(ppm);
    EXPECT_FLOAT_EQ(c.at(0, 0)[2], 48.0f / 255);
    EXPECT_FLOAT_EQ(c.at(0, 0)[3], 1.0f);
}

TEST_F(ImageIoTest, ErrorsNameThePathAndLeaveNothing) {
    const std::string missing = dir_ + "/nope.png";
    try {
        dsr::load_image(missing);
        FAIL() << "no error";
    } catch (const dsr::Error& e) {
        EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    }
    const std::string bad_dir = dir_ + "/no_such_dir/out.png";
    try {
        dsr::write_image(bad_dir, gradient(2, 2));
        FAIL() << "no error";
    } catch (const dsr::Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("cannot write " + bad_dir + ": ", 0), 0u) << e.what();
    }
    try {
        dsr::write_image(dir_ + "/out.not_an_image_format", gradient(2, 2));
        FAIL() << "no error";
    } catch (const dsr::Error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot write "), std::string::npos) << e.what();
    }
    EXPECT_TRUE(entries().empty());
}

}  // namespace

namespace {

class ImageDamage : public ImageIoTest {};

// Cut short at any point, every format dsr (OpenImageIO) writes is refused with one line naming
// the file, whatever the decoder printed, and so is a header alone or a file of another kind;
// where libjpeg used to fill the missing half with grey and say nothing to dsr.
TEST_F(ImageDamage, CutShortIsAnErrorInEveryFormat) {
    const dsr::Image img = gradient(64, 64);
    int formats = 0;
    for (const std::string ext : {".png", ".jpg", ".tif", ".exr", ".ppm", ".bmp", ".tga", ".hdr", ".sgi", ".pnm", ".dpx"}) {
        const std::string full = dir_ + "/full" + ext;
        try {
            dsr::write_image(full, img);
        } catch (const dsr::Error&) {
            continue;  // this OpenImageIO has no writer for it
        }
        ++formats;
        std::ifstream in(full, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_NO_THROW(dsr::load_image(full)) << ext;
        // TGA ends in optional metadata (a 495-byte extension area and a 26-byte footer, no pixels):
        // cut inside them the picture is whole and reads as one; its cuts stay in the pixels.
        const bool tga = ext == ".tga";
        for (const size_t keep : {size_t(20), bytes.size() / 2, tga ? bytes.size() * 3 / 4 : bytes.size() - 30,
                                  tga ? bytes.size() * 9 / 10 : bytes.size() - 1}) {
            const std::string cut = dir_ + "/cut" + ext;
            std::ofstream(cut, std::ios::binary) << bytes.substr(0, keep);
            try {
                dsr::load_image(cut);
                ADD_FAILURE() << ext << " cut to " << keep << " of " << bytes.size() << " bytes was read";
            } catch (const dsr::Error& e) {
                const std::string m = e.what();
                EXPECT_EQ(m.rfind("cannot read image " + cut + ": ", 0), 0u) << m;
                EXPECT_EQ(m.find('\n'), std::string::npos) << m;
            }
            std::remove(cut.c_str());
        }
        std::remove(full.c_str());
    }
    EXPECT_GE(formats, 5);
}

// The decoders' own lines (libpng's "IDAT: invalid distance too far back" printed twice) are in
// the error and not on stderr.
TEST_F(ImageDamage, DamagedPngIsOneLineAndStderrStaysQuiet) {
    const std::string full = dir_ + "/full.png";
    dsr::write_image(full, gradient(64, 64));
    std::ifstream in(full, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    bytes.replace(200, 8, "XXXXXXXX");
    const std::string bad = dir_ + "/bad.png";
    std::ofstream(bad, std::ios::binary) << bytes;
    ::testing::internal::CaptureStderr();
    std::string m;
    try {
        dsr::load_image(bad);
    } catch (const dsr::Error& e) {
        m = e.what();
    }
    const std::string printed = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(m.rfind("cannot read image " + bad + ": ", 0), 0u) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_EQ(printed, "");
}

// A header claims a size: over the caller's budget is ImageTooLarge (with the size), over the
// per-image limits a plain error; nothing is allocated for either.
TEST_F(ImageDamage, SizeLimitsAreCheckedOnTheHeader) {
    const std::string p = dir_ + "/a.png";
    dsr::write_image(p, gradient(64, 32));
    try {
        dsr::load_image(p, 1000);
        ADD_FAILURE() << "no error";
    } catch (const dsr::ImageTooLarge& e) {
        EXPECT_EQ(e.width, 64);
        EXPECT_EQ(e.height, 32);
    }
    EXPECT_EQ(dsr::load_image(p, 2048).width, 64);
    const std::string pnm = dir_ + "/big.ppm";
    std::ofstream(pnm, std::ios::binary) << "P6\n20000 20000\n255\n";
    try {
        dsr::load_image(pnm);
        ADD_FAILURE() << "no error";
    } catch (const dsr::ImageTooLarge&) {
        ADD_FAILURE() << "an absurd size is not a budget";
    } catch (const dsr::Error& e) {
        EXPECT_NE(std::string(e.what()).find("20000 x 20000 pixels, expected at most 16384 a side"), std::string::npos) << e.what();
    }
}

}  // namespace
