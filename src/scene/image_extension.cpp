#include <cctype>
#include <string>

#include "scene/image.h"

namespace dsr {

std::string image_extension(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string ext = path.substr(dot);
    for (char& c : ext) c = char(std::tolower((unsigned char)c));
    return ext;
}

}  // namespace dsr
