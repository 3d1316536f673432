// Hand-made .mesh bytes: the formats OGRE 1.12 can read but no longer write (v1.20, v1.10), and
// files with exactly the defect a test wants.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace obscura::mesh::testing {

class ChunkWriter {
public:
    explicit ChunkWriter(bool bigEndian = false) : big_(bigEndian) {}

    void u16(std::uint16_t v) { bytes(&v, 2); }
    void u32(std::uint32_t v) { bytes(&v, 4); }
    void f32(float v) { bytes(&v, 4); }
    void boolean(bool v) { data.push_back(v ? 1 : 0); }
    void str(const std::string& s) {
        data.insert(data.end(), s.begin(), s.end());
        data.push_back('\n');
    }
    void header(const std::string& version) {
        u16(0x1000);
        str(version);
    }
    // Opens a chunk; `end` patches its length (header included) unless `length` overrides it.
    std::size_t begin(std::uint16_t id) {
        const std::size_t at = data.size();
        u16(id);
        u32(0);
        return at;
    }
    void end(std::size_t at) { patch32(at + 2, static_cast<std::uint32_t>(data.size() - at)); }
    void patch32(std::size_t at, std::uint32_t v) {
        std::vector<std::uint8_t> keep;
        keep.swap(data);
        u32(v);
        std::memcpy(keep.data() + at, data.data(), 4);
        data.swap(keep);
    }

    std::vector<std::uint8_t> data;

private:
    // Values are laid out little-endian (the test machines are), swapped for big-endian files.
    void bytes(const void* p, std::size_t n) {
        const auto* b = static_cast<const std::uint8_t*>(p);
        if (big_)
            for (std::size_t i = n; i-- > 0;) data.push_back(b[i]);
        else
            data.insert(data.end(), b, b + n);
    }
    bool big_;
};

}  // namespace obscura::mesh::testing
