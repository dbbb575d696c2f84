#include "analysis/large_mesh.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "dsr_error.h"

namespace dsr {

void write_grid_obj(const std::string& path, int n) {
    if (n < 1 || n > 4096) throw Error(path + ": grid size must be in [1, 4096], got " + std::to_string(n));
    const std::string tmp = path + ".part";  // nothing half-written under the real name
    {
        std::ofstream o(tmp);
        if (!o) throw Error(path + ": cannot write");
        o << "# " << n << "x" << n << " quad grid, " << 2LL * n * n << " triangles (dsr: src/analysis/large_mesh.cpp)\n";
        char buf[96];
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const double x = double(i) / n * 2 - 1, z = double(j) / n * 2 - 1;
                std::snprintf(buf, sizeof buf, "v %.6f %.6f %.6f\n", x, 0.1 * std::sin(9 * x) * std::cos(7 * z), z);
                o << buf;
            }
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                std::snprintf(buf, sizeof buf, "vt %.6f %.6f\n", double(i) / n, double(j) / n);
                o << buf;
            }
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                // counter-clockwise seen from +Y
                const int a = j * (n + 1) + i + 1, b = a + 1, c = b + n + 1, d = a + n + 1;
                std::snprintf(buf, sizeof buf, "f %d/%d %d/%d %d/%d %d/%d\n", a, a, d, d, c, c, b, b);
                o << buf;
            }
        if (!o.flush()) throw Error(path + ": write failed");
    }
    std::filesystem::rename(tmp, path);
}

std::string write_grid_scene(const std::string& dir, int n) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    const std::string stem = dir + "/grid_" + std::to_string(n);
    const std::string obj = stem + ".obj", scene = stem + ".scene";
    if (!std::filesystem::is_regular_file(obj, ec)) write_grid_obj(obj, n);
    std::ofstream s(scene);
    s << "# " << 2LL * n * n << " triangles in one material (src/analysis/large_mesh.cpp)\n"
      << "camera pos 0 2.2 2.2 target 0 0 0 up 0 1 0 fov 50 near 0.1 far 20\n"
         "ambient 0.1 0.1 0.1\n"
         "material m diffuse 0.8 0.8 0.8 specular 0.3 0.3 0.3 shininess 32\n"
         "mesh grid_" << n << ".obj material m\n"
         "light point pos 0 1 0 color 1 1 1 radius 3\n"
         "light point pos 0.8 0.5 0.6 color 0.3 0.5 1 radius 1.5\n";
    if (!s.flush()) throw Error(scene + ": write failed");
    return scene;
}

}  // namespace dsr
