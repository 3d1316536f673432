// obscura_signref end to end on tests/signref/levels/sign_room.map: a render compared with itself
// and with the all-zero frame, the edge and measure modes, and bad arguments failing clearly.
#include <gtest/gtest.h>

#include "core/pfm.h"
#include "map/map_compile.h"
#include "signs/sign_light.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

using namespace obscura;

namespace {
const std::string kLevel = std::string(OBSCURA_SOURCE_DIR) + "/tests/signref/levels/sign_room.map";

struct Result {
    int rc = -1;
    std::string out;  // stdout and stderr
};
Result run(const std::string& args) {
    Result r;
    const std::string cmd = std::string(OBSCURA_SIGNREF) + " " + args + " 2>&1";
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf;
    std::size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
    const int status = pclose(p);
    r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}
std::string temp(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("signref_cli_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}
double field(const std::string& line, const std::string& key) {
    const auto at = line.find(key + "=");
    return at == std::string::npos ? -1 : std::stod(line.substr(at + key.size() + 1));
}
// Looking at the sign from 4.5 m in front and below, through its shafts.
const std::string kView = "--level " + kLevel + " --pose '5 1.2 -3.5 0 25' --width 32 --height 18 --spp 1 --step 0.05 "
                          "--lamp-samples 4 --haze 0.05 --threads 2";
}  // namespace

TEST(SignrefCli, RendersAndComparesWithTheOffBaseline) {
    const std::string ref = temp("ref.pfm"), zero = temp("zero.pfm"), png = temp("ref.png");
    const Result a = run(kView + " --out " + ref + " --png " + png);
    ASSERT_EQ(a.rc, 0) << a.out;
    const FloatImage img = readPfm(ref);
    ASSERT_EQ(img.width, 32);
    ASSERT_EQ(img.height, 18);
    EXPECT_TRUE(std::filesystem::exists(png));
    writePfm(FloatImage{32, 18, std::vector<float>(32 * 18 * 3, 0.0f)}, zero);
    // the same render (deterministic) against itself and against no shafts
    const Result b = run(kView + " --compare " + ref + " --compare " + zero);
    ASSERT_EQ(b.rc, 0) << b.out;
    const auto l1 = b.out.find("signref rmse="), l2 = b.out.find("signref rmse=", l1 + 1);
    ASSERT_NE(l2, std::string::npos) << b.out;
    const std::string self = b.out.substr(l1, l2 - l1), off = b.out.substr(l2);
    EXPECT_EQ(field(self, "rmse"), 0.0) << self;
    EXPECT_GT(field(self, "rmse_off"), 0.0) << self;
    EXPECT_EQ(field(off, "rmse"), field(off, "rmse_off")) << off;
    EXPECT_EQ(field(off, "pixels"), 32 * 18);
    EXPECT_NE(off.find("channels=rgb file=" + zero), std::string::npos) << off;
    EXPECT_GT(field(off, "max_ref"), field(off, "mean_ref"));
}

TEST(SignrefCli, EdgeModeMeasuresTheLevelsSignAgainstThePenumbraLaws) {
    // A straight edge of the level's sign: the plate's own top edge, opened above the letters by a
    // bullet hole (radius 0.1 m, centred on it: over the penumbra's ~0.03 m footprint its rim is
    // far and the plate's edge straight). Receivers 1 m in front of the plate across its shadow.
    // The edge is 0.25 m above the lamp's axis, 0.3 m behind: seen 39 degrees off the normal, the
    // lamp's sphere casts a penumbra 1 / cos 39 = 1.29 x the law for a disc parallel to the plate.
    const map::Level level = map::loadLevel(kLevel);
    std::vector<std::string> warnings;
    const auto specs = signs::readSignLights(level, {"/usr/share/fonts/truetype/dejavu"}, warnings);
    ASSERT_EQ(specs.size(), 1u);
    const signs::SignSpec& s = specs[0];
    const double hh = signs::bakeMask(s, signs::maxPenumbraRadius(s)).halfHeight;
    const double a = 0.3, b = 1.0, scale = (a + b) / a;  // plate -> receiver, about the lamp (under the ceiling)
    auto receiver = [&](double y) {
        const Vec3 p = s.lamp + (s.up * y + s.facing * a) * scale;
        return std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z);
    };
    const Result r = run("--level " + kLevel + " --hole '0 0 " + std::to_string(hh) + " 0.1' --edge-from '" +
                         receiver(hh - 0.06) + "' --edge-to '" + receiver(hh + 0.06) + "' --edge-points 241 --lamp-samples 4096");
    ASSERT_EQ(r.rc, 0) << r.out;
    EXPECT_NEAR(field(r.out, "b"), b, 1e-5) << r.out;
    EXPECT_NEAR(field(r.out, "penumbra"), 2 * 0.03 * b / a, 1e-5) << r.out;
    EXPECT_NEAR(field(r.out, "cos_axis"), a / std::hypot(a, hh), 0.01) << r.out;
    EXPECT_NEAR(field(r.out, "ratio_sphere"), 1.0, 0.03) << r.out;
    EXPECT_NEAR(field(r.out, "ratio"), std::hypot(a, hh) / a, 0.05) << r.out;
}

TEST(SignrefCli, MeasuresAPfmProfile) {
    const std::string f = temp("ramp.pfm");
    FloatImage img{40, 4, {}};
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 40; ++x)
            for (int c = 0; c < 3; ++c) img.rgb.push_back(x < 10 ? 0.0f : (x >= 30 ? 1.0f : (x - 9.5f) / 20.0f));
    writePfm(img, f);
    const Result r = run("--measure-pfm " + f + " --from '0 2' --to '40 2'");
    ASSERT_EQ(r.rc, 0) << r.out;
    EXPECT_NEAR(field(r.out, "width1090_px"), 16.0, 0.1) << r.out;
}

