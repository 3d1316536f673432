#include <gtest/gtest.h>

#include "map/map_compile.h"
#include "replay/replay_recorder.h"
#include "replay_player.h"
#include "settings.h"

#include <cstdio>
#include <filesystem>
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

TEST(Settings, OutOfRangeNumbersAreErrorsNotClamped) {
    EXPECT_EQ(errorOf({"--width", "-5"}), "command line: setting 'width': '-5' is out of range, expected 16 to 8192");
    EXPECT_EQ(errorOf({"--fov", "500"}), "command line: setting 'fov': '500' is out of range, expected 40 to 140");
    EXPECT_EQ(errorOf({"--width", "640.5"}), "command line: setting 'width': '640.5' is not a whole number");
    for (const char* bad : {"inf", "nan", "0x10", "1e400", " 90", "90 ", ""})
        EXPECT_EQ(errorOf({"--fov", bad}), "command line: setting 'fov': '" + std::string(bad) + "' is not a number") << bad;
    EXPECT_EQ(errorOf({"--map-scale", "0.5"}), "command line: setting 'map-scale': '0.5' is out of range, expected 0 (from the map) or 1 to 1024");
    EXPECT_EQ(errorOf({"--ticks", "-1"}), "command line: setting 'ticks': '-1' is out of range, expected 0 to 1000000000");
    const std::string cfg = writeTemp("obscura_range.cfg", "fov = 90\nmouse-sensitivity = 0\n");
    EXPECT_EQ(errorOf({"--config", cfg}), cfg + ":2: setting 'mouse-sensitivity': '0' is out of range, expected 0.01 to 20");
    Settings s;
    ASSERT_TRUE(parseArgs({"--fov", "140", "--width", "16", "--map-scale", "0", "--ticks", "+5"}, s));
    EXPECT_DOUBLE_EQ(s.fov, 140);
    EXPECT_EQ(s.ticks, 5);
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
    ASSERT_TRUE(parseArgs({"--ssao", "crytek", "--ssao-radius", "0.8", "--ssao-samples", "32"}, s));
    EXPECT_EQ(s.ssao, "crytek");
    EXPECT_DOUBLE_EQ(s.ssaoRadius, 0.8);
    EXPECT_EQ(s.ssaoSamples, 32);
    EXPECT_DOUBLE_EQ(s.ssaoLargeRadius, 2.0);  // the combined mode's large scale: its own knob
    ASSERT_TRUE(parseArgs({"--ssao", "combined", "--ssao-large-radius", "4"}, s));
    EXPECT_EQ(s.ssao, "combined");
    EXPECT_DOUBLE_EQ(s.ssaoLargeRadius, 4.0);
    EXPECT_DOUBLE_EQ(s.ssaoRadius, 0.8);  // untouched by it
    EXPECT_NE(errorOf({"--ssao-large-radius", "20"}).find("out of range"), std::string::npos);
    EXPECT_EQ(errorOf({"--ssao-samples", "64"}), "command line: setting 'ssao-samples': '64' is out of range, expected 1 to 32");
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

// Hardening (issue 12): every value checked where it enters, with the file:line or "command line".
TEST(SettingsBoundary, APositionalArgumentIsNamed) {
    EXPECT_EQ(errorOf({"arena.map"}), "command line: unexpected argument 'arena.map': settings are given as --name value (see --help)");
    EXPECT_EQ(errorOf({"--width", "640", "x"}), "command line: unexpected argument 'x': settings are given as --name value (see --help)");
}

TEST(SettingsBoundary, DuplicateBindingsAreErrorsButSwapsInAFileAreFine) {
    EXPECT_EQ(errorOf({"--bind-jump", "w"}),
              "command line: setting 'bind-jump': key 'w' is already bound to 'forward' (by default); one key per action");
    const std::string dup = writeTemp("obscura_dup.cfg", "bind-fire = j\nbind-jump = j\n");
    EXPECT_EQ(errorOf({"--config", dup}), dup + ":2: setting 'bind-jump': key 'j' is already bound to 'fire' (at " + dup +
                                              ":1); one key per action");
    const std::string swap = writeTemp("obscura_swap.cfg", "bind-forward = s\nbind-back = w\n");
    Settings s;
    ASSERT_TRUE(parseArgs({"--config", swap}, s));
    EXPECT_EQ(s.bindings.at(Action::Forward), "s");
    EXPECT_EQ(s.bindings.at(Action::Back), "w");
    // At run time (the menu's rebinding, a replay's set) the two actions swap keys.
    SettingsParser p;
    p.apply("bind-jump", "w", s, "menu");
    EXPECT_EQ(s.bindings.at(Action::Jump), "w");
    EXPECT_EQ(s.bindings.at(Action::Back), "space");
    EXPECT_NO_THROW(checkBindings(s));
}

TEST(SettingsBoundary, StartPoseAndSmokeAtAreFiniteAndRanged) {
    EXPECT_EQ(errorOf({"--start-pose", "1e10 1.65 0 0 0"}),
              "command line: setting 'start-pose': '1e10' (x) is out of range, expected -300000 to 300000");
    EXPECT_EQ(errorOf({"--start-pose", "1 2 3 4 5garbage"}),
              "command line: setting 'start-pose': '5garbage' (pitch) is not a number, expected 'x y z yaw pitch'");
    EXPECT_EQ(errorOf({"--start-pose", "1 2 3 4 5 6"}),
              "command line: setting 'start-pose': 6 numbers in '1 2 3 4 5 6', expected 'x y z yaw pitch'");
    EXPECT_EQ(errorOf({"--smoke-at", "0 nan 0"}), "command line: setting 'smoke-at': 'nan' (y) is not a number, expected 'x y z'");
    const std::string cfg = writeTemp("obscura_pose.cfg", "# far\nstart-pose = 0 1.65 -4e5 0 0\n");
    EXPECT_EQ(errorOf({"--config", cfg}), cfg + ":2: setting 'start-pose': '-4e5' (z) is out of range, expected -300000 to 300000");
}

TEST(SettingsBoundary, PosesMustLieInTheLevel) {
    // A 64-unit cube: 2 m; the box allowed is the brushes plus 100 m.
    const std::string cube =
        "{\n\"classname\" \"worldspawn\"\n{\n"
        "( 0 0 0 ) ( 0 1 0 ) ( 0 0 1 ) t 0 0 0 1 1\n( 0 0 0 ) ( 0 0 1 ) ( 1 0 0 ) t 0 0 0 1 1\n"
        "( 0 0 0 ) ( 1 0 0 ) ( 0 1 0 ) t 0 0 0 1 1\n( 64 64 64 ) ( 64 65 64 ) ( 65 64 64 ) t 0 0 0 1 1\n"
        "( 64 64 64 ) ( 65 64 64 ) ( 64 64 65 ) t 0 0 0 1 1\n( 64 64 64 ) ( 64 64 65 ) ( 64 65 64 ) t 0 0 0 1 1\n}\n}\n";
    const map::Level level = map::compileLevel(map::parseMap(cube, "cube.map"));
    Settings s;
    ASSERT_TRUE(parseArgs({"--start-pose", "1 1.65 -1 0 0", "--smoke-at", "50 0 0"}, s));
    EXPECT_NO_THROW(checkInLevel(s, level));
    ASSERT_TRUE(parseArgs({"--start-pose", "500 1.65 0 0 0"}, s));
    try {
        checkInLevel(s, level);
        FAIL();
    } catch (const SettingsError& e) {
        EXPECT_STREQ(e.what(), "command line: setting 'start-pose': (500, 1.65, 0) is outside cube.map: its brushes plus 100 m "
                               "reach (-100, -100, -102) to (102, 102, 100)");
    }
    // From a file: its line. A replay's `start` goes through the same check with the script's line.
    Settings t;
    const std::string cfg = writeTemp("obscura_far.cfg", "smoke-at = 0 0 -300\n");
    ASSERT_TRUE(parseArgs({"--config", cfg}, t));
    t.sources["start-pose"] = "walk.replay:4";
    t.startPose = "0 1.65 900 0 0";
    try {
        checkInLevel(t, level);
        FAIL();
    } catch (const SettingsError& e) {
        EXPECT_NE(std::string(e.what()).find("walk.replay:4: setting 'start-pose': (0, 1.65, 900) is outside"), std::string::npos) << e.what();
    }
    t.startPose.clear();
    try {
        checkInLevel(t, level);
        FAIL();
    } catch (const SettingsError& e) {
        EXPECT_NE(std::string(e.what()).find(cfg + ":1: setting 'smoke-at': (0, 0, -300) is outside"), std::string::npos) << e.what();
    }
}

TEST(SettingsBoundary, ConfigFilesAreBoundedAndNamed) {
    EXPECT_EQ(errorOf({"--config", "/dev/zero"}), "/dev/zero: is a device, expected a config file");
    EXPECT_EQ(errorOf({"--config", testing::TempDir()}), testing::TempDir() + ": is a directory, expected a config file");
    const std::string big = testing::TempDir() + "obscura_big.cfg";
    std::ofstream(big).close();
    std::filesystem::resize_file(big, kMaxConfigBytes + 1);
    EXPECT_EQ(errorOf({"--config", big}), big + ": config file is 1048577 bytes, more than the 1 MiB limit");
    // A long token and raw bytes: a short line, escaped.
    const std::string longLine = writeTemp("obscura_long.cfg", "fov = " + std::string(900'000, '9') + "\x01\n");
    const std::string e = errorOf({"--config", longLine});
    EXPECT_LT(e.size(), 300u);
    EXPECT_NE(e.find(longLine + ":1: setting 'fov': '9999"), std::string::npos) << e;
    EXPECT_NE(e.find("... (900001 bytes)' is not a number"), std::string::npos) << e;
    const std::string raw = writeTemp("obscura_raw.cfg", "\x1b[31m\n");
    EXPECT_EQ(errorOf({"--config", raw}), raw + ":1: expected 'key = value', got '\\x1b[31m'");
}

TEST(SettingsBoundary, AConfigsLevelIsCheckedWithItsLine) {
    const std::string cfg = writeTemp("obscura_level.cfg", "fov = 90\nlevel = /nonexistent/nothere.map\n");
    EXPECT_EQ(errorOf({"--config", cfg}), cfg + ":2: setting 'level': map file '/nonexistent/nothere.map' not found");
    const std::string dir = writeTemp("obscura_level2.cfg", "level = " + testing::TempDir() + "\n");
    EXPECT_NE(errorOf({"--config", dir}).find(dir + ":1: setting 'level': '"), std::string::npos);
    const std::string ok = writeTemp("obscura_level3.cfg", "level = " + std::string(OBSCURA_SOURCE_DIR) + "/media/levels/arena.map\n");
    Settings s;
    EXPECT_TRUE(parseArgs({"--config", ok}, s));
}

TEST(SettingsBoundary, OutputsAreCheckedWritableBeforeTheRun) {
    const auto outputError = [](std::vector<std::string> args) {
        Settings s;
        try {
            parseArgs(std::move(args), s);
            checkOutputsWritable(s);
        } catch (const SettingsError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(outputError({"--screenshot", "/proc/nonexistent/shot.png"}),
              "command line: setting 'screenshot': cannot write '/proc/nonexistent/shot.png': its folder '/proc/nonexistent' cannot be "
              "created (No such file or directory)");
    EXPECT_EQ(outputError({"--record", "/etc/passwd/x.replay"}),
              "command line: setting 'record': cannot write '/etc/passwd/x.replay': its folder '/etc/passwd' is not a folder");
    EXPECT_EQ(outputError({"--record", "/proc/x.replay"}),
              "command line: setting 'record': cannot write '/proc/x.replay': its folder '/proc' cannot be written");
    EXPECT_EQ(outputError({"--replay", "x.replay", "--capture-dir", "/proc/captures"}),
              "command line: setting 'capture-dir': folder '/proc/captures' cannot be created (No such file or directory)");
    EXPECT_EQ(outputError({"--screenshot", testing::TempDir() + "shot"}),
              "command line: setting 'screenshot': '" + testing::TempDir() + "shot' does not end in .png (screenshots are PNG files)");
    EXPECT_EQ(outputError({"--screenshot", testing::TempDir() + "shot.png", "--record", testing::TempDir() + "r.replay",
                           "--replay", "x.replay", "--capture-dir", testing::TempDir() + "caps/new"}),
              "");
    EXPECT_TRUE(std::filesystem::is_directory(testing::TempDir() + "caps/new"));
    // A screenshot's (and a dump's, a recording's) folder is made like the capture folder.
    std::filesystem::remove_all(testing::TempDir() + "shots");
    EXPECT_EQ(outputError({"--screenshot", testing::TempDir() + "shots/new/a.png"}), "");
    EXPECT_TRUE(std::filesystem::is_directory(testing::TempDir() + "shots/new"));
    const std::string cfg = writeTemp("obscura_out.cfg", "\nscreenshot = /proc/nonexistent/a.png\n");
    EXPECT_EQ(outputError({"--config", cfg}), cfg + ":2: setting 'screenshot': cannot write '/proc/nonexistent/a.png': its folder "
                                                    "'/proc/nonexistent' cannot be created (No such file or directory)");
}

TEST(SettingsBoundary, RecordingsCarryTheInputSettingsAndReplaysApplyThemFirst) {
    Settings recorded;
    ASSERT_TRUE(parseArgs({"--mouse-sensitivity", "2.5", "--invert-mouse", "--bind-jump", "j", "--bind-fire", "mouse2"}, recorded));
    replay::Recorder rec("a.map", 1, 320, 180, 60);
    for (const auto& [k, v] : inputSettingValues(recorded)) rec.setting(k, v);
    rec.keyDown(0, "j");
    rec.end(10);
    const replay::Script script = replay::parseScript(replay::formatScript(rec.script()), "rec.replay");
    // Played back onto default settings (replays never read a config), in ReplayPlayer's order.
    Settings played;
    SettingsParser p;
    ReplayPlayer player(script);
    const ReplayTick t0 = player.take(0);
    ASSERT_EQ(t0.settings.size(), inputSettingValues(recorded).size());
    for (const auto* c : t0.settings) p.apply(c->name, c->value, played, script.fileName + ":" + std::to_string(c->line));
    EXPECT_DOUBLE_EQ(played.mouseSensitivity, 2.5);
    EXPECT_TRUE(played.invertMouse);
    EXPECT_EQ(played.bindings, recorded.bindings);
    ASSERT_EQ(t0.inputs.size(), 1u);
    EXPECT_TRUE(player.take(1).settings.empty());  // once, before the first tick
}

TEST(Settings, SignModeIsValidated) {
    Settings s;
    EXPECT_EQ(s.signMode, "shafts");
    for (const char* mode : {"off", "shafts", "meshuggah"}) {
        ASSERT_TRUE(parseArgs({"--sign-mode", mode}, s));
        EXPECT_EQ(s.signMode, mode);
    }
    EXPECT_EQ(errorOf({"--sign-mode", "rays"}), "command line: setting 'sign-mode': 'rays', expected off, shafts or meshuggah");
}

TEST(Settings, ReplayDrawIsValidatedAndStartupOnly) {
    Settings s;
    EXPECT_EQ(s.replayDraw, "every-frame");
    for (const char* mode : {"captures", "every-frame"}) {
        ASSERT_TRUE(parseArgs({"--replay-draw", mode}, s));
        EXPECT_EQ(s.replayDraw, mode);
    }
    EXPECT_EQ(errorOf({"--replay-draw", "some"}), "command line: setting 'replay-draw': 'some', expected every-frame or captures");
    EXPECT_FALSE(SettingsParser().isRuntime("replay-draw"));  // a replay's `set` cannot change it mid-run
}

TEST(Settings, TruthKeyIsBoundValidatedAndRuntime) {
    Settings s;
    EXPECT_EQ(s.bindings.at(Action::CycleTruth), "t");
    EXPECT_EQ(std::string(actionName(Action::CycleTruth)), "cycle_truth");
    EXPECT_EQ(s.truth, "off");
    EXPECT_EQ(s.truthRays, 256);
    EXPECT_EQ(s.truthThreads, 1);
    for (const char* show : {"off", "reference", "mode", "heatmap"}) {
        ASSERT_TRUE(parseArgs({"--truth", show}, s));
        EXPECT_EQ(s.truth, show);
    }
    EXPECT_EQ(errorOf({"--truth", "heat-map"}), "command line: setting 'truth': 'heat-map', expected off, reference, mode or heatmap");
    EXPECT_NE(errorOf({"--truth-rays", "4"}).find("'4' is out of range, expected 8 to 4096"), std::string::npos);
    ASSERT_TRUE(parseArgs({"--bind-cycle_truth", "y", "--truth-threads", "2"}, s));
    EXPECT_EQ(s.bindings.at(Action::CycleTruth), "y");  // rebindable like the others
    EXPECT_EQ(s.truthThreads, 2);
    // A replay may `set truth ...` and the rays, not the threads (the tracer's pool is made once);
    // a bad value names the script's line.
    SettingsParser p;
    EXPECT_TRUE(p.isRuntime("truth"));
    EXPECT_TRUE(p.isRuntime("truth-rays"));
    EXPECT_FALSE(p.isRuntime("truth-threads"));
    try {
        p.apply("truth", "on", s, "t.replay:7");
        ADD_FAILURE() << "no error";
    } catch (const SettingsError& e) {
        EXPECT_EQ(std::string(e.what()), "t.replay:7: setting 'truth': 'on', expected off, reference, mode or heatmap");
    }
}
