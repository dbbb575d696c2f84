// Running the `dsr` binary from tests: build/dsr sits beside build/dsr_tests.
#pragma once
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace dsr::test {

struct RunResult {
    int status;
    std::string output;  // stdout and stderr together (stdout alone: run_stdout)
};

inline std::string dsr_binary() {
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    exe[n > 0 ? n : 0] = 0;
    std::string dir(exe);
    return dir.substr(0, dir.find_last_of('/')) + "/dsr";
}

// `env` (e.g. "GALLIUM_DRIVER=softpipe") is set for this command only. `stderr_to`: where the
// command's stderr goes ("&1": into output with stdout).
inline RunResult run(const std::string& args, const std::string& env = "", const std::string& stderr_to = "&1") {
    std::string cmd = (env.empty() ? "" : "env " + env + " ") + dsr_binary() + " " + args + " 2>" + stderr_to;
    RunResult r{-1, ""};
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf;
    size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.output.append(buf.data(), n);
    int st = pclose(p);
    r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    return r;
}

// What the command prints on stdout alone (its stderr discarded).
inline RunResult run_stdout(const std::string& args) { return run(args, "", "/dev/null"); }

inline bool exists(const std::string& p) {
    struct stat st;
    return stat(p.c_str(), &st) == 0;
}

inline std::string temp_dir() {
    char tmpl[] = "/tmp/dsr-test-XXXXXX";
    return mkdtemp(tmpl);
}

}  // namespace dsr::test
