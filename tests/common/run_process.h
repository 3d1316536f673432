// Runs a shell command for the end-to-end tests, capturing stdout and stderr together.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace obscura::testing_support {

struct ProcessResult {
    int code = -1;    // exit status, or 128 + signal
    std::string out;  // stdout and stderr, interleaved
};

inline ProcessResult runProcess(const std::string& command) {
    ProcessResult r;
    FILE* p = popen((command + " 2>&1").c_str(), "r");
    char buf[4096];
    while (p && std::fgets(buf, sizeof buf, p)) r.out += buf;
    const int status = p ? pclose(p) : -1;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return r;
}

}  // namespace obscura::testing_support
