// docs/architecture.md's layer table and docs/source_files.md's file table held against src/:
// every `#include "…"` under src/ goes to a folder its own folder's row allows, and every source
// file is listed with its job, and nothing listed is missing. Pure file reading, no GL.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path kRoot = fs::path(DSR_SOURCE_DIR);
const fs::path kSrc = kRoot / "src";

std::vector<std::string> read_lines(const fs::path& p) {
    std::ifstream in(p);
    EXPECT_TRUE(in) << "cannot read " << p;
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    return lines;
}

std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return "";
    return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

// The cells of a markdown table row ("| a | b |" -> {"a", "b"}); empty for any other line.
std::vector<std::string> cells(const std::string& line) {
    const std::string t = trim(line);
    if (t.size() < 2 || t.front() != '|' || t.back() != '|') return {};
    std::vector<std::string> out;
    std::string cur;
    for (size_t i = 1; i + 1 < t.size(); ++i) {
        if (t[i] == '\\' && i + 2 < t.size() && t[i + 1] == '|') {
            cur += '|';
            ++i;
        } else if (t[i] == '|') {
            out.push_back(trim(cur));
            cur.clear();
        } else {
            cur += t[i];
        }
    }
    out.push_back(trim(cur));
    return out;
}

// Every `code span` of a cell.
std::vector<std::string> code_spans(const std::string& cell) {
    std::vector<std::string> out;
    for (size_t a = cell.find('`'); a != std::string::npos; a = cell.find('`', a + 1)) {
        const size_t b = cell.find('`', a + 1);
        if (b == std::string::npos) break;
        out.push_back(cell.substr(a + 1, b - a - 1));
        a = b;
    }
    return out;
}

// A folder as the tables name it: "src/" for src itself, "src/NAME/" for a folder under it.
std::string folder_of(const fs::path& file) {
    const fs::path rel = fs::relative(file.parent_path(), kSrc);
    return rel == "." ? "src/" : "src/" + rel.generic_string() + "/";
}

std::vector<fs::path> source_files() {
    std::vector<fs::path> out;
    for (const auto& e : fs::recursive_directory_iterator(kSrc)) {
        const std::string ext = e.path().extension().string();
        if (e.is_regular_file() && (ext == ".h" || ext == ".cpp")) out.push_back(e.path());
    }
    return out;
}

// docs/architecture.md, section "Layers": folder -> the folders it may include.
std::map<std::string, std::set<std::string>> layer_table() {
    std::map<std::string, std::set<std::string>> allowed;
    bool in_section = false;
    for (const std::string& line : read_lines(kRoot / "docs" / "architecture.md")) {
        if (line.rfind("## ", 0) == 0) in_section = line == "## Layers";
        if (!in_section) continue;
        const std::vector<std::string> c = cells(line);
        if (c.size() < 2) continue;
        const std::vector<std::string> self = code_spans(c[0]);
        if (self.size() != 1 || self[0].rfind("src/", 0) != 0) continue;  // the header and rule rows
        std::set<std::string>& may = allowed[self[0]];
        for (const std::string& f : code_spans(c[1])) may.insert(f);
    }
    return allowed;
}

// The folder an include line names, or "" where it names no file under src/.
std::string included_folder(const fs::path& from, const std::string& name) {
    for (const fs::path& base : {from.parent_path(), kSrc}) {
        const fs::path p = (base / name).lexically_normal();
        if (fs::is_regular_file(p)) return folder_of(p);
    }
    return "";
}

}  // namespace

TEST(Architecture, EveryIncludeGoesWhereTheLayerTableAllows) {
    const std::map<std::string, std::set<std::string>> allowed = layer_table();
    ASSERT_FALSE(allowed.empty()) << "docs/architecture.md has no \"## Layers\" table of `src/…/` rows";
    std::string failures;
    std::set<std::string> folders;
    size_t includes = 0;
    for (const fs::path& file : source_files()) {
        const std::string from = folder_of(file);
        folders.insert(from);
        const std::string rel = fs::relative(file, kRoot).generic_string();
        int n = 0;
        for (const std::string& line : read_lines(file)) {
            ++n;
            const std::string t = trim(line);
            if (t.rfind("#include", 0) != 0) continue;  // include lines only, never a comment that quotes one
            const size_t a = t.find('"');
            if (a == std::string::npos) continue;  // <system> headers
            const size_t b = t.find('"', a + 1);
            const std::string name = t.substr(a + 1, b - a - 1);
            ++includes;
            const std::string to = included_folder(file, name);
            if (to.empty()) {
                failures += "  " + rel + ":" + std::to_string(n) + ": #include \"" + name + "\" names no file under src/\n";
                continue;
            }
            if (to == from) continue;
            const auto row = allowed.find(from);
            if (row == allowed.end() || !row->second.count(to))
                failures += "  " + rel + ":" + std::to_string(n) + ": #include \"" + name + "\": " + from + " may not include " +
                            to + "\n";
        }
    }
    for (const std::string& f : folders)
        if (!allowed.count(f)) failures += "  " + f + " has no row in docs/architecture.md's layer table\n";
    EXPECT_GT(includes, 100u) << "the include lines were not found";
    EXPECT_TRUE(failures.empty()) << "includes against docs/architecture.md, \"Layers\":\n" << failures;
}

TEST(Architecture, TheFileTableListsEverySourceFileAndNothingElse) {
    // docs/source_files.md: under each "### `src/…/`" heading, rows whose first cell names files in
    // code spans (`name.h/.cpp` for both) and whose second says the file's job.
    std::set<std::string> listed;
    std::string failures;
    std::string folder;
    for (const std::string& line : read_lines(kRoot / "docs" / "source_files.md")) {
        if (line.rfind("### ", 0) == 0) {
            const std::vector<std::string> f = code_spans(line);
            folder = f.size() == 1 ? f[0] : "";
            continue;
        }
        const std::vector<std::string> c = cells(line);
        if (folder.empty() || c.size() < 2) continue;
        for (const std::string& name : code_spans(c[0])) {
            std::vector<std::string> names;
            const size_t both = name.find(".h/.cpp");
            if (both != std::string::npos && both + 7 == name.size()) {
                names.push_back(name.substr(0, both) + ".h");
                names.push_back(name.substr(0, both) + ".cpp");
            } else {
                names.push_back(name);
            }
            for (const std::string& n : names) {
                listed.insert(folder + n);
                if (c[1].empty()) failures += "  " + folder + n + ": no job given\n";
            }
        }
    }
    ASSERT_FALSE(listed.empty()) << "docs/source_files.md has no file table";
    std::set<std::string> present;
    for (const fs::path& file : source_files()) present.insert(fs::relative(file, kRoot).generic_string());
    for (const std::string& f : present)
        if (!listed.count(f)) failures += "  " + f + " is not in docs/source_files.md\n";
    for (const std::string& f : listed)
        if (!present.count(f)) failures += "  " + f + " is listed in docs/source_files.md but does not exist\n";
    EXPECT_TRUE(failures.empty()) << "docs/source_files.md against src/:\n" << failures;
}
