// Tests of the image comparison (engine_ext/imagecmp): metrics, heat map, PNG I/O, the HTML report
// and obscura_imgcompare's output and exit codes (run as a subprocess).
#include <gtest/gtest.h>

#include "core/rng.h"
#include "imagecmp/imagecmp.h"
#include "imagecmp/report.h"
#include "run_process.h"
#include "texgen/texgen.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace obscura;
using namespace obscura::imagecmp;

namespace {
// A textured test frame: a generated brick texture tiled over 256 x 160.
Image frame() {
    const Image tex = texgen::generateTexture("brick", 64);
    Image im{256, 160, std::vector<std::uint8_t>(256 * 160 * 4)};
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x)
            for (int c = 0; c < 4; ++c)
                im.rgba[static_cast<std::size_t>((y * im.width + x) * 4 + c)] = tex.rgba[static_cast<std::size_t>(((y % 64) * 64 + x % 64) * 4 + c)];
    return im;
}

Image shifted(const Image& a, int dx) {
    Image b = a;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 4; ++c)
                b.rgba[static_cast<std::size_t>((y * a.width + x) * 4 + c)] =
                    a.rgba[static_cast<std::size_t>((y * a.width + std::min(a.width - 1, x + dx)) * 4 + c)];
    return b;
}

Image blurred(const Image& a) {  // 3x3 box blur
    Image b = a;
    for (int y = 1; y + 1 < a.height; ++y)
        for (int x = 1; x + 1 < a.width; ++x)
            for (int c = 0; c < 3; ++c) {
                int s = 0;
                for (int j = -1; j <= 1; ++j)
                    for (int i = -1; i <= 1; ++i) s += a.rgba[static_cast<std::size_t>(((y + j) * a.width + x + i) * 4 + c)];
                b.rgba[static_cast<std::size_t>((y * a.width + x) * 4 + c)] = static_cast<std::uint8_t>(s / 9);
            }
    return b;
}

// Under a folder of this suite's own, so generic names (ref.png) cannot meet other suites' files.
std::string tempPath(const std::string& name) {
    const auto dir = std::filesystem::path(testing::TempDir()) / "obscura_imagecmp_test";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}
}  // namespace

TEST(ImageCompare, IdenticalImagesPass) {
    const Image a = frame();
    const Metrics m = compare(a, a);
    EXPECT_DOUBLE_EQ(m.ssim, 1.0);
    EXPECT_TRUE(std::isinf(m.psnr));
    EXPECT_EQ(m.maxChannelDiff, 0);
    EXPECT_EQ(m.pixelsOver, 0);
    EXPECT_TRUE(failures(m, Tolerance{}).empty());
}

TEST(ImageCompare, OnePixelChangeIsCountedButWithinTolerance) {
    const Image a = frame();
    Image b = a;
    b.rgba[(80 * 256 + 100) * 4] = static_cast<std::uint8_t>(255 - b.rgba[(80 * 256 + 100) * 4]);
    const Metrics m = compare(a, b);
    EXPECT_EQ(m.pixelsOver, 1);
    EXPECT_GT(m.maxChannelDiff, 16);
    EXPECT_GT(m.ssim, 0.999);
    Tolerance t;
    t.maxPixelsOver = 4;
    EXPECT_TRUE(failures(m, t).empty());
    EXPECT_EQ(failures(m, Tolerance{}).size(), 1u);  // zero changed pixels allowed by default
}

TEST(ImageCompare, OnePixelShiftFailsOnSsim) {
    const Image a = frame();
    const Metrics m = compare(a, shifted(a, 1));
    Tolerance t;
    t.maxPixelsOver = 1 << 30;  // judge on SSIM and PSNR only
    const auto f = failures(m, t);
    ASSERT_FALSE(f.empty());
    EXPECT_NE(f[0].find("SSIM"), std::string::npos) << f[0];
    EXPECT_LT(m.ssim, 0.95);
}

