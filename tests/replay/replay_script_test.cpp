// Tests of the replay script format v1 (engine_ext/replay): parser, errors with file:line, format
// round trip, commandsAt and the Recorder.
#include <gtest/gtest.h>

#include "replay/replay_recorder.h"
#include "replay/replay_script.h"

#include <filesystem>
#include <fstream>

using namespace obscura::replay;

namespace {
const char* kHeader = "obscura-replay 1\nlevel media/levels/arena.map\nseed 7\nresolution 320 180\n";

std::string errorOf(const std::string& body, const std::function<bool(const std::string&)>& known = {}) {
    try {
        parseScript(kHeader + body, "r.replay", known);
    } catch (const ScriptError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(ReplayScript, ParsesEveryCommandAndHeader) {
    const Script s = parseScript(std::string("# a comment\n\n") + kHeader + "tickrate 30\n"
                                 "0 key w down   # walk\n"
                                 "0 mouse 120 -4\n"
                                 "10 button left tap\n"
                                 "12 key o tap\n"
                                 "20 capture door_1\n"
                                 "20 set mouse-sensitivity 2.5\n"
                                 "21 hash\n"
                                 "22 hash 0123456789abcdef\n"
                                 "30 end\n",
                                 "r.replay");
    EXPECT_EQ(s.level, "media/levels/arena.map");
    EXPECT_EQ(s.seed, 7u);
    EXPECT_EQ(s.width, 320);
    EXPECT_EQ(s.height, 180);
    EXPECT_DOUBLE_EQ(s.tickRate, 30);
    ASSERT_EQ(s.commands.size(), 9u);
    EXPECT_EQ(s.commands[0].type, Command::Type::Key);
    EXPECT_EQ(s.commands[0].name, "w");
    EXPECT_EQ(s.commands[0].action, Command::Action::Down);
    EXPECT_EQ(s.commands[0].line, 8);
    EXPECT_EQ(s.commands[1].dx, 120);
    EXPECT_EQ(s.commands[1].dy, -4);
    EXPECT_EQ(s.commands[2].type, Command::Type::Button);
    EXPECT_EQ(s.commands[2].action, Command::Action::Tap);
    EXPECT_EQ(s.commands[4].name, "door_1");
    EXPECT_EQ(s.commands[5].value, "2.5");
    EXPECT_TRUE(s.commands[6].value.empty());
    EXPECT_EQ(s.commands[7].value, "0123456789abcdef");
    EXPECT_EQ(s.commands[8].type, Command::Type::End);
    EXPECT_EQ(s.endTick(), 30);
}

TEST(ReplayScript, ErrorsNameFileLineAndWhatWasExpected) {
    EXPECT_EQ(errorOf("0 jmp\n"), "r.replay:5: unknown command 'jmp', expected one of key, mouse, button, capture, set, hash, end");
    EXPECT_EQ(errorOf("45 key w down\n40 key w up\n"), "r.replay:6: tick 40 is before tick 45 of line 5");
    EXPECT_NE(errorOf("0 key shiftt down\n").find("r.replay:5: unknown key 'shiftt'"), std::string::npos);
    EXPECT_NE(errorOf("0 key w sideways\n").find("unknown action 'sideways', expected down, up or tap"), std::string::npos);
    EXPECT_NE(errorOf("0 capture a\n1 capture a\n").find("r.replay:6: duplicate capture name 'a'"), std::string::npos);
    EXPECT_NE(errorOf("0 capture a/b\n").find("bad capture name"), std::string::npos);
    EXPECT_NE(errorOf("0 mouse 1\n").find("missing arguments, expected '<tick> mouse <dx> <dy>'"), std::string::npos);
    EXPECT_NE(errorOf("0 end\n1 hash\n").find("r.replay:6: '1 hash' after 'end', expected nothing"), std::string::npos);
    EXPECT_NE(errorOf("0 key w down extra\n").find("extra arguments"), std::string::npos);
    EXPECT_NE(errorOf("x key w down\n").find("unknown header 'x'"), std::string::npos);
    EXPECT_NE(errorOf("-3 key w down\n").find("out of range"), std::string::npos);
    EXPECT_NE(errorOf("0 hash 12\n").find("bad expected hash"), std::string::npos);
    EXPECT_NE(errorOf("0 button side down\n").find("unknown button 'side'"), std::string::npos);
    auto known = [](const std::string& k) { return k == "fov"; };
    EXPECT_TRUE(errorOf("0 set fov 90\n", known).empty());
    EXPECT_NE(errorOf("0 set fob 90\n", known).find("r.replay:5: unknown setting 'fob'"), std::string::npos);
    EXPECT_NE(errorOf("0 key w down\nseed 3\n").find("header 'seed' after the first command"), std::string::npos);
}

TEST(ReplayScript, HeaderErrors) {
    auto err = [](const std::string& text) {
        try {
            parseScript(text, "h.replay");
        } catch (const ScriptError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(err("level a.map\n"), "h.replay:1: expected the header 'obscura-replay 1' first, found 'level'");
    EXPECT_EQ(err("obscura-replay 2\n"), "h.replay:1: unsupported version 2, expected 1");
    EXPECT_EQ(err(""), "h.replay:1: empty script, expected the header 'obscura-replay 1'");
    EXPECT_EQ(err("obscura-replay 1\n0 hash\n"), "h.replay:2: the header has no 'level <path>' line before the first command");
    EXPECT_NE(err("obscura-replay 1\nlevel a.map\nresolution 10 10\n").find("a width 10 is out of range"), std::string::npos);
    EXPECT_THROW(loadScript("/nonexistent.replay"), ScriptError);
}

TEST(ReplayScript, FormatParseRoundTrip) {
    const Script a = parseScript(std::string(kHeader) + "0 key w down\n3 mouse -5 2\n3 button right tap\n9 set fov 100\n9 capture x\n10 hash abcdefabcdef0123\n11 end\n", "a.replay");
    const Script b = parseScript(formatScript(a), "b.replay");
    EXPECT_EQ(b.level, a.level);
    EXPECT_EQ(b.seed, a.seed);
    EXPECT_EQ(b.width, a.width);
    EXPECT_EQ(b.commands, a.commands);
}

TEST(ReplayRecorder, MergesMouseMotionPerTickAndOrdersByTick) {
    Recorder r("lvl.map", 3, 320, 180, 60);
    r.keyDown(0, "w");
    r.mouse(0, 5, 1);
    r.mouse(0, 7, -3);
    r.mouse(1, 1, 1);
    r.keyDown(2, "mouse1");
    r.keyUp(2, "w");
    r.hash(1, "0000000000000001");  // taken after tick 2's inputs were recorded
    r.end(3);
    const Script s = parseScript(formatScript(r.script()), "rec.replay");
    ASSERT_EQ(s.commands.size(), 7u);
    EXPECT_EQ(s.commands[1].type, Command::Type::Mouse);
    EXPECT_EQ(s.commands[1].dx, 12);
    EXPECT_EQ(s.commands[1].dy, -2);
    EXPECT_EQ(s.commands[3].type, Command::Type::Hash);
    EXPECT_EQ(s.commands[3].tick, 1);
    EXPECT_EQ(s.commands[4].type, Command::Type::Button);
    EXPECT_EQ(s.commands[4].name, "left");
    EXPECT_EQ(s.commands[6].type, Command::Type::End);
    EXPECT_EQ(s.seed, 3u);
}

TEST(ReplayScript, AcceptsEveryKeyNameOfTheFormatAndNoOther) {
    std::vector<std::string> names;
    for (char c = 'a'; c <= 'z'; ++c) names.emplace_back(1, c);
    for (char c = '0'; c <= '9'; ++c) names.emplace_back(1, c);
    for (int i = 1; i <= 12; ++i) names.push_back("f" + std::to_string(i));
    for (const char* n : {"space", "return", "escape", "tab", "backspace", "lshift", "rshift", "lctrl", "rctrl", "lalt",
                          "ralt", "up", "down", "left", "right", "minus", "equals", "comma", "period", "slash", "grave"})
        names.emplace_back(n);
    std::string body;
    for (const auto& n : names) body += "0 key " + n + " tap\n";
    const Script s = parseScript(kHeader + body, "keys.replay");
    ASSERT_EQ(s.commands.size(), names.size());
    for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(s.commands[i].name, names[i]);
    for (const char* bad : {"W", "f13", "f0", "shift", "enter", "mouse1"})
        EXPECT_EQ(errorOf(std::string("0 key ") + bad + " down\n"),
                  std::string("r.replay:5: unknown key '") + bad + "', expected a key name such as w, space, lshift, f1")
            << bad;
}

TEST(ReplayScript, HeaderDefaultsAndValues) {
    const Script d = parseScript("obscura-replay 1\nlevel a b.map\n", "d.replay");
    EXPECT_EQ(d.level, "a b.map");
    EXPECT_DOUBLE_EQ(d.tickRate, 60);  // default
    EXPECT_TRUE(d.commands.empty());
    EXPECT_EQ(d.endTick(), 0);
    const Script s = parseScript("obscura-replay 1 # v1\nlevel x.map\nseed 18446744073709551615\nseed 010\ntickrate 59.94\n", "s.replay");
    EXPECT_EQ(s.seed, 10u);  // the last seed line wins; decimal, not octal
    EXPECT_DOUBLE_EQ(s.tickRate, 59.94);
    EXPECT_EQ(parseScript("obscura-replay 1\nlevel x.map\nseed 18446744073709551615\n", "s.replay").seed, 18446744073709551615u);
}

TEST(ReplayScript, HeaderValueErrorsNameTheirLine) {
    auto err = [](const std::string& headerLine) {
        try {
            parseScript("obscura-replay 1\n# c\nlevel a.map\n" + headerLine + "\n", "h.replay");
        } catch (const ScriptError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(err("seed -1"), "h.replay:4: '-1' is not an unsigned 64-bit integer, expected a seed");
    EXPECT_EQ(err("seed 18446744073709551616"), "h.replay:4: '18446744073709551616' is not an unsigned 64-bit integer, expected a seed");
    EXPECT_EQ(err("seed 0x10"), "h.replay:4: '0x10' is not an unsigned 64-bit integer, expected a seed");
    EXPECT_EQ(err("seed 1 2"), "h.replay:4: extra arguments, expected 'seed <unsigned integer>'");
    EXPECT_EQ(err("tickrate 5"), "h.replay:4: tick rate 5 is out of range, expected 10 to 240");
    EXPECT_EQ(err("tickrate fast"), "h.replay:4: 'fast' is not a number, expected ticks per second");
    EXPECT_EQ(err("tickrate nan"), "h.replay:4: 'nan' is not a number, expected ticks per second");
    EXPECT_EQ(err("resolution 640"), "h.replay:4: missing arguments, expected 'resolution <width> <height>'");
    EXPECT_EQ(err("resolution 640 x"), "h.replay:4: 'x' is not an integer, expected a height");
    EXPECT_EQ(err("level"), "h.replay:4: missing path, expected 'level <path>'");
    EXPECT_EQ(err("obscura-replay 1"), "h.replay:4: unknown header 'obscura-replay', expected level, seed, resolution, tickrate, start, setting or '<tick> <command>'");
    EXPECT_EQ(err("0"), "h.replay:4: missing command after tick, expected '<tick> <command>'");
    EXPECT_EQ(err("0 capture a\n9 capture a"), "h.replay:5: duplicate capture name 'a' (first on line 4), expected a unique name");
    EXPECT_EQ(err("0 end\n\n# trailing comments are fine\n"), "");
}

TEST(ReplayScript, CommandsAtGroupsOneTickInScriptOrder) {
    const Script s = parseScript(std::string(kHeader) + "0 key w down\n5 mouse 1 2\n5 capture a\n5 hash\n9 end\n", "t.replay");
    EXPECT_TRUE(s.commandsAt(3).empty());
    const auto at5 = s.commandsAt(5);
    ASSERT_EQ(at5.size(), 3u);
    EXPECT_EQ(at5[0]->type, Command::Type::Mouse);
    EXPECT_EQ(at5[1]->name, "a");
    EXPECT_EQ(at5[2]->type, Command::Type::Hash);
    EXPECT_EQ(at5[0], &s.commands[1]);  // points into the script, no copies
    ASSERT_EQ(s.commandsAt(9).size(), 1u);
    EXPECT_TRUE(s.commandsAt(10).empty());
}

TEST(ReplayScript, FormatParseRoundTripIsEqualAndStable) {
    const Script a = parseScript(std::string(kHeader) + "tickrate 59.94\n0 key f12 tap\n0 mouse 0 -100000\n2 button middle up\n"
                                 "2 set ssao hemisphere   half\n3 capture k-9_Z\n3 hash\n4 end\n",
                                 "a.replay");
    const std::string text = formatScript(a);
    const Script b = parseScript(text, "b.replay");
    EXPECT_EQ(b, a);
    EXPECT_EQ(b.commands[3].value, "hemisphere half");
    EXPECT_EQ(formatScript(b), text);  // canonical: formatting again changes nothing
    Script c = b;
    c.commands[1].dy = 3;
    EXPECT_NE(c, a);  // the comparison sees a changed command
}

TEST(ReplayRecorder, ButtonsAndKeysParseBackToTheSameCommands) {
    Recorder r("media/levels/arena.map", 99, 640, 360, 60);
    r.end(7);  // recorded first, still last
    r.button(1, "right", true);
    r.keyDown(1, "lshift");
    r.mouse(1, -3, 0);
    r.capture(2, "shot");
    r.button(2, "right", false);
    r.mouse(2, 1, 1);
    r.mouse(2, 1, 1);
    r.keyUp(3, "lshift");
    const Script rec = r.script();
    const Script back = parseScript(formatScript(rec), "rec.replay");
    EXPECT_EQ(back, rec);
    ASSERT_EQ(back.commands.size(), 8u);
    EXPECT_EQ(back.commands[0].type, Command::Type::Button);
    EXPECT_EQ(back.commands[0].name, "right");
    EXPECT_EQ(back.commands[0].action, Command::Action::Down);
    EXPECT_EQ(back.commands[4].type, Command::Type::Button);
    EXPECT_EQ(back.commands[4].action, Command::Action::Up);
    EXPECT_EQ(back.commands[5].dx, 2);  // two motions in tick 2 merged
    EXPECT_EQ(back.commands[5].dy, 2);
    EXPECT_EQ(back.commands.back().type, Command::Type::End);
    EXPECT_EQ(back.endTick(), 7);
    EXPECT_THROW(r.button(4, "side", true), ScriptError);
}

TEST(ReplayScript, OptionalStartPoseRoundTripsAndBadOnesNameTheLine) {
    const std::string text = "obscura-replay 1\nlevel a.map\nstart 12 1.65 -6 -90 -2\n0 end\n";
    const auto s = obscura::replay::parseScript(text, "t.replay");
    EXPECT_EQ(s.start, "12 1.65 -6 -90 -2");
    EXPECT_EQ(obscura::replay::parseScript(obscura::replay::formatScript(s), "u.replay"), s);
    try {
        obscura::replay::parseScript("obscura-replay 1\nlevel a.map\nstart 1 2 x 4 5\n", "bad.replay");
        FAIL() << "accepted a bad start pose";
    } catch (const obscura::replay::ScriptError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.replay:3"), std::string::npos) << e.what();
    }
}

// Hardening: bounded reads, short error lines, ranged poses, capture names that fit a file name,
// the level named with its line, and the input settings a recording carries.
namespace {
std::string loadError(const std::string& path) {
    try {
        loadScript(path);
    } catch (const ScriptError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(ReplayLimits, DevicesDirectoriesAndOversizedScriptsAreRefusedByName) {
    EXPECT_EQ(loadError("/dev/zero"), "/dev/zero: is a device, expected a replay script");
    EXPECT_EQ(loadError(testing::TempDir()), testing::TempDir() + ": is a directory, expected a replay script");
    const std::string big = testing::TempDir() + "huge.replay";
    std::ofstream(big).close();
    std::filesystem::resize_file(big, kMaxScriptBytes + 1);
    EXPECT_EQ(loadError(big), big + ": replay script is 16777217 bytes, more than the 16 MiB limit");
    std::filesystem::remove(big);
    EXPECT_EQ(loadError("/nonexistent.replay"), "/nonexistent.replay: cannot open replay script (No such file or directory)");
}

TEST(ReplayLimits, LongTokensAreCutAndRawBytesEscaped) {
    const std::string e = errorOf("0 key " + std::string(10'000'000, 'w') + " down\n");
    EXPECT_LT(e.size(), 200u);
    EXPECT_NE(e.find("r.replay:5: unknown key 'wwww"), std::string::npos) << e;
    EXPECT_NE(e.find("... (10000000 bytes)'"), std::string::npos) << e;
    EXPECT_EQ(errorOf("0 frob\x1b[2J\n"), "r.replay:5: unknown command 'frob\\x1b[2J', expected one of key, mouse, button, capture, set, hash, end");
}

TEST(ReplayLimits, CaptureNamesMustFitAFileName) {
    const std::string ok(kMaxCaptureName, 'c');
    EXPECT_EQ(errorOf("0 capture " + ok + "\n"), "");
    const std::string e = errorOf("0 capture " + ok + "d\n");
    EXPECT_NE(e.find("r.replay:5: capture name 'cccc"), std::string::npos) << e;
    EXPECT_NE(e.find("is 244 characters, expected at most 243 (<name>.partial.png must fit a 255-byte file name)"), std::string::npos) << e;
}

TEST(ReplayLimits, StartPoseIsFiniteAndRanged) {
    const auto err = [](const std::string& start) {
        try {
            parseScript("obscura-replay 1\nlevel a.map\nstart " + start + "\n", "s.replay");
        } catch (const ScriptError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(err("1e10 1.65 0 0 0"), "s.replay:3: start '1e10' (x) is out of range, expected -300000 to 300000");
    EXPECT_EQ(err("0 1.65 0 0 91"), "s.replay:3: start '91' (pitch) is out of range, expected -90 to 90");
    EXPECT_EQ(err("0 1.65 0 720 0"), "s.replay:3: start '720' (yaw) is out of range, expected -360 to 360");
    EXPECT_EQ(err("0 1.65 0 inf 0"), "s.replay:3: start 'inf' (yaw) is not a number, expected 'x y z yaw pitch'");
    EXPECT_EQ(err("0 1e400 0 0 0"), "s.replay:3: start '1e400' (y) is not a number, expected 'x y z yaw pitch'");
    EXPECT_EQ(err("300000 -300000 1.5 -360 90"), "");
    EXPECT_EQ(checkPose("1 2 3 4"), "4 numbers in '1 2 3 4', expected 'x y z yaw pitch'");
    EXPECT_EQ(checkPoint("1 2 3"), "");
    EXPECT_EQ(checkPoint("1 2 3x"), "'3x' (z) is not a number, expected 'x y z'");
    const Script s = parseScript("obscura-replay 1\n# c\nlevel a.map\nstart 1 2 3 4 5\n", "s.replay");
    EXPECT_EQ(s.levelLine, 3);
    EXPECT_EQ(s.startLine, 4);
}

TEST(ReplayLimits, AMissingLevelNamesTheScriptsLevelLine) {
    const std::string dir = testing::TempDir() + "replay_level/";
    std::filesystem::create_directories(dir + "sub.map");
    std::ofstream(dir + "here.map") << "{\n}\n";
    const auto script = [&](const std::string& level) {
        return parseScript("obscura-replay 1\n\nlevel " + level + "\n0 end\n", dir + "x.replay");
    };
    EXPECT_EQ(resolveLevel(script("here.map"), "/nonexistent"), dir + "here.map");
    try {
        resolveLevel(script("gone.map"), "/data");
        FAIL();
    } catch (const ScriptError& e) {
        EXPECT_EQ(std::string(e.what()), dir + "x.replay:3: level 'gone.map' not found (looked beside the script and in /data)");
    }
    try {
        resolveLevel(script(dir + "sub.map"), "/data");
        FAIL();
    } catch (const ScriptError& e) {
        EXPECT_EQ(std::string(e.what()), dir + "x.replay:3: level '" + dir + "sub.map' is a directory, expected a map file");
    }
}

TEST(ReplayLimits, SettingHeadersRoundTripAndNameUnknownSettings) {
    Recorder r("a.map", 3, 320, 180, 60);
    r.setting("mouse-sensitivity", "2.5");
    r.setting("bind-jump", "j");
    r.set(40, "invert-mouse", "true");
    r.end(50);
    const Script s = r.script();
    const std::string text = formatScript(s);
    EXPECT_NE(text.find("tickrate 60\nsetting mouse-sensitivity 2.5\nsetting bind-jump j\n40 set invert-mouse true\n"), std::string::npos) << text;
    const Script back = parseScript(text, "rec.replay");
    EXPECT_EQ(back, s);
    ASSERT_EQ(back.settings.size(), 2u);
    EXPECT_EQ(back.settings[1].name, "bind-jump");
    EXPECT_EQ(back.settings[1].line, 7);
    const auto known = [](const std::string& k) { return k == "mouse-sensitivity"; };
    try {
        parseScript("obscura-replay 1\nlevel a.map\nsetting mouse-sensitivty 2\n", "u.replay", known);
        FAIL();
    } catch (const ScriptError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "u.replay:3: unknown setting 'mouse-sensitivty', expected a setting `obscura --help` lists that can change at run time");
    }
}