TEST(SignrefCli, BadArgumentsFailClearly) {
    struct Case {
        std::string args, message;
        int rc;
    };
    const std::vector<Case> cases = {
        {"--pose '1 2 3' --level " + kLevel + " --out x.pfm", "--pose needs 'x y z yaw pitch', got '1 2 3'", 2},
        {"--pose '0 1 0 0 0' --out x.pfm", "--level is required", 2},
        {"--level " + kLevel + " --out x.pfm", "--pose is required to render", 2},
        {"--level " + kLevel + " --pose '0 1 0 0 0'", "nothing to do: give --out, --png or --compare", 2},
        {"--level " + kLevel + " --pose '0 1 0 0 0' --out x.pfm --step 0", "--step must be a positive number of metres", 2},
        {"--level " + kLevel + " --pose '0 1 0 0 0' --out x.pfm --lamp-samples 0", "--lamp-samples must be at least 1", 2},
        {"--level " + kLevel + " --pose '0 1 0 0 0' --out x.pfm --frobnicate", "unrecognised option '--frobnicate'", 2},
        {"--level " + kLevel + " --pose '0 1 0 0 0' --out x.pfm --smoke /nonexistent/s.dump", "/nonexistent/s.dump: cannot open", 1},
        {"--level " + kLevel + " --pose '0 1 0 0 0' --compare /nonexistent/g.pfm", "/nonexistent/g.pfm: cannot open", 1},
        {"--level " + kLevel + " --pose '0 1 0 0 0' --out x.pfm --hole '3 0 0 0.1'", "--hole '3 0 0 0.1': sign 3", 2},
        {"--level " + kLevel + " --edge-from '0 0 0'", "edge mode needs both --edge-from and --edge-to", 2},
        {"--level " + kLevel + " --edge-from '0 0' --edge-to '1 1 1'", "--edge-from needs 3 numbers, got '0 0'", 2},
        {"--measure-pfm x.pfm", "--measure-pfm needs --from and --to", 2},
    };
    for (const auto& c : cases) {
        const Result r = run(c.args);
        EXPECT_EQ(r.rc, c.rc) << c.args << "\n" << r.out;
        EXPECT_NE(r.out.find(c.message), std::string::npos) << c.args << "\n" << r.out;
        EXPECT_NE(r.out.find("obscura_signref: "), std::string::npos) << r.out;
    }
}
