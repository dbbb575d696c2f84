#include "platform/resources.h"

#include <sys/stat.h>
#include <unistd.h>

#include <climits>

#include "dsr_error.h"

#ifndef DSR_SOURCE_DIR
#define DSR_SOURCE_DIR "."
#endif

namespace dsr {

static bool is_dir(const std::string& p) {
    struct stat st;
    return stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

std::string resource_dir(const std::string& name) {
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
        exe[n] = 0;
        std::string dir(exe);
        dir = dir.substr(0, dir.find_last_of('/'));           // build/
        std::string cand = dir.substr(0, dir.find_last_of('/')) + "/" + name;  // repo/name
        if (is_dir(cand)) return cand;
    }
    std::string src = std::string(DSR_SOURCE_DIR) + "/" + name;
    if (is_dir(src)) return src;
    throw Error("cannot find dsr's " + name + "/ folder (looked beside the executable and in " DSR_SOURCE_DIR ")");
}

}  // namespace dsr
