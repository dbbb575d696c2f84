// `dsr compare A B`: two image files compared as the tests compare images (compare_images, RGB,
// in 8-bit LSB): one line on stdout. tests/legacy_matrix.sh uses it, so the matrix needs no other
// image tool. Exit 1 when the files cannot be read or differ in size, or when --max-lsb is given
// and exceeded.
#include <cstdio>

#include "analysis/image_metrics.h"
#include "app/args.h"
#include "app/command_table.h"
#include "app/commands.h"
#include "scene/image.h"

namespace dsr {

int cmd_compare(const std::vector<std::string>& argv) {
    CompareSettings flags;  // the compare command's table (app/command_table.h)
    parse_command_line(compare_command(flags), argv);
    const std::vector<std::string>& files = flags.files;
    const double threshold_lsb = flags.threshold_lsb, max_lsb = flags.max_lsb;
    if (files.size() != 2) fail_command("compare", "expected two image files, got " + std::to_string(files.size()));
    const Image a = load_image(files[0]), b = load_image(files[1]);  // regular files only (scene/image.h)
    if (a.width != b.width || a.height != b.height)
        fail_command("compare", "sizes differ: " + files[0] + " is " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                  ", " + files[1] + " is " + std::to_string(b.width) + "x" + std::to_string(b.height));
    const ImageDiff d = compare_images(a, b, threshold_lsb / 255.0);
    std::printf("max_lsb %.2f mean_lsb %.6f over_threshold %lld pixels %lld threshold_lsb %.2f\n", d.max_lsb(),
                d.mean_lsb(), d.failing, d.pixels, threshold_lsb);
    if (max_lsb >= 0 && d.max_lsb() > max_lsb) {
        std::fprintf(stderr, "dsr compare: max %.2f LSB is over --max-lsb %.2f\n", d.max_lsb(), max_lsb);
        return 1;
    }
    return 0;
}

}  // namespace dsr
