#include <gtest/gtest.h>

#include "replay/replay_recorder.h"
#include "replay/replay_script.h"

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
    EXPECT_EQ(err("level a.map\n"), "h.replay:1: expected the header 'obscura-replay 1' first");
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
