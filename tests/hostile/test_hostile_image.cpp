// Hostile image files: `dsr compare`'s inputs and a scene's textures. Not a file, cut short,
// damaged, or claiming a size no decoder should allocate: one line each, whatever the format,
// with what the decoder libraries print caught into it.
#include <string>
#include <vector>

#include "hostile.h"

namespace dsr::hostile {
namespace {

using D = const std::string&;

// `dsr compare bad ok.png` with `bad` made by setup.
Case compare_case(const std::string& name, std::function<void(D)> setup, const std::string& bad, const std::string& expect) {
    return {name,
            [setup](D d) {
                image(d, "ok.png", 64, 64);
                setup(d);
            },
            "compare " + bad + " ok.png", expect};
}

// A scene whose material maps `file`, made by setup.
Case texture_case(const std::string& name, std::function<void(D)> setup, const std::string& file, const std::string& expect) {
    return {name,
            [setup, file](D d) {
                write(d, "a.scene", scene_text("", " diffuse_map " + file));
                setup(d);
            },
            "render a.scene --size 16x16 -o out.png",
            "a.scene:2: expected a readable image for diffuse_map, got '" + file + "': " + expect};
}

std::vector<Case> cases() {
    std::vector<Case> c;
    // ---- compare: not a file
    c.push_back(compare_case("compare_fifo", [](D d) { fifo(d, "f.png"); }, "f.png", "cannot open image f.png: expected a regular file, got a FIFO"));
    c.push_back(compare_case("compare_directory", [](D d) { folder(d, "f.png"); }, "f.png", "cannot open image f.png: expected a file, got a directory"));
    c.push_back(compare_case("compare_dev_zero", [](D) {}, "/dev/zero", "cannot open image /dev/zero: expected a regular file, got a character device"));
    c.push_back(compare_case("compare_missing", [](D) {}, "none.png", "cannot open image none.png: No such file or directory"));
    c.push_back(compare_case("compare_symlink_loop", [](D d) { symlink_to(d, "f.png", "f.png"); }, "f.png", "cannot open image f.png: Too many levels of symbolic links"));
    c.push_back(compare_case("compare_empty_file", [](D d) { write(d, "f.png", ""); }, "f.png", "cannot read image f.png:"));
    c.push_back(compare_case("compare_text_as_png", [](D d) { write(d, "f.png", "not an image\n"); }, "f.png", "cannot read image f.png:"));
    c.push_back(compare_case("compare_oversize", [](D d) { sparse(d, "f.png", (2ll << 30) + 1); }, "f.png", "cannot open image f.png: expected at most 2147483648 bytes"));
    // ---- compare: cut short, each format dsr writes
    for (const char* ext : {"png", "jpg", "tif", "exr", "ppm"}) {
        const std::string e = ext;
        c.push_back(compare_case("compare_truncated_" + e, [e](D d) { image(d, "full." + e, 64, 64); truncated(d, "t." + e, "full." + e, -1000); },
                                 "t." + e, "cannot read image t." + e + ":"));
        c.push_back(compare_case("compare_header_only_" + e, [e](D d) { image(d, "full." + e, 64, 64); truncated(d, "t." + e, "full." + e, 40); },
                                 "t." + e, "cannot read image t." + e + ":"));
    }
    // ---- compare: damaged in the compressed data or the header
    c.push_back(compare_case("compare_damaged_png_data", [](D d) { image(d, "full.png", 64, 64); damaged(d, "t.png", "full.png", 200, "XXXXXXXX"); }, "t.png", "cannot read image t.png: "));
    c.push_back(compare_case("compare_damaged_png_crc", [](D d) { image(d, "full.png", 64, 64); damaged(d, "t.png", "full.png", 29, "\xff"); }, "t.png", "cannot read image t.png: "));
    c.push_back(compare_case("compare_damaged_jpeg_marker", [](D d) { image(d, "full.jpg", 64, 64); damaged(d, "t.jpg", "full.jpg", 1000, "\xff\xd9"); }, "t.jpg", "cannot read image t.jpg: JPEG error: Corrupt JPEG data: premature end of data segment"));
    c.push_back(compare_case("compare_damaged_exr", [](D d) { image(d, "full.exr", 64, 64); damaged(d, "t.exr", "full.exr", 400, std::string(64, '\xff')); }, "t.exr", "cannot read image t.exr: "));
    c.push_back(compare_case("compare_header_absurd", [](D d) { header_only_png(d, "t.png", 1u << 20, 1u << 20); }, "t.png", "cannot read image t.png: PNG read error: Invalid IHDR data"));
    c.push_back(compare_case("compare_ppm_absurd", [](D d) { write(d, "t.ppm", "P6\n99999 99999\n255\n"); }, "t.ppm", "cannot read image t.ppm: 99999 x 99999 pixels"));
    // ---- textures of a scene file
    c.push_back(texture_case("texture_fifo", [](D d) { fifo(d, "t.png"); }, "t.png", "cannot open image t.png: expected a regular file, got a FIFO"));
    c.push_back(texture_case("texture_directory", [](D d) { folder(d, "t.png"); }, "t.png", "cannot open image t.png: expected a file, got a directory"));
    c.push_back(texture_case("texture_dev_urandom", [](D) {}, "/dev/urandom", "cannot open image /dev/urandom: expected a regular file, got a character device"));
    c.push_back(texture_case("texture_truncated_jpeg", [](D d) { image(d, "full.jpg", 64, 64); truncated(d, "t.jpg", "full.jpg", 700); }, "t.jpg", "cannot read image t.jpg: JPEG error: Premature end of JPEG file"));
    c.push_back(texture_case("texture_truncated_png", [](D d) { image(d, "full.png", 64, 64); truncated(d, "t.png", "full.png", -100); }, "t.png", "cannot read image t.png: "));
    c.push_back(texture_case("texture_truncated_tif", [](D d) { image(d, "full.tif", 64, 64); truncated(d, "t.tif", "full.tif", -2000); }, "t.tif", "cannot read image t.tif: "));
    c.push_back(texture_case("texture_truncated_exr", [](D d) { image(d, "full.exr", 64, 64); truncated(d, "t.exr", "full.exr", -500); }, "t.exr", "cannot read image t.exr: "));
    c.push_back(texture_case("texture_damaged_png", [](D d) { image(d, "full.png", 64, 64); damaged(d, "t.png", "full.png", 200, "XXXXXXXX"); }, "t.png", "cannot read image t.png: "));
    c.push_back(texture_case("texture_not_an_image", [](D d) { write(d, "t.png", "camera pos 0 0 0\n"); }, "t.png", "cannot read image t.png: "));
    return c;
}

INSTANTIATE_TEST_SUITE_P(Image, Hostile, ::testing::ValuesIn(cases()), CaseName());

}  // namespace
}  // namespace dsr::hostile
