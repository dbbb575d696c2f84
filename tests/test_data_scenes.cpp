// Every scene shipped in data/ loads without a warning and renders: no GL error (checked after every
// stage), and an image that is not black. A scene added to data/ is covered without naming it here.
#include <gtest/gtest.h>

#include <dirent.h>

#include <algorithm>
#include <string>
#include <vector>

#include "gl/check.h"
#include "render_fixture.h"

using namespace dsr;
using namespace dsr::test;

namespace {

std::vector<std::string> data_scenes() {
    std::vector<std::string> out;
    const std::string dir = resource_dir("data");
    if (DIR* d = opendir(dir.c_str())) {
        while (const dirent* e = readdir(d)) {
            const std::string name = e->d_name;
            if (name.size() > 6 && name.compare(name.size() - 6, 6, ".scene") == 0) out.push_back(dir + "/" + name);
        }
        closedir(d);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST(DataScenes, EachLoadsAndRenders) {
    const std::vector<std::string> scenes = data_scenes();
    EXPECT_GE(scenes.size(), 7u);  // default, lights, mesh, metal_rough, physical_lights, shadow, transparency
    const bool was = debug_gl();
    set_debug_gl(true);
    for (const std::string& path : scenes) {
        SCOPED_TRACE(path);
        const Scene s = load_scene(path);
        EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
        RenderResult r;
        ASSERT_NO_THROW(r = render_scene(s, 96, 96, ShaderOptions{}));
        double brightest = 0;
        long lit = 0;
        for (size_t i = 0; i < r.image.rgba.size(); i += 4) {
            const double v = std::max({r.image.rgba[i], r.image.rgba[i + 1], r.image.rgba[i + 2]});
            brightest = std::max(brightest, v);
            lit += v > 0.1;
        }
        std::printf("[ scene    ] %s: brightest %.3f, %ld of %d pixels above 0.1\n", path.c_str(), brightest, lit, 96 * 96);
        EXPECT_GT(lit, 96 * 96 / 20);
    }
    set_debug_gl(was);
}
