// Reading untrusted input files (levels, replays, config files) and quoting what they hold in
// error messages. Plain C++. One policy for every file the game reads at load time:
//   - only a regular file (after following symlinks) is read: a directory, device, pipe or socket
//     is refused by name (`--level /dev/zero` must not read forever);
//   - a file larger than its kind's cap is refused before it is read, and at most cap + 1 bytes
//     are ever read (a file growing while it is read cannot get past the cap either);
//   - text from a file echoed in an error is cut to a readable length and its raw bytes escaped,
//     so a 10 MB token gives a one-line message.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace obscura {

// Reads `path` into `text`. On failure returns false and sets `error` to "path: problem" (e.g.
// "x.map: is a directory, expected a map file"); `what` names the kind ("map file").
bool readInputFile(const std::string& path, std::size_t maxBytes, const char* what, std::string& text, std::string& error);

// `text` for an error message: bytes outside printable ASCII as \xNN, and anything past
// `maxChars` characters cut and replaced by "... (N bytes)".
std::string errorText(std::string_view text, std::size_t maxChars = 64);

}  // namespace obscura
