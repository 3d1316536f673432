// Incremental 64-bit FNV-1a over the raw bytes of simulation state. Floats are hashed by
// bit pattern (with -0 folded into +0), so any divergence, however small, changes the hash.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace obscura {

class StateHasher {
public:
    void addBytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            h_ ^= p[i];
            h_ *= 1099511628211ULL;  // FNV-1a 64-bit prime
        }
    }
    void add(std::uint64_t v) { addBytes(&v, sizeof v); }
    void add(std::uint32_t v) { addBytes(&v, sizeof v); }
    void add(std::int32_t v) { addBytes(&v, sizeof v); }
    void add(bool v) { add(static_cast<std::uint32_t>(v)); }
    void add(float v) {
        if (v == 0.0f) v = 0.0f;
        std::uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        add(bits);
    }
    void add(double v) {
        if (v == 0.0) v = 0.0;
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        add(bits);
    }
    void add(std::string_view s) {
        add(static_cast<std::uint64_t>(s.size()));
        addBytes(s.data(), s.size());
    }

    std::uint64_t value() const { return h_; }
    std::string hex() const { return toHex(h_); }

    static std::string toHex(std::uint64_t v) {
        static const char* digits = "0123456789abcdef";
        std::string s(16, '0');
        for (int i = 15; i >= 0; --i, v >>= 4) s[static_cast<std::size_t>(i)] = digits[v & 15u];
        return s;
    }

private:
    std::uint64_t h_ = 14695981039346656037ULL;  // FNV-1a 64-bit offset basis
};

}  // namespace obscura
