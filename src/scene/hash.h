// Deterministic integer hashing for generated content (textures, bench lights): the same
// bits on every machine, unlike std::random distributions.
#pragma once
#include <cstdint>

namespace dsr {

// Chris Wellons' lowbias32: a well-mixed 32-bit integer hash.
inline uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

}  // namespace dsr
