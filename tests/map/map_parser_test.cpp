#include <gtest/gtest.h>

#include "map/map_parser.h"

using namespace obscura::map;

namespace {
std::string errorOf(const std::string& text) {
    try {
        parseMap(text, "t.map");
    } catch (const MapError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(MapParser, QuakeAndValveFacesCommentsAndQuotedValues) {
    const char* text = R"(// Game: Quake
// Format: Valve
{
"classname" "worldspawn"
"message" "Hounds of \"The\" Depths"  // trailing comment
{
( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) *water1 [ 1 0 0 16 ] [ 0 -1 0 -8 ] 15 0.5 2
( 0 0 64 ) ( 1 0 64 ) ( 0 1 64 ) base_floor 4 8 90 1 1
}
}
{
"classname" "light"
"origin" "10 -20 30.5"
}
)";
    const MapFile m = parseMap(text, "t.map");
    ASSERT_EQ(m.entities.size(), 2u);
    EXPECT_EQ(m.entities[0].value("classname"), "worldspawn");
    EXPECT_EQ(m.entities[0].value("message"), "Hounds of \"The\" Depths");
    ASSERT_EQ(m.entities[0].brushes.size(), 1u);
    const auto& f = m.entities[0].brushes[0].faces;
    ASSERT_EQ(f.size(), 2u);
    EXPECT_TRUE(f[0].valve220);
    EXPECT_EQ(f[0].texture, "*water1");
    EXPECT_DOUBLE_EQ(f[0].uOffset, 16);
    EXPECT_DOUBLE_EQ(f[0].vAxis.y, -1);
    EXPECT_DOUBLE_EQ(f[0].vOffset, -8);
    EXPECT_DOUBLE_EQ(f[0].rotation, 15);
    EXPECT_DOUBLE_EQ(f[0].uScale, 0.5);
    EXPECT_EQ(f[0].pos.line, 7);
    EXPECT_FALSE(f[1].valve220);
    EXPECT_DOUBLE_EQ(f[1].uOffset, 4);
    EXPECT_DOUBLE_EQ(f[1].rotation, 90);
    EXPECT_DOUBLE_EQ(f[1].points[0].z, 64);
    EXPECT_EQ(m.entities[1].value("origin"), "10 -20 30.5");
    EXPECT_EQ(m.entities[1].pos.line, 11);
}

TEST(MapParser, ErrorsNameFileLineAndColumn) {
    // Missing ')' after the first point of the face on line 3: the lexer finds '(' at column 9.
    EXPECT_EQ(errorOf("{\n{\n( 0 0 0 ( 0 1 0 ) ( 1 0 0 ) tex 0 0 0 1 1\n}\n}\n"),
              "t.map:3:9: expected ')' to close a face point, found '('");
    EXPECT_EQ(errorOf("{\n\"classname\" \"worldspawn\n}\n"), "t.map:2:13: unterminated string (newline inside quotes)");
    EXPECT_NE(errorOf("{\n{\n( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) tex 0 0 0 1 1\n").find("unexpected end of file inside the brush opened at line 2"),
              std::string::npos);
    EXPECT_EQ(errorOf("{\n{\n( 0 0 zero ) ( 0 1 0 ) ( 1 0 0 ) tex 0 0 0 1 1\n}\n}\n"),
              "t.map:3:7: 'zero' is not a number (z coordinate)");
    EXPECT_EQ(errorOf("}\n"), "t.map:1:1: expected '{' to open an entity, found '}'");
    EXPECT_EQ(errorOf("{\n\"a\" \"b\"\nfoo\n}\n"), "t.map:3:1: expected '\"', '{' or '}' in an entity, found 'f'");
    EXPECT_NE(errorOf("{\n\"a\" \"b\"\n").find("unexpected end of file inside the entity opened at line 1"), std::string::npos);
}

TEST(MapParser, SkipsQuake3PatchesWithAWarning) {
    const MapFile m = parseMap("{\n\"classname\" \"worldspawn\"\n{\npatchDef2\n{\nfoo\n( ( 1 2 ) )\n}\n}\n}\n", "t.map");
    ASSERT_EQ(m.entities.size(), 1u);
    EXPECT_TRUE(m.entities[0].brushes.empty());
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_NE(m.warnings[0].find("t.map:4: skipped unsupported 'patchDef2'"), std::string::npos);
}

TEST(MapParser, MissingFileIsAClearError) {
    try {
        loadMapFile("/nonexistent/level.map");
        FAIL();
    } catch (const MapError& e) {
        EXPECT_EQ(std::string(e.what()), "/nonexistent/level.map: cannot open map file (No such file or directory)");
    }
}

TEST(MapParser, MoreErrorsWithPositions) {
    // A quote never closed before the end of the file: reported where the string opens.
    EXPECT_EQ(errorOf("{\n\"classname\" \"worldsp"), "t.map:2:13: unterminated string");
    // A bad number among the texture parameters (the x scale, column 41).
    EXPECT_EQ(errorOf("{\n{\n( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) tex 0 0 0 1.5.2 1\n}\n}\n"),
              "t.map:3:41: '1.5.2' is not a number (x scale)");
    // Infinity and NaN are not coordinates.
    EXPECT_EQ(errorOf("{\n{\n( inf 0 0 ) ( 0 1 0 ) ( 1 0 0 ) tex 0 0 0 1 1\n}\n}\n"),
              "t.map:3:3: 'inf' is not a number (x coordinate)");
    EXPECT_EQ(errorOf("{\n{\n( 0 0 0 ) ( 0 1 0 ) ( 1 0 nan ) tex 0 0 0 1 1\n}\n}\n"),
              "t.map:3:27: 'nan' is not a number (z coordinate)");
    // A Valve-220 axis missing its closing bracket.
    EXPECT_EQ(errorOf("{\n{\n( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) tex [ 1 0 0 0 [ 0 -1 0 0 ] 0 1 1\n}\n}\n"),
              "t.map:3:45: expected ']' to close the u axis, found '['");
    // The file ends inside a brush, right after a complete face.
    EXPECT_EQ(errorOf("{\n\"classname\" \"worldspawn\"\n{\n( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) tex 0 0 0 1 1\n"),
              "t.map:5:1: unexpected end of file inside the brush opened at line 3");
    // ... or inside a face.
    EXPECT_EQ(errorOf("{\n{\n( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) tex 0 0"),
              "t.map:3:38: unexpected end of file, expected rotation");
}

TEST(MapParser, EscapedQuotesAndBackslashes) {
    const MapFile m = parseMap(
        "{\n"
        "\"a\" \"say \\\"hi\\\" now\"\n"      // "say \"hi\" now" -> say "hi" now
        "\"wad\" \"c:\\quake\\\"\n"              // ends in a backslash: the quote still closes
        "\"b\" \"x\\\\\" \"c\" \"y\"\n"      // "x\\" : an even run of backslashes, then the quote
        "}\n",
        "t.map");
    ASSERT_EQ(m.entities.size(), 1u);
    const MapEntity& e = m.entities[0];
    EXPECT_EQ(e.value("a"), "say \"hi\" now");
    EXPECT_EQ(e.value("wad"), "c:\\quake\\");
    EXPECT_EQ(e.value("b"), "x\\\\");
    EXPECT_EQ(e.value("c"), "y");
    EXPECT_TRUE(e.has("c"));
    EXPECT_FALSE(e.has("d"));
}

TEST(MapParser, TextureNamesWithSymbolsAndQuotes) {
    const MapFile m = parseMap(
        "{\n{\n"
        "( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) +0slipbot 0 0 0 1 1\n"
        "( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) common/clip-2.x 0 0 0 1 1\n"
        "( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) \"my tex\" 0 0 0 1 1\n"
        "( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) {fence 1e-05 -2.5E1 +90 1 1\n"
        "}\n}\n",
        "t.map");
    const auto& f = m.entities.at(0).brushes.at(0).faces;
    ASSERT_EQ(f.size(), 4u);
    EXPECT_EQ(f[0].texture, "+0slipbot");
    EXPECT_EQ(f[1].texture, "common/clip-2.x");
    EXPECT_EQ(f[2].texture, "my tex");
    EXPECT_EQ(f[3].texture, "{fence");
    EXPECT_DOUBLE_EQ(f[3].uOffset, 1e-05);
    EXPECT_DOUBLE_EQ(f[3].vOffset, -25);
    EXPECT_DOUBLE_EQ(f[3].rotation, 90);
}

TEST(MapParser, SkipsQuake3BrushDefWithAWarning) {
    const MapFile m = parseMap(
        "{\n\"classname\" \"worldspawn\"\n{\nbrushDef\n{\n( 0 0 1 0 ) ( ( 1 0 0 ) ( 0 1 0 ) ) tex 0 0 0\n}\n}\n"
        "{\n( 0 0 0 ) ( 0 1 0 ) ( 1 0 0 ) tex 0 0 0 1 1\n}\n}\n",
        "t.map");
    ASSERT_EQ(m.entities.size(), 1u);
    EXPECT_EQ(m.entities[0].brushes.size(), 1u);  // the ordinary brush after it still parses
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_NE(m.warnings[0].find("t.map:4: skipped unsupported 'brushDef'"), std::string::npos) << m.warnings[0];
}
