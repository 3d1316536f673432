// Test levels that mark each entity with a "// <why>" comment line before its opening brace (one
// bad entity per reason): the line where each such entity opens, by its comment.
#pragma once

#include <fstream>
#include <map>
#include <string>

namespace obscura::test {

inline std::map<std::string, int> entityLinesAfterComments(const std::string& mapPath) {
    std::map<std::string, int> out;
    std::ifstream in(mapPath);
    std::string line, pending;
    for (int n = 1; std::getline(in, line); ++n) {
        if (line.rfind("// ", 0) == 0) pending = line.substr(3);
        else if (line == "{" && !pending.empty()) out[pending] = n, pending.clear();
    }
    return out;
}

}  // namespace obscura::test
