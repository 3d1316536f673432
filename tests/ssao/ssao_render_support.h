// What the AO render tests share: the real game, headless, at 320x180 without the HUD, and the
// luma of its screenshots.
#pragma once

#include "core/image.h"
#include "run_process.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace obscura::ssao_test {

inline testing_support::ProcessResult game(const std::string& args) {
    return testing_support::runProcess(std::string("'" OBSCURA_GAME "' --headless --ticks 1 --width 320 "
                                                   "--height 180 --hud off ") + args + " 2>&1");
}

inline std::string shot(const std::string& name) {
    return (std::filesystem::path(testing::TempDir()) / ("ssao_" + name + ".png")).string();
}

// The game's frame with `args` (a view and the AO settings), as a PNG read back.
inline Image render(const std::string& name, const std::string& args) {
    const auto r = game(args + " --screenshot " + shot(name));
    EXPECT_EQ(r.code, 0) << r.out;
    return readPng(shot(name));
}

inline int luma(const Image& im, std::size_t pixel) {
    const auto* p = &im.rgba[pixel * 4];
    return (2126 * p[0] + 7152 * p[1] + 722 * p[2]) / 10000;
}

}  // namespace obscura::ssao_test
