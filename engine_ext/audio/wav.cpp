#include "audio/wav.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace obscura::audio {
namespace {

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>((v >> (8 * i)) & 0xffu));
}
void put16(std::vector<std::uint8_t>& out, std::uint16_t v) {
    out.push_back(static_cast<std::uint8_t>(v & 0xffu));
    out.push_back(static_cast<std::uint8_t>(v >> 8));
}
void putTag(std::vector<std::uint8_t>& out, const char* tag) { out.insert(out.end(), tag, tag + 4); }

std::uint32_t get32(const std::uint8_t* p) {
    return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
           (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}
std::uint16_t get16(const std::uint8_t* p) {
    return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}

[[noreturn]] void fail(const std::string& name, const std::string& problem) {
    throw std::runtime_error(name + ": " + problem);
}

}  // namespace

std::vector<std::uint8_t> encodeWav(const WavData& wav) {
    if (wav.channels < 1 || wav.channels > 2) throw std::invalid_argument("encodeWav: channels must be 1 or 2");
    if (wav.sampleRate <= 0) throw std::invalid_argument("encodeWav: sample rate must be positive");
    const auto dataBytes = static_cast<std::uint32_t>(wav.samples.size() * 2);
    std::vector<std::uint8_t> out;
    out.reserve(44 + dataBytes);
    putTag(out, "RIFF");
    put32(out, 36 + dataBytes);
    putTag(out, "WAVE");
    putTag(out, "fmt ");
    put32(out, 16);
    put16(out, 1);  // PCM
    put16(out, static_cast<std::uint16_t>(wav.channels));
    put32(out, static_cast<std::uint32_t>(wav.sampleRate));
    put32(out, static_cast<std::uint32_t>(wav.sampleRate * wav.channels * 2));  // byte rate
    put16(out, static_cast<std::uint16_t>(wav.channels * 2));                  // block align
    put16(out, 16);
    putTag(out, "data");
    put32(out, dataBytes);
    for (std::int16_t s : wav.samples) put16(out, static_cast<std::uint16_t>(s));
    return out;
}

WavData decodeWav(const std::vector<std::uint8_t>& bytes, const std::string& name) {
    if (bytes.size() < 12) fail(name, "truncated header (" + std::to_string(bytes.size()) + " bytes, need at least 12)");
    if (std::memcmp(bytes.data(), "RIFF", 4) != 0) fail(name, "not a RIFF file");
    if (std::memcmp(bytes.data() + 8, "WAVE", 4) != 0) fail(name, "RIFF file is not WAVE");

    bool haveFmt = false;
    int channels = 0, rate = 0, bits = 0;
    std::size_t pos = 12;
    while (pos + 8 <= bytes.size()) {
        const std::uint8_t* chunk = bytes.data() + pos;
        const std::uint32_t size = get32(chunk + 4);
        const std::size_t body = pos + 8;
        if (std::memcmp(chunk, "fmt ", 4) == 0) {
            if (size < 16 || body + 16 > bytes.size()) fail(name, "truncated header (fmt chunk)");
            const std::uint16_t format = get16(chunk + 8);
            channels = get16(chunk + 10);
            rate = static_cast<int>(get32(chunk + 12));
            bits = get16(chunk + 22);
            std::uint16_t effective = format;
            if (format == 0xFFFE && size >= 40 && body + 40 <= bytes.size())
                effective = get16(chunk + 8 + 24);  // WAVE_FORMAT_EXTENSIBLE: sub-format GUID's first word
            if (effective != 1)
                fail(name, "unsupported format tag " + std::to_string(format) + " (only integer PCM is supported)");
            if (channels < 1 || channels > 2)
                fail(name, "unsupported channel count " + std::to_string(channels) + " (mono or stereo only)");
            if (bits != 8 && bits != 16)
                fail(name, "unsupported bit depth " + std::to_string(bits) + " (8 or 16 bits only)");
            if (rate <= 0 || rate > 384000) fail(name, "bad sample rate " + std::to_string(rate));
            haveFmt = true;
        } else if (std::memcmp(chunk, "data", 4) == 0) {
            if (!haveFmt) fail(name, "data chunk before fmt chunk");
            if (body + size > bytes.size())
                fail(name, "truncated data (header says " + std::to_string(size) + " bytes, file has " +
                               std::to_string(bytes.size() - body) + ")");
            const int bytesPerSample = bits / 8;
            if (size % static_cast<std::uint32_t>(bytesPerSample * channels) != 0)
                fail(name, "data size " + std::to_string(size) + " is not a whole number of frames");
            WavData wav;
            wav.sampleRate = rate;
            wav.channels = channels;
            const std::size_t count = size / static_cast<std::uint32_t>(bytesPerSample);
            wav.samples.resize(count);
            const std::uint8_t* p = bytes.data() + body;
            for (std::size_t i = 0; i < count; ++i) {
                if (bits == 16)
                    wav.samples[i] = static_cast<std::int16_t>(get16(p + 2 * i));
                else
                    wav.samples[i] = static_cast<std::int16_t>((static_cast<int>(p[i]) - 128) * 256);
            }
            return wav;
        }
        pos = body + size + (size & 1u);  // chunks are word aligned
    }
    if (!haveFmt) fail(name, "truncated header (no fmt chunk)");
    fail(name, "no data chunk");
}

void writeWav(const std::string& path, const WavData& wav) {
    const std::vector<std::uint8_t> bytes = encodeWav(wav);
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    if (!f) fail(path, "cannot open for writing");
    f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!f) fail(path, "write failed");
}

WavData readWav(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) fail(path, "cannot open");
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    return decodeWav(bytes, path);
}

}  // namespace obscura::audio
