// The files tools/signref reads and writes: PFM (core/pfm.h) and the game's smoke dump
// (smoke/smoke_dump.h): round trips, the layouts byte for byte, and malformed files rejected with
// the file and the problem named.
#include <gtest/gtest.h>

#include "core/pfm.h"
#include "smoke/smoke_dump.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace obscura;

namespace {
std::string tempPath(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("signref_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}
std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}
void spit(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
}
std::string floats(std::initializer_list<float> v) {
    std::string s(v.size() * 4, '\0');
    std::memcpy(s.data(), std::data(v), s.size());  // little-endian host (x86, arm64)
    return s;
}
// The message of what `f` throws, or "" when it does not.
template <class F>
std::string thrown(F&& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(SignrefPfm, RoundTripAndTheLayout) {
    FloatImage img{3, 2, {}};
    for (int i = 0; i < 18; ++i) img.rgb.push_back(static_cast<float>(i) * 0.5f - 1.0f);
    const std::string path = tempPath("a.pfm");
    writePfm(img, path);
    const std::string bytes = slurp(path);
    const std::string header = "PF\n3 2\n-1.0\n";
    ASSERT_EQ(bytes.size(), header.size() + 18 * 4);
    EXPECT_EQ(bytes.substr(0, header.size()), header);
    // rows bottom to top: the file's first pixel is the image's bottom-left (index 3 of top-first)
    float first;
    std::memcpy(&first, bytes.data() + header.size(), 4);
    EXPECT_EQ(first, img.rgb[9]);
    const FloatImage back = readPfm(path);
    EXPECT_EQ(back.width, 3);
    EXPECT_EQ(back.height, 2);
    EXPECT_EQ(back.rgb, img.rgb);
}

TEST(SignrefPfm, ReadsGreyAndBigEndian) {
    const std::string path = tempPath("grey.pfm");
    std::string data = floats({1.5f, -2.0f});  // a 1x2 grey image, bottom row first
    for (std::size_t i = 0; i < data.size(); i += 4) std::swap(data[i], data[i + 3]), std::swap(data[i + 1], data[i + 2]);
    spit(path, "Pf\n1 2\n1.0\n" + data);  // scale > 0: big-endian
    const FloatImage img = readPfm(path);
    ASSERT_EQ(img.rgb.size(), 6u);
    EXPECT_EQ(img.rgb[0], -2.0f);  // top
    EXPECT_EQ(img.rgb[2], -2.0f);
    EXPECT_EQ(img.rgb[3], 1.5f);   // bottom
}

TEST(SignrefPfm, MalformedFilesAreNamed) {
    const std::string path = tempPath("bad.pfm");
    spit(path, "P6\n1 1\n255\nabc");
    EXPECT_NE(thrown([&] { readPfm(path); }).find(path + ": not a PFM"), std::string::npos);
    spit(path, "PF\n2 2\n-1.0\n" + floats({1, 2, 3}));
    EXPECT_NE(thrown([&] { readPfm(path); }).find(path + ": PFM data ends after 12 of 48 bytes"), std::string::npos);
    spit(path, "PF\n2 x\n-1.0\n");
    EXPECT_NE(thrown([&] { readPfm(path); }).find(path + ": bad PFM header"), std::string::npos);
    EXPECT_NE(thrown([&] { readPfm(tempPath("missing.pfm")); }).find("missing.pfm: cannot open"), std::string::npos);
}

namespace {
smoke::SmokeDump sampleDump() {
    smoke::SmokeDump d;
    d.time = 12.25;
    d.sigma = 6.5;
    smoke::DumpVolume a;
    a.nx = 3, a.ny = 2, a.nz = 2;
    a.origin = {-1.5, 0.25, 3};
    a.cellSize = 0.25;
    for (int i = 0; i < 12; ++i) a.density.push_back(static_cast<float>(i) * 0.1f);
    smoke::DumpVolume b;
    b.nx = b.ny = b.nz = 1;
    b.origin = {0, 0, 0};
    b.cellSize = 0.5;
    b.density = {2.0f};
    d.volumes = {a, b};
    return d;
}
std::string dumpText(const smoke::SmokeDump& d) {
    std::ostringstream os;
    smoke::writeSmokeDump(d, os);
    return os.str();
}
std::string readError(const std::string& text) {
    std::istringstream in(text);
    return thrown([&] { smoke::readSmokeDump(in, "s.dump"); });
}
}  // namespace

TEST(SignrefSmokeDump, RoundTripAndTheFormat) {
    const smoke::SmokeDump d = sampleDump();
    const std::string path = tempPath("a.dump");
    smoke::writeSmokeDump(d, path);
    const std::string bytes = slurp(path);
    const std::string head = "obscura-smoke-dump 1\ntime 12.25 sigma 6.5\nvolumes 2\nvolume 3 2 2 -1.5 0.25 3 0.25\n";
    ASSERT_GT(bytes.size(), head.size());
    EXPECT_EQ(bytes.substr(0, head.size()), head);
    EXPECT_EQ(bytes.substr(head.size(), 8), floats({0.0f, 0.1f}));  // x fastest, right after the newline
    EXPECT_EQ(bytes.substr(head.size() + 48, 23), "volume 1 1 1 0 0 0 0.5\n");
    const smoke::SmokeDump back = smoke::readSmokeDump(path);
    EXPECT_EQ(back.time, d.time);
    EXPECT_EQ(back.sigma, d.sigma);
    ASSERT_EQ(back.volumes.size(), 2u);
    EXPECT_EQ(back.volumes[0].density, d.volumes[0].density);
    EXPECT_EQ(back.volumes[0].origin, d.volumes[0].origin);
    EXPECT_EQ(back.volumes[1].density, d.volumes[1].density);
}

TEST(SignrefSmokeDump, DensityIsTrilinearBetweenCellCentres) {
    const smoke::DumpVolume v = sampleDump().volumes[0];  // cell (i, j, k) = 0.1 (i + 3 j + 6 k)
    auto centre = [&](double i, double j, double k) { return v.origin + Vec3{i + 0.5, j + 0.5, k + 0.5} * v.cellSize; };
    EXPECT_NEAR(v.densityAt(centre(1, 1, 0)), 0.4, 1e-6);
    EXPECT_NEAR(v.densityAt(centre(1.5, 0.5, 0.5)), 0.1 * (1.5 + 1.5 + 3), 1e-6);
    EXPECT_NEAR(v.densityAt(centre(2.4, 0, 0)), 0.2, 1e-6);  // clamped past the last centre
    EXPECT_EQ(v.densityAt(centre(3.1, 0, 0)), 0.0);          // outside the grid's box
    EXPECT_EQ(v.densityAt(centre(0, -0.6, 0)), 0.0);
}

TEST(SignrefSmokeDump, MalformedFilesNameTheFileAndTheProblem) {
    const std::string good = dumpText(sampleDump());
    EXPECT_EQ(readError(good), "");
    EXPECT_EQ(readError("obscura-smoke-dump 2\n"), "s.dump:1: not a smoke dump (the first line must be 'obscura-smoke-dump 1')");
    EXPECT_EQ(readError("obscura-smoke-dump 1\ntime 1 sigmas 2\nvolumes 0\n"), "s.dump:2: expected 'time <seconds> sigma <per metre>'");
    EXPECT_EQ(readError("obscura-smoke-dump 1\ntime 1 sigma -2\nvolumes 0\n"),
              "s.dump:2: time must be finite and sigma finite and not negative");
    EXPECT_EQ(readError("obscura-smoke-dump 1\ntime 1 sigma 2\nvolumes -1\n"), "s.dump:3: expected 'volumes <N>' with 0 <= N <= 1024");
    EXPECT_EQ(readError("obscura-smoke-dump 1\ntime 1 sigma 2\nvolumes 1\n"),
              "s.dump:3: the file ends where 'volume nx ny nz ox oy oz cell' (volume 1 of 1) was expected");
    EXPECT_EQ(readError("obscura-smoke-dump 1\ntime 1 sigma 2\nvolumes 1\nvolume 0 1 1 0 0 0 0.25\n"),
              "s.dump:4: volume 1 of 1: bad grid size 0x1x1");
    EXPECT_EQ(readError("obscura-smoke-dump 1\ntime 1 sigma 2\nvolumes 1\nvolume 1 1 1 0 0 0 0\n" + floats({1})),
              "s.dump:4: volume 1 of 1: the origin must be finite and the cell size positive");
    EXPECT_EQ(readError("obscura-smoke-dump 1\ntime 1 sigma 2\nvolumes 1\nvolume 2 1 1 0 0 0 0.25\n" + floats({1})),
              "s.dump:4: volume 1 of 1: the densities end after 4 of 8 bytes");
    EXPECT_EQ(readError(good.substr(0, good.size() - 2)), "s.dump:5: volume 2 of 2: the densities end after 2 of 4 bytes");
    EXPECT_EQ(readError(good + "x"), "s.dump:5: data after the last volume (the header said 2)");
    EXPECT_EQ(readError("obscura-smoke-dump 1\ntime 1 sigma 2\nvolumes 1\nvolume 1 1 1 0 0 0 0.25\n" + floats({NAN})),
              "s.dump:4: volume 1 of 1: a density is not finite");
    EXPECT_NE(thrown([] { smoke::readSmokeDump(tempPath("none.dump")); }).find("none.dump: cannot open"), std::string::npos);
}