TEST(ImageCompare, BlurFailsOnSsim) {
    const Image a = frame();
    const Metrics m = compare(a, blurred(a));
    Tolerance t;
    t.maxPixelsOver = 1 << 30;
    const auto f = failures(m, t);
    ASSERT_FALSE(f.empty());
    EXPECT_NE(f[0].find("SSIM"), std::string::npos) << f[0];  // structure lost, colours close
    EXPECT_LT(m.ssim, 0.97);
}

TEST(ImageCompare, SizeMismatchThrows) {
    Image small{10, 10, std::vector<std::uint8_t>(400)};
    EXPECT_THROW(compare(frame(), small), ImageError);
}

TEST(ImageCompare, PngRoundTripAndErrors) {
    const Image a = frame();
    const std::string p = tempPath("roundtrip.png");
    writePng(a, p);
    const Image b = readPng(p);
    EXPECT_EQ(b.width, a.width);
    EXPECT_EQ(b.rgba, a.rgba);
    EXPECT_THROW(readPng(tempPath("missing.png")), ImageError);
    std::ofstream(tempPath("notpng.png")) << "hello";
    EXPECT_THROW(readPng(tempPath("notpng.png")), ImageError);
}

TEST(ImageCompare, ReportReferencesImagesThatExist) {
    const Image a = frame(), b = shifted(a, 2);
    writePng(a, tempPath("ref.png"));
    writePng(b, tempPath("act.png"));
    const Metrics m = compare(a, b);
    const std::string dir = tempPath("report");
    const std::string html = writeReport(dir, "demo", {{"view1", tempPath("ref.png"), tempPath("act.png"), m, {}, failures(m, {})}}, "ref-gl", "act-gl");
    std::ifstream in(html);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    for (const char* f : {"view1.reference.png", "view1.actual.png", "view1.diff.png"}) {
        EXPECT_NE(text.find(f), std::string::npos) << f;
        EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(dir) / f)) << f;
    }
    EXPECT_NE(text.find("FAIL"), std::string::npos);
}

TEST(ImageCompare, ToolExitCodes) {
    const Image a = frame();
    writePng(a, tempPath("t_a.png"));
    writePng(shifted(a, 1), tempPath("t_b.png"));
    const std::string tool = OBSCURA_IMGCOMPARE;
    auto run = [&](const std::string& args) {
        const int rc = std::system((tool + " " + args + " > /dev/null 2>&1").c_str());
        return WEXITSTATUS(rc);
    };
    EXPECT_EQ(run(tempPath("t_a.png") + " " + tempPath("t_a.png")), 0);
    EXPECT_EQ(run(tempPath("t_a.png") + " " + tempPath("t_b.png") + " --max-pixels-over 100000"), 1);
    EXPECT_EQ(run(tempPath("t_a.png") + " " + tempPath("nope.png")), 2);
    EXPECT_EQ(run("--bogus"), 2);
}

TEST(ImageCompare, MalformedImagesThrowInsteadOfReadingPastTheEnd) {
    const Image a = frame();
    Image shortData = a;
    shortData.rgba.resize(100);
    EXPECT_THROW(compare(a, shortData), ImageError);
    EXPECT_THROW(compare(shortData, a), ImageError);
    EXPECT_THROW(diffHeatmap(a, shortData), ImageError);
    const Image empty;
    EXPECT_THROW(compare(empty, empty), ImageError);
    try {
        compare(a, Image{10, 20, std::vector<std::uint8_t>(800)});
        ADD_FAILURE() << "no exception";
    } catch (const ImageError& e) {
        EXPECT_STREQ(e.what(), "image sizes differ: 256x160 vs 10x20");
    }
}

