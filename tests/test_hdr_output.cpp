// A float image file holds the light (docs/hdr.md, "Float image files"): `dsr render` with float
// accumulation and no operator writes P-buffer 0's values past 1 into .exr and .tif, while its
// 8-bit files are the main frame buffer's as before: the same light, clamped and rounded.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.h"
#include "deferred/final_stage.h"
#include "platform/resources.h"
#include "scene/image.h"

namespace {

std::string read_all(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// data/default.scene with every light four times as bright, its textures read from data/.
std::string bright_default_scene() {
    const std::string data = dsr::resource_dir("data");
    std::istringstream in(read_all(data + "/default.scene"));
    std::string out, line;
    while (std::getline(in, line)) {
        for (size_t at = 0; (at = line.find("textures/", at)) != std::string::npos; at += data.size() + 10)
            line.replace(at, 9, data + "/textures/");
        if (line.rfind("light ", 0) == 0) {
            std::istringstream words(line.substr(0, line.find('#')));
            std::string w, text;
            while (words >> w) {
                text += (text.empty() ? "" : " ") + w;
                if (w != "color") continue;
                for (int c = 0; c < 3 && words >> w; ++c) {
                    char buf[32];
                    std::snprintf(buf, sizeof buf, "%g", 4 * std::stod(w));
                    text += std::string(" ") + buf;
                }
            }
            line = text;
        }
        out += line + "\n";
    }
    return out;
}

float max_rgb(const dsr::Image& img) {
    float m = 0;
    for (size_t i = 0; i < img.rgba.size(); ++i)
        if (i % 4 != 3) m = std::max(m, img.rgba[i]);
    return m;
}

}  // namespace

TEST(HdrOutput, FloatImageHoldsTheLight) {
    const std::string dir = dsr::test::temp_dir();
    {
        std::ofstream(dir + "/bright.scene") << bright_default_scene();
    }
    const std::string common = "render " + dir + "/bright.scene --size 128x128 --accum half --tonemap none -o " + dir;
    for (const char* file : {"/x.exr", "/x.tif", "/x.png", "/x.ppm"}) {
        const dsr::test::RunResult r = dsr::test::run(common + file);
        ASSERT_EQ(r.status, 0) << file << ": " << r.output;
    }
    const dsr::Image exr = dsr::load_image(dir + "/x.exr"), tif = dsr::load_image(dir + "/x.tif");
    const dsr::Image png = dsr::load_image(dir + "/x.png"), ppm = dsr::load_image(dir + "/x.ppm");
    EXPECT_GT(max_rgb(exr), 1.0f);
    EXPECT_GT(max_rgb(tif), 1.0f);
    EXPECT_EQ(max_rgb(png), 1.0f);
    // P-buffer 0 is half floats: the .exr (half) and the .tif (float) hold the same values.
    EXPECT_EQ(exr.rgba, tif.rgba);
    // The 8-bit files are the main frame buffer's, unchanged: the float values clamped and rounded.
    EXPECT_EQ(png.rgba, ppm.rgba);
    ASSERT_EQ(png.rgba.size(), exr.rgba.size());
    size_t differ = 0;
    for (size_t i = 0; i < png.rgba.size(); ++i)
        if (i % 4 != 3 && std::lround(png.rgba[i] * 255) != std::lround(std::clamp(exr.rgba[i], 0.0f, 1.0f) * 255)) ++differ;
    EXPECT_EQ(differ, 0u);
    // An operator maps the light into [0, 1]: no float values past it.
    const dsr::test::RunResult r = dsr::test::run("render " + dir + "/bright.scene --size 128x128 --accum half --tonemap aces -o " + dir + "/aces.exr");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_LE(max_rgb(dsr::load_image(dir + "/aces.exr")), 1.0f);
    // One stop of exposure doubles what the file holds.
    const dsr::test::RunResult e = dsr::test::run(common + "/e1.exr --exposure 1");
    ASSERT_EQ(e.status, 0) << e.output;
    EXPECT_EQ(max_rgb(dsr::load_image(dir + "/e1.exr")), 2 * max_rgb(exr));
    std::system(("rm -rf " + dir).c_str());
}

// The final pass's scaling, on the CPU for float files: texel centres onto pixel centres,
// clamped at the edges, the image itself at its own size.
TEST(HdrOutput, ResampleBilinear) {
    dsr::Image img;
    img.width = 2, img.height = 1;
    img.rgba = {0, 0, 0, 1, 4, 8, 2, 1};
    EXPECT_EQ(dsr::resample_bilinear(img, 2, 1).rgba, img.rgba);
    const dsr::Image wide = dsr::resample_bilinear(img, 4, 1);
    // Pixel centres 0.5 .. 3.5 of 4 land at texel coordinates -0.25, 0.25, 0.75, 1.25: clamped, 1/4, 3/4, clamped.
    EXPECT_FLOAT_EQ(wide.at(0, 0)[0], 0.0f);
    EXPECT_FLOAT_EQ(wide.at(1, 0)[0], 1.0f);
    EXPECT_FLOAT_EQ(wide.at(2, 0)[1], 6.0f);
    EXPECT_FLOAT_EQ(wide.at(3, 0)[2], 2.0f);
    EXPECT_FLOAT_EQ(wide.at(2, 0)[3], 1.0f);
    const dsr::Image one = dsr::resample_bilinear(img, 1, 1);
    EXPECT_FLOAT_EQ(one.at(0, 0)[0], 2.0f);
}
