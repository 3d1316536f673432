#include <gtest/gtest.h>

#include "settings.h"

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

using namespace obscura;

namespace {
bool parseArgs(std::vector<std::string> args, Settings& s) {
    args.insert(args.begin(), "obscura");
    std::vector<const char*> argv;
    for (auto& a : args) argv.push_back(a.c_str());
    SettingsParser p;
    return p.parse(static_cast<int>(argv.size()), argv.data(), s);
}

std::string writeTemp(const std::string& name, const std::string& text) {
    const std::string path = testing::TempDir() + name;
    std::ofstream(path) << text;
    return path;
}

std::string errorOf(std::vector<std::string> args) {
    Settings s;
    try {
        parseArgs(std::move(args), s);
    } catch (const SettingsError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(Settings, DefaultsAreConventional) {
    Settings s;
    EXPECT_EQ(s.bindings.at(Action::Forward), "w");
    EXPECT_EQ(s.bindings.at(Action::CycleAo), "o");
    EXPECT_EQ(s.bindings.at(Action::Jump), "space");
    EXPECT_EQ(s.width, 1280);
}

TEST(Settings, CommandLineValuesAndFlags) {
    Settings s;
    ASSERT_TRUE(parseArgs({"--width", "640", "--height=360", "--headless", "--fov", "100", "--seed", "77",
                           "--bind-jump", "j"}, s));
    EXPECT_EQ(s.width, 640);
    EXPECT_EQ(s.height, 360);
    EXPECT_TRUE(s.headless);
    EXPECT_DOUBLE_EQ(s.fov, 100);
    EXPECT_EQ(s.seed, 77u);
    EXPECT_EQ(s.bindings.at(Action::Jump), "j");
}

TEST(Settings, ConfigFileIsReadAndCommandLineWins) {
    const std::string cfg = writeTemp("obscura_ok.cfg", "# comment\nwidth = 800\nvsync = off  # trailing\nfov = 75\n");
    Settings s;
    ASSERT_TRUE(parseArgs({"--config", cfg, "--fov", "95"}, s));
    EXPECT_EQ(s.width, 800);
    EXPECT_FALSE(s.vsync);
    EXPECT_DOUBLE_EQ(s.fov, 95);
}

TEST(Settings, ConfigErrorsNameFileAndLine) {
    const std::string cfg = writeTemp("obscura_bad.cfg", "width = 800\n\nfrobnicate = 3\n");
    const std::string e = errorOf({"--config", cfg});
    EXPECT_NE(e.find(cfg + ":3"), std::string::npos) << e;
    EXPECT_NE(e.find("frobnicate"), std::string::npos) << e;

    const std::string cfg2 = writeTemp("obscura_bad2.cfg", "width 800\n");
    EXPECT_NE(errorOf({"--config", cfg2}).find(cfg2 + ":1: expected 'key = value'"), std::string::npos);

    const std::string cfg3 = writeTemp("obscura_bad3.cfg", "vsync = maybe\n");
    EXPECT_NE(errorOf({"--config", cfg3}).find("not a boolean"), std::string::npos);
}

TEST(Settings, BadCommandLineIsAClearError) {
    EXPECT_NE(errorOf({"--no-such-option"}).find("command line"), std::string::npos);
    EXPECT_NE(errorOf({"--width", "wide"}).find("not a number"), std::string::npos);
    EXPECT_NE(errorOf({"--bind-jump", "hyperspace"}).find("unknown key 'hyperspace'"), std::string::npos);
    EXPECT_NE(errorOf({"--config", "/nonexistent/obscura.cfg"}).find("cannot open"), std::string::npos);
}

TEST(Settings, OutOfRangeNumbersAreClamped) {
    Settings s;
    ASSERT_TRUE(parseArgs({"--fov", "500", "--width", "3"}, s));
    EXPECT_DOUBLE_EQ(s.fov, 140);
    EXPECT_EQ(s.width, 16);
}

TEST(Settings, RuntimeApplyUsesTheSameTable) {
    SettingsParser p;
    Settings s;
    EXPECT_TRUE(p.isKnown("fov"));
    EXPECT_FALSE(p.isKnown("fovv"));
    p.apply("mouse-sensitivity", "2.5", s, "x.replay:4");
    EXPECT_DOUBLE_EQ(s.mouseSensitivity, 2.5);
    try {
        p.apply("fovv", "3", s, "x.replay:9");
        FAIL();
    } catch (const SettingsError& e) {
        EXPECT_NE(std::string(e.what()).find("x.replay:9"), std::string::npos);
    }
}

TEST(Settings, AoModeIsValidatedAndCycles) {
    Settings s;
    ASSERT_TRUE(parseArgs({"--ssao", "crytek", "--ssao-radius", "0.8", "--ssao-samples", "64"}, s));
    EXPECT_EQ(s.ssao, "crytek");
    EXPECT_DOUBLE_EQ(s.ssaoRadius, 0.8);
    EXPECT_EQ(s.ssaoSamples, 32);  // clamped with a warning
    EXPECT_NE(errorOf({"--ssao", "hbao++"}).find("unknown mode 'hbao++', expected one of off, crytek, hemisphere, cone, horizon"),
              std::string::npos);
}

TEST(Settings, UpdateConfigTextRewritesKeysKeepsTheRest) {
    const std::string before = "# my config\nfov = 100\n\nmouse-sensitivity = 2 # fast\nbind-jump = space\n";
    const std::string after = updateConfigText(before, {{"mouse-sensitivity", "1.5"}, {"master-volume", "0.3"}});
    EXPECT_EQ(after, "# my config\nfov = 100\n\nmouse-sensitivity = 1.5\nbind-jump = space\nmaster-volume = 0.3\n");
    // What it writes reads back through the same parser.
    const std::string path = testing::TempDir() + "/updated.cfg";
    std::ofstream(path) << after;
    Settings s;
    SettingsParser p;
    const char* argv[] = {"obscura", "--config", path.c_str()};
    ASSERT_TRUE(p.parse(3, argv, s));
    EXPECT_DOUBLE_EQ(s.mouseSensitivity, 1.5);
    EXPECT_DOUBLE_EQ(s.masterVolume, 0.3);
    EXPECT_DOUBLE_EQ(s.fov, 100);
}
