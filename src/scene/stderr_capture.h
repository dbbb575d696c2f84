// Image decoders (libpng, libjpeg, libtiff through OpenImageIO) print their warnings and
// errors on stderr themselves, several lines for one damaged file. StderrCapture sends file
// descriptor 2 to a memory file while a decoder runs, so what they said can go into dsr's one
// error line instead (or be dropped when the read succeeds).
#pragma once
#include <string>

namespace dsr {

class StderrCapture {
public:
    StderrCapture();   // from here on, stderr goes to memory (unchanged if that cannot be set up)
    ~StderrCapture();  // stderr restored
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;
    // Everything written to stderr since the constructor, as one line ("" for nothing).
    std::string text();

private:
    int saved_ = -1, mem_ = -1;
};

}  // namespace dsr
