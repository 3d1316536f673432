// See input_file.h.
#include "map/input_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sys/stat.h>

namespace obscura {

namespace {
std::string bytes(std::size_t n) {
    if (n >= (1u << 20) && n % (1u << 20) == 0) return std::to_string(n >> 20) + " MiB";
    return std::to_string(n) + " bytes";
}
}  // namespace

bool readInputFile(const std::string& path, std::size_t maxBytes, const char* what, std::string& text, std::string& error) {
    const std::string shown = errorText(path, 200);
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        error = shown + ": cannot open " + what + " (" + std::strerror(errno) + ")";
        return false;
    }
    if (S_ISDIR(st.st_mode)) {
        error = shown + ": is a directory, expected a " + what;
        return false;
    }
    if (!S_ISREG(st.st_mode)) {
        const char* kind = S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device" : S_ISFIFO(st.st_mode) ? "a pipe" : "not a regular file";
        error = shown + ": is " + kind + ", expected a " + what;
        return false;
    }
    if (static_cast<unsigned long long>(st.st_size) > maxBytes) {
        error = shown + ": " + what + " is " + std::to_string(st.st_size) + " bytes, more than the " + bytes(maxBytes) + " limit";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = shown + ": cannot open " + what + " (" + std::strerror(errno) + ")";
        return false;
    }
    text.assign(static_cast<std::size_t>(st.st_size), '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(in.gcount()));
    // Grown since stat: read what is there up to the cap, and refuse beyond it.
    char buf[65536];
    while (in && text.size() <= maxBytes) {
        in.read(buf, sizeof buf);
        text.append(buf, static_cast<std::size_t>(in.gcount()));
    }
    if (text.size() > maxBytes) {
        error = shown + ": " + what + " grew past the " + bytes(maxBytes) + " limit while it was read";
        return false;
    }
    if (in.bad()) {
        error = shown + ": cannot read " + what;
        return false;
    }
    return true;
}

std::string errorText(std::string_view text, std::size_t maxChars) {
    std::string out;
    std::size_t shown = 0;
    for (; shown < text.size() && out.size() < maxChars; ++shown) {
        const auto c = static_cast<unsigned char>(text[shown]);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            char esc[8];
            std::snprintf(esc, sizeof esc, "\\x%02x", c);
            out += esc;
        }
    }
    if (shown < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
    return out;
}

}  // namespace obscura
