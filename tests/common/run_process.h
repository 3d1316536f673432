// Runs a shell command for the end-to-end tests, capturing stdout and stderr together.
#pragma once

#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

namespace obscura::testing_support {

struct ProcessResult {
    int code = -1;    // exit status, or 128 + signal
    std::string out;  // stdout and stderr, interleaved
};

inline ProcessResult runOnce(const std::string& command) {
    ProcessResult r;
    FILE* p = popen((command + " 2>&1").c_str(), "r");
    char buf[4096];
    while (p && std::fgets(buf, sizeof buf, p)) r.out += buf;
    const int status = p ? pclose(p) : -1;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return r;
}

// As runOnce, but a game the suite's shared Xvfb refused a connection (the game's own "cannot open
// an X display" line, seen once in 575 tests of a full suite on 2026-12-07 with DISPLAY set) is
// started again, twice at most, a second apart: that is the machine's X server, not the code under
// test. A command that has no display gives the same answer each time, so nothing is hidden.
inline ProcessResult runProcess(const std::string& command) {
    ProcessResult r = runOnce(command);
    for (int retry = 0; retry < 2 && r.code != 0 && r.out.find("cannot open an X display") != std::string::npos; ++retry) {
        std::fprintf(stderr, "runProcess: the X server refused the game; starting it again\n");
        std::this_thread::sleep_for(std::chrono::seconds(1));
        r = runOnce(command);
    }
    return r;
}

}  // namespace obscura::testing_support
