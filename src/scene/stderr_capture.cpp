// stderr into memory while a decoder runs (stderr_capture.h).
#include "scene/stderr_capture.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>

#include "scene/user_file.h"

namespace dsr {

StderrCapture::StderrCapture() {
    std::fflush(stderr);
    mem_ = memfd_create("dsr-stderr", MFD_CLOEXEC);
    if (mem_ < 0) return;
    saved_ = dup(2);
    if (saved_ < 0 || dup2(mem_, 2) < 0) {
        if (saved_ >= 0) close(saved_);
        close(mem_);
        saved_ = mem_ = -1;
    }
}

StderrCapture::~StderrCapture() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    dup2(saved_, 2);
    close(saved_);
    close(mem_);
}

std::string StderrCapture::text() {
    if (mem_ < 0) return "";
    std::fflush(stderr);
    std::string all;
    char buf[4096];
    for (off_t at = 0;;) {
        const ssize_t n = pread(mem_, buf, sizeof buf, at);
        if (n <= 0 || all.size() > 4096) break;  // a few lines say it; the rest is repetition
        all.append(buf, size_t(n));
        at += n;
    }
    std::string joined;  // lines joined with "; "
    for (TextLines lines(all); ;) {
        std::string_view l;
        if (!lines.next(l)) break;
        const std::string t = one_line(l);
        if (!t.empty()) joined += (joined.empty() ? "" : "; ") + t;
    }
    return joined;
}

}  // namespace dsr
