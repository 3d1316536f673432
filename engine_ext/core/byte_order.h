// Byte order for the binary files the core reads and writes (PFM, the smoke dump): the host's,
// and a float's four bytes reversed.
#pragma once

#include <cstdint>
#include <cstring>
#include <utility>

namespace obscura {

inline bool hostLittleEndian() {
    const std::uint32_t one = 1;
    unsigned char b[4];
    std::memcpy(b, &one, 4);
    return b[0] == 1;
}

inline float byteSwapped(float f) {
    unsigned char b[4];
    std::memcpy(b, &f, 4);
    std::swap(b[0], b[3]);
    std::swap(b[1], b[2]);
    std::memcpy(&f, b, 4);
    return f;
}

}  // namespace obscura
