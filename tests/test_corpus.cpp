// Files nobody here wrote: every OBJ, glTF and GLB file of Debian's assimp-testmodels (assimp's own
// test corpus, installed by `make deps`), read as `dsr render FILE` reads a model and drawn at a
// small size, each outcome held against the table in docs/models.md:
//   renders, with the share of the image the model covers (the G-buffer's normal target outside
//   the ground dsr adds) and how many warnings its reader gave;
//   refused, with the one line dsr prints.
// The table is what a user reads to know which of those files dsr draws; when an outcome changes,
// the test fails and writes the table it saw to build/test-output/models_table.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "deferred/deferred_shader.h"
#include "dsr_error.h"
#include "gl/caps.h"
#include "gl/readback.h"
#include "platform/context.h"
#include "platform/resources.h"
#include "render_fixture.h"
#include "scene/framing.h"
#include "scene/scene.h"
#include "scene/stderr_capture.h"

namespace fs = std::filesystem;

namespace {

const std::string kCorpus = "/usr/share/assimp/models";
constexpr int kSize = 64;

struct Outcome {
    bool renders = false;
    int covered_pct = 0;  // renders: percent of the image the model covers
    size_t warnings = 0;  // renders: the reader's warnings
    std::string why;      // refused: the line, the corpus folder left out of the path
};

// Every OBJ, glTF and GLB file of the corpus, relative to it, sorted.
std::vector<std::string> corpus_files() {
    std::vector<std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(kCorpus)) {
        if (!e.is_regular_file()) continue;
        std::string ext = e.path().extension().string();
        for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
        if (ext == ".obj" || ext == ".gltf" || ext == ".glb") out.push_back(fs::relative(e.path(), kCorpus).string());
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string without_corpus_dir(std::string s) {
    const std::string dir = kCorpus + "/";
    for (size_t p; (p = s.find(dir)) != std::string::npos;) s.erase(p, dir.size());
    return s;
}

// The share of pixels whose G-buffer normal is not the "no surface" grey, the ground left out.
int covered_percent(const dsr::Scene& loaded) {
    dsr::Scene s = loaded;
    for (size_t i = 0; i < s.objects.size();) {
        const dsr::Object& o = s.objects[i];
        if (s.materials.at(size_t(o.material)).name == dsr::kGroundMaterial) s.objects.erase(s.objects.begin() + long(i));
        else ++i;
    }
    auto ctx = dsr::create_context(dsr::ContextDesc{"osmesa", kSize, kSize});
    dsr::Caps caps = dsr::probe_caps({});
    dsr::DeferredShader ds(caps, kSize, kSize, dsr::ShaderOptions{}, dsr::resource_dir("glsl120"));
    ds.set_scene(s);
    ds.render(s, kSize, kSize);
    ds.draw_view(dsr::View::normal, s.camera, kSize, kSize);
    const dsr::Image img = dsr::read_pixels(kSize, kSize);
    int covered = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const float* p = img.at(x, y);
            bool grey = true;
            for (int c = 0; c < 3; ++c) grey = grey && std::fabs(p[c] * 255.0f - 128.0f) <= 1.0f;
            covered += !grey;
        }
    return int(std::lround(100.0 * covered / (kSize * kSize)));
}

Outcome outcome_of(const std::string& rel) {
    Outcome o;
    dsr::Scene s;
    try {
        const dsr::StderrCapture quiet;  // the warnings are counted, not printed
        s = dsr::load_scene(kCorpus + "/" + rel);
    } catch (const dsr::Error& e) {
        o.why = without_corpus_dir(e.what());
        return o;
    }
    o.renders = true;
    o.warnings = s.warnings.size();
    o.covered_pct = covered_percent(s);
    return o;
}

std::string table_row(const std::string& rel, const Outcome& o) {
    if (o.renders)
        return "| `" + rel + "` | renders | " + std::to_string(o.covered_pct) + "% | " + std::to_string(o.warnings) + " |";
    std::string why = o.why;
    for (char& c : why)
        if (c == '|') c = '/';
    return "| `" + rel + "` | refused: " + why + " | | |";
}

// docs/models.md's rows "| `KEY` ... |", keyed by KEY: the summary's (one a folder, before the
// table) or the table's (one a file).
std::map<std::string, std::string> documented_rows(bool table) {
    std::ifstream in(std::string(DSR_SOURCE_DIR) + "/docs/models.md");
    std::map<std::string, std::string> rows;
    std::string line;
    bool in_table = false;
    while (std::getline(in, line)) {
        if (line.rfind("## The table", 0) == 0) in_table = true;
        if (line.rfind("| `", 0) != 0 || in_table != table) continue;
        const size_t end = line.find('`', 3);
        if (end != std::string::npos) rows[line.substr(3, end - 3)] = line;
    }
    return rows;
}

}  // namespace

// Each file's outcome as docs/models.md tables it; a file in neither place fails too.
TEST(Corpus, EveryFileAsDocsTableIt) {
    if (!fs::is_directory(kCorpus)) GTEST_SKIP() << "skipped: " << kCorpus << " is absent (make deps installs assimp-testmodels)";
    const std::vector<std::string> files = corpus_files();
    ASSERT_GE(files.size(), 70u) << "the corpus holds 25 OBJ and 53 glTF files";
    const std::map<std::string, std::string> documented = documented_rows(true);
    std::string table, mismatches;
    int renders = 0;
    std::map<std::string, std::pair<int, int>> by_folder;  // files, renders
    for (const std::string& rel : files) {
        const Outcome o = outcome_of(rel);
        renders += o.renders;
        auto& f = by_folder[rel.substr(0, rel.find('/') + 1)];
        ++f.first;
        f.second += o.renders;
        const std::string row = table_row(rel, o);
        table += row + "\n";
        auto it = documented.find(rel);
        if (it == documented.end()) mismatches += "  not in docs/models.md: " + row + "\n";
        else if (it->second != row) mismatches += "  docs: " + it->second + "\n  now:  " + row + "\n";
    }
    for (const auto& [rel, row] : documented)
        if (std::find(files.begin(), files.end(), rel) == files.end()) mismatches += "  no such file: " + row + "\n";
    // The summary: each folder's files, renders and refusals as counted here.
    for (const auto& [folder, row] : documented_rows(false)) {
        const auto it = by_folder.find(folder);
        const int n = it == by_folder.end() ? 0 : it->second.first, r = it == by_folder.end() ? 0 : it->second.second;
        const std::string counts = " | " + std::to_string(n) + " | " + std::to_string(r) + " | " + std::to_string(n - r) + " |";
        if (row.size() < counts.size() || row.compare(row.size() - counts.size(), counts.size(), counts) != 0)
            mismatches += "  summary: " + row + "\n  counted:" + counts + "\n";
    }
    EXPECT_EQ(documented_rows(false).size(), by_folder.size()) << "one summary row a folder";
    const std::string out = dsr::test::test_output_dir() + "/models_table.md";
    std::ofstream(out) << table;
    EXPECT_TRUE(mismatches.empty()) << "outcomes differ from docs/models.md (the table seen is in " << out << "):\n"
                                    << mismatches;
    std::printf("corpus: %d of %zu files render\n", renders, files.size());
}
