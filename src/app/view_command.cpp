// `dsr view`: runs dsr_view, the viewer's own executable beside this one (it links the system
// libGL through GLFW; dsr links libOSMesa, and never both in one executable).
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <string>
#include <vector>

#include "app/commands.h"
#include "dsr_error.h"

namespace dsr {

int cmd_view(const std::vector<std::string>& args) {
    char exe[PATH_MAX];
    const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    exe[n > 0 ? n : 0] = 0;
    std::string dir(exe);
    const std::string viewer = dir.substr(0, dir.find_last_of('/')) + "/dsr_view";
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(viewer.c_str()));
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(viewer.c_str(), argv.data());
    throw Error("dsr view: cannot run " + viewer + " (" + std::strerror(errno) + "; `make run` builds it)");
}

}  // namespace dsr
