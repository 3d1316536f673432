// The committed TrenchBroom FGD against the entity-class registry: read with the FGD reader and
// compared both ways (every registry class with every key, every FGD class known), the file equal
// to what writeFgd makes now, and the comparison shown to fail on doctored files.
#include <gtest/gtest.h>

#include "map/entity_classes.h"
#include "map/fgd.h"
#include "map/map_parser.h"

#include <fstream>
#include <sstream>

namespace obscura::map {
namespace {

const std::string kFgdPath = OBSCURA_SOURCE_DIR "/tools/trenchbroom/obscura/obscura.fgd";

std::string committedText() {
    std::ifstream in(kFgdPath, std::ios::binary);
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
}

std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
}

bool mentions(const std::vector<std::string>& lines, const std::string& what) {
    for (const auto& l : lines)
        if (l.find(what) != std::string::npos) return true;
    return false;
}

// The committed text with the first occurrence of `from` replaced by `to` (the test fails loudly
// if the text to doctor is not there).
std::string doctored(const std::string& from, const std::string& to) {
    std::string s = committedText();
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << "'" << from << "' not in the FGD";
    if (at != std::string::npos) s.replace(at, from.size(), to);
    return s;
}

TEST(Fgd, CommittedFileAgreesWithTheRegistryBothWays) {
    const FgdFile fgd = loadFgdFile(kFgdPath);
    const std::vector<std::string> diff = compareFgd(fgd, entityClasses());
    EXPECT_TRUE(diff.empty()) << joined(diff);
    // And it is really read: every registry class is there with its kind and its keys.
    for (const EntityClass& c : entityClasses()) {
        const FgdClass* f = fgd.find(c.name);
        ASSERT_NE(f, nullptr) << c.name;
        EXPECT_EQ(f->kind, c.kind == EntityKind::Point ? "PointClass" : "SolidClass");
        EXPECT_EQ(fgd.resolvedProperties(*f).size(), allKeys(c).size()) << c.name;
    }
}

TEST(Fgd, CommittedFileIsTheGeneratorsCurrentOutput) {
    EXPECT_EQ(committedText(), writeFgd(keyGroups(), entityClasses()))
        << kFgdPath << " is stale: run `cmake --build build --target update_fgd` and commit it";
}

TEST(Fgd, ReaderTakesBasesSizesColoursChoicesFlagsAndContinuations) {
    const FgdFile f = parseFgd(
        "// comment\n"
        "@BaseClass = Named [ targetname(target_source) : \"Name\" ]\n"
        "@PointClass base(Named) size(-8 -8 -8, 8 8 8) color(255 0 0) model({ \"path\": \"a.mdl\" }) = thing : \"A \" + \"thing\"\n"
        "[\n"
        "  count(integer) : \"Count\" : 3 : \"long text\"\n"
        "  speed(float) readonly : \"Speed\" : \"1.5\"\n"
        "  empty(string) : : \"x\"\n"
        "  sounds(choices) : \"Sounds\" : 1 = [ 0 : \"None\" 1 : \"Some\" ]\n"
        "  spawnflags(flags) = [ 1 : \"A\" : 0  4 : \"B\" : 1 : \"long\" ]\n"
        "]\n",
        "x.fgd");
    ASSERT_EQ(f.classes.size(), 2u);
    const FgdClass& t = f.classes[1];
    EXPECT_EQ(t.name, "thing");
    EXPECT_EQ(t.description, "A thing");
    EXPECT_EQ(t.size, "-8 -8 -8, 8 8 8");
    EXPECT_EQ(t.colour, "255 0 0");
    EXPECT_EQ(t.model, "{ \"path\": \"a.mdl\" }");
    EXPECT_EQ(t.line, 3);
    const auto props = f.resolvedProperties(t);
    ASSERT_EQ(props.size(), 6u);
    EXPECT_EQ(props[0].name, "targetname");
    EXPECT_EQ(props[1].defaultValue, "3");
    EXPECT_EQ(props[2].defaultValue, "1.5");
    EXPECT_EQ(props[3].description, "");
    EXPECT_EQ(props[3].defaultValue, "x");
    EXPECT_EQ(props[4].choices.size(), 2u);
    EXPECT_EQ(props[4].defaultValue, "1");
    EXPECT_EQ(props[5].defaultValue, "4");  // the bits marked on
    EXPECT_EQ(props[5].line, 9);
}

TEST(Fgd, MalformedFilesNameTheirLine) {
    const auto error = [](const std::string& text) {
        try {
            const FgdFile f = parseFgd(text, "bad.fgd");
            for (const auto& c : f.classes) f.resolvedProperties(c);
        } catch (const MapError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error("@PointClass = a [\n  b(string) : \"x\n]\n"), "bad.fgd:2: string not closed on its line");
    EXPECT_EQ(error("\n\nPointClass = a []"), "bad.fgd:3: expected @Class, got 'PointClass'");
    EXPECT_EQ(error("@PointClass base(Nope) = a []"), "bad.fgd:1: a's base 'Nope' is not defined");
    EXPECT_EQ(error("@PointClass = a [\n b(integer) : \"x\" : 1\n"), "bad.fgd:3: expected a property name or ']', got end of file");
}

TEST(Fgd, ComparisonFailsForAMissingClass) {
    const FgdFile f = parseFgd(doctored("= prop_barrel :", "= prop_keg :"), "doctored.fgd");
    const std::vector<std::string> diff = compareFgd(f, entityClasses());
    EXPECT_TRUE(mentions(diff, "doctored.fgd: class 'prop_barrel' (point) is missing")) << joined(diff);
    EXPECT_TRUE(mentions(diff, "class 'prop_keg' is not one the game knows")) << joined(diff);
}

TEST(Fgd, ComparisonFailsForAMissingOrExtraOrChangedKey) {
    {  // target_moving loses 'distance'
        const std::string from = "\tdistance(float)";
        std::string text = committedText();
        const auto at = text.find(from);
        ASSERT_NE(at, std::string::npos);
        text.erase(at, text.find('\n', at) + 1 - at);
        const auto diff = compareFgd(parseFgd(text, "d.fgd"), entityClasses());
        EXPECT_TRUE(mentions(diff, "target_moving lacks key 'distance'")) << joined(diff);
    }
    {  // a key the game does not read
        const auto diff = compareFgd(parseFgd(doctored("\tmass(float)", "\tcolour(string) : \"x\"\n\tmass(float)"), "d.fgd"), entityClasses());
        EXPECT_TRUE(mentions(diff, "prop_crate key 'colour' is not in the registry")) << joined(diff);
    }
    {  // a default that is not the game's
        const auto diff = compareFgd(parseFgd(doctored(": \"Edge length, metres (0.05 to 10)\" : \"0.75\"",
                                                       ": \"Edge length, metres (0.05 to 10)\" : \"1\""),
                                              "d.fgd"),
                                     entityClasses());
        EXPECT_TRUE(mentions(diff, "prop_crate key 'size': default '1', the registry has '0.75'")) << joined(diff);
    }
    {  // a class of the wrong kind
        const auto diff = compareFgd(parseFgd(doctored("@SolidClass = func_wall", "@PointClass = func_wall"), "d.fgd"), entityClasses());
        EXPECT_TRUE(mentions(diff, "func_wall is @PointClass, the registry has a brush class")) << joined(diff);
    }
}

TEST(Fgd, WriterRefusesAQuoteInADescription) {
    EntityClass c;
    c.name = "x";
    c.description = "say \"hi\"";
    EXPECT_THROW(writeFgd({}, {c}), std::invalid_argument);
}

}  // namespace
}  // namespace obscura::map
