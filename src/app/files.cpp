#include "app/files.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "dsr_error.h"

namespace dsr {

void write_file_atomic(const std::string& path, const std::string& contents) {
    std::string tmp = path + ".tmp-" + std::to_string(getpid());
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw Error("cannot write " + path + ": " + std::strerror(errno));
        out << contents;
        out.flush();
        if (!out) {
            std::remove(tmp.c_str());
            throw Error("cannot write " + path + ": write failed");
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        int e = errno;
        std::remove(tmp.c_str());
        throw Error("cannot write " + path + ": " + std::strerror(e));
    }
}

}  // namespace dsr