TEST(ImageCompare, HeatmapIsBlackWhereEqualAndBrightWhereChanged) {
    const Image a = frame();
    Image b = a;
    const std::size_t changed = (10 * 256 + 20) * 4;
    b.rgba[changed + 1] = static_cast<std::uint8_t>(b.rgba[changed + 1] ^ 0x80);  // green off by 128
    const Image h = diffHeatmap(a, b, 8);
    ASSERT_EQ(h.rgba.size(), a.rgba.size());
    long lit = 0;
    for (std::size_t i = 0; i < h.rgba.size(); i += 4) lit += h.rgba[i] != 0 || h.rgba[i + 1] != 0 || h.rgba[i + 2] != 0;
    EXPECT_EQ(lit, 1);
    EXPECT_EQ(h.rgba[changed], 255);  // 128 x 8 saturates to white
    EXPECT_EQ(h.rgba[changed + 2], 255);
    EXPECT_THROW(diffHeatmap(a, b, -1), ImageError);
}

TEST(ImageCompare, ReportFileNamesAreSafeAndRelative) {
    const Image a = frame();
    writePng(a, tempPath("same.png"));
    const std::string dir = tempPath("report_odd");
    const Metrics m = compare(a, a);
    const std::string html = writeReport(dir, "odd <name>", {{"../x y", tempPath("same.png"), tempPath("same.png"), m, {}, {}}});
    std::ifstream in(html);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    for (const char* f : {"___x_y.reference.png", "___x_y.actual.png", "___x_y.diff.png"}) {
        EXPECT_NE(text.find(std::string("src=\"") + f + "\""), std::string::npos) << f;
        EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(dir) / f)) << f;
    }
    EXPECT_NE(text.find("odd &lt;name&gt;"), std::string::npos);
    EXPECT_EQ(text.find("FAIL"), std::string::npos);  // identical: passes
    EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(dir).parent_path() / "x y.reference.png"));
}

TEST(ImageCompare, ToolPrintsMetricsFailedMetricAndReportPath) {
    using obscura::testing_support::runProcess;
    const Image a = frame();
    writePng(a, tempPath("p_a.png"));
    writePng(blurred(a), tempPath("p_b.png"));
    const std::string tool = OBSCURA_IMGCOMPARE;
    const auto same = runProcess(tool + " " + tempPath("p_a.png") + " " + tempPath("p_a.png"));
    EXPECT_EQ(same.code, 0) << same.out;
    EXPECT_EQ(same.out, "ssim=1.00000 psnr=inf maxdiff=0 over=0\n");

    const std::string dir = tempPath("tool_report");
    const auto blur = runProcess(tool + " " + tempPath("p_a.png") + " " + tempPath("p_b.png") +
                                 " --max-pixels-over 1000000 --report " + dir + " --name blur");
    EXPECT_EQ(blur.code, 1) << blur.out;
    EXPECT_EQ(blur.out.rfind("ssim=0.", 0), 0u) << blur.out;
    EXPECT_NE(blur.out.find("FAIL: SSIM"), std::string::npos) << blur.out;
    EXPECT_EQ(blur.out.find("FAIL: max channel"), std::string::npos) << blur.out;  // 255 allowed by default
    EXPECT_NE(blur.out.find("report: " + dir + "/report.html"), std::string::npos) << blur.out;
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(dir) / "blur.diff.png"));

    // Loose enough limits pass the same pair.
    EXPECT_EQ(runProcess(tool + " " + tempPath("p_a.png") + " " + tempPath("p_b.png") +
                         " --min-ssim 0 --min-psnr 0 --max-pixels-over 1000000").code, 0);
    for (const char* bad : {"--pixel-threshold 300", "--min-ssim 2", "--max-pixels-over -1", "--min-ssim abc", "extra.png"}) {
        const auto r = runProcess(tool + " " + tempPath("p_a.png") + " " + tempPath("p_a.png") + " " + bad);
        EXPECT_EQ(r.code, 2) << bad << "\n" << r.out;
    }
    const auto missing = runProcess(tool + " " + tempPath("p_a.png") + " " + tempPath("absent.png"));
    EXPECT_EQ(missing.code, 2);
    EXPECT_NE(missing.out.find(tempPath("absent.png") + ": cannot open PNG"), std::string::npos) << missing.out;
}
