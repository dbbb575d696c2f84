// tinyobjloader's implementation, compiled from Debian's header into the fuzzers only, so that
// libFuzzer sees its coverage and the sanitizers check it (the normal build links Debian's
// libtinyobjloader.so, built from the same header).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
