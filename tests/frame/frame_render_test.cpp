// The frame pipeline in the real game, headless: each pass fails alone with one clear line and
// the rest of the frame keeps drawing; a GPU with 2 render targets draws the same picture in two
// scene passes; every AO mode and the smoke pass set only uniforms their programs declare.
#include <gtest/gtest.h>

#include "core/image.h"
#include "run_process.h"
#include "ssao/ssao_modes.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using obscura::testing_support::ProcessResult;

namespace {
// The courtyard's east end with a smoke cloud released at the low wall: G-buffer, AO, lighting,
// volumetrics and output all have something to do in this view.
const char* const kView = "--start-pose '26 1.65 -24 -30 -10' --smoke-at '27 0.5 -30'";

ProcessResult game(const std::string& args) {
    return obscura::testing_support::runProcess(std::string("'" OBSCURA_GAME "' --headless --ticks 40 --width 320 "
                                                            "--height 180 --hud off ") + kView + " " + args);
}

std::string shot(const std::string& name) { return (fs::path(testing::TempDir()) / ("frame_" + name + ".png")).string(); }

obscura::Image render(const std::string& name, const std::string& args, ProcessResult* result = nullptr) {
    const ProcessResult r = game(args + " --screenshot " + shot(name));
    EXPECT_EQ(r.code, 0) << r.out;
    if (result) *result = r;
    return obscura::readPng(shot(name));
}

std::size_t differing(const obscura::Image& a, const obscura::Image& b, int tolerance) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) n += std::abs(int(a.rgba[i]) - int(b.rgba[i])) > tolerance;
    return n;
}

// Lines the frame printed about stages it turned off.
std::size_t offLines(const std::string& out) {
    std::size_t n = 0;
    for (std::size_t at = out.find("stage ("); at != std::string::npos; at = out.find("stage (", at + 1)) ++n;
    return n;
}
}  // namespace

TEST(FrameRender, EveryModeAndPassSetsOnlyUniformsItsProgramDeclares) {
    // The load-time check turns a stage off with a line when the C++ sets a name its program lacks.
    for (const auto& mode : obscura::ssao::modeNames()) {
        ProcessResult r;
        render("mode_" + mode, "--ssao " + mode, &r);
        EXPECT_EQ(offLines(r.out), 0u) << mode << ":\n" << r.out;
    }
}

TEST(FrameRender, RenamedUniformTurnsOffItsStageWithTheMaterialAndNameAndTheFrameGoesOn) {
    // A copy of the data folder whose AO shaders call the radius uniform something else, everywhere
    // (they compile; only the C++ still says "radius").
    const fs::path data = fs::path(testing::TempDir()) / "frame_renamed_data";
    fs::remove_all(data);
    fs::create_directories(data);
    for (const char* dir : {"media", "shaders"})
        fs::copy(fs::path(OBSCURA_SOURCE_DIR) / dir, data / dir, fs::copy_options::recursive);
    std::size_t renamed = 0;
    for (const auto& file : fs::directory_iterator(data / "shaders/ssao")) {
        std::stringstream text;
        text << std::ifstream(file.path()).rdbuf();
        const std::string glsl = text.str();
        const std::string changed = std::regex_replace(glsl, std::regex("\\bradius\\b"), "aoRadius");
        renamed += changed != glsl;
        std::ofstream(file.path()) << changed;
    }
    ASSERT_GT(renamed, 0u) << "the test no longer matches shaders/ssao";

    ProcessResult r;
    const obscura::Image image = render("renamed", "--ssao horizon --data-dir '" + data.string() + "'", &r);
    EXPECT_NE(r.out.find("obscura: frame: the AO stage (engine_ext/ssao) is off: its program does not declare the "
                         "uniform(s) the C++ sets: material Obscura/SSAO/Horizon has no parameter 'radius'"),
              std::string::npos) << r.out;
    EXPECT_EQ(offLines(r.out), 1u) << r.out;
    // The rest of the frame: the picture without AO, smoke included.
    const obscura::Image off = render("renamed_off", "--ssao off");
    EXPECT_EQ(differing(image, off, 0), 0u);
}

TEST(FrameRender, ThreeRenderTargetsDrawTheSamePictureInTwoScenePassesSmokeIncluded) {
    for (const std::string mode : {"off", "horizon"}) {
        ProcessResult r;
        const obscura::Image two = render("three_" + mode, "--ssao " + mode + " --debug-max-render-targets 3", &r);
        EXPECT_NE(r.out.find("obscura: frame: the G-buffer is drawn in two passes (this GPU has 3 simultaneous render "
                             "targets, one pass needs 5)"), std::string::npos) << r.out;
        EXPECT_EQ(offLines(r.out), 0u) << r.out;
        const obscura::Image four = render("four_" + mode, "--ssao " + mode);
        EXPECT_EQ(differing(two, four, 0), 0u) << mode;
    }
    // One target cannot hold a G-buffer: a clear error at load time, not a black window.
    const ProcessResult one = game("--debug-max-render-targets 2");
    EXPECT_NE(one.code, 0);
    EXPECT_NE(one.out.find("frame: the G-buffer needs 3 simultaneous render targets"), std::string::npos) << one.out;
}

TEST(FrameRender, AMissingFormatTurnsOffOnlyTheStageThatNeedsIt) {
    const obscura::Image off = render("fmt_ao_off", "--ssao off");
    const obscura::Image horizon = render("fmt_horizon", "--ssao horizon");
    ASSERT_GT(differing(off, horizon, 2), 100u) << "AO changes this view";

    // Without PF_FLOAT32_GR targets, AO is off, and the smoke (PF_FLOAT32_RGBA) still shows.
    ProcessResult r;
    const obscura::Image noAo = render("fmt_no_ao", "--ssao horizon --debug-unsupported-formats PF_FLOAT32_GR", &r);
    EXPECT_NE(r.out.find("obscura: frame: the AO stage (engine_ext/ssao) is off: it needs render targets in PF_FLOAT32_GR"),
              std::string::npos) << r.out;
    EXPECT_EQ(differing(noAo, off, 0), 0u);

    // Without PF_FLOAT32_RGBA targets the smoke is off, and AO still runs.
    const obscura::Image noSmoke = render("fmt_no_smoke", "--ssao horizon --debug-unsupported-formats PF_FLOAT32_RGBA", &r);
    EXPECT_NE(r.out.find("obscura: frame: the volumetrics stage (engine_ext/smoke) is off: it needs render targets in "
                         "PF_FLOAT32_RGBA"), std::string::npos) << r.out;
    EXPECT_GT(differing(noSmoke, horizon, 16), 1000u) << "the cloud is gone";
    const obscura::Image noSmokeOff = render("fmt_no_smoke_off", "--ssao off --debug-unsupported-formats PF_FLOAT32_RGBA");
    EXPECT_GT(differing(noSmoke, noSmokeOff, 2), 100u) << "AO still darkens the creases";
}

TEST(FrameRender, ARealWindowShowsWhatHeadlessShowsInEveryMode) {
    // The window's render target is not flipped like a render texture: a pass that took the flip
    // from the viewport's target drew hemisphere and heightfield AO upside down in a window
    // (PSNR 21.7 dB against headless before the frame pipeline). The flip now comes from the
    // G-buffer's own render texture. With smoke in view: frames are slow there, and a live run of
    // --ticks N must still stop on tick N (it used to bank ticks past it), so the cloud matches.
    const char* const kStillView = kView;
    for (const auto& mode : obscura::ssao::modeNames()) {
        const std::string headlessShot = shot("head_" + mode);
        ASSERT_EQ(obscura::testing_support::runProcess(std::string("'" OBSCURA_GAME "' --headless --ticks 40 --width 320 "
                                                                   "--height 180 --hud off ") + kStillView + " --ssao " +
                                                       mode + " --screenshot " + headlessShot).code, 0);
        const obscura::Image headless = obscura::readPng(headlessShot);
        const std::string path = shot("window_" + mode);
        const ProcessResult r = obscura::testing_support::runProcess(
            std::string("'" OBSCURA_GAME "' --ticks 40 --width 320 --height 180 --hud off ") + kStillView + " --ssao " + mode +
            " --screenshot " + path);
        ASSERT_EQ(r.code, 0) << r.out;
        const obscura::Image window = obscura::readPng(path);
        ASSERT_EQ(window.rgba.size(), headless.rgba.size()) << mode;
        EXPECT_EQ(differing(window, headless, 1), 0u) << mode;
    }
}

TEST(FrameRender, EveryViewShowsSomethingElseAndAnUnknownViewIsAnError) {
    const obscura::Image scene = render("view_scene", "--ssao horizon");
    for (const std::string view : {"ao", "albedo", "normal", "depth", "direct-light", "hdr-light"}) {
        ProcessResult r;
        const obscura::Image shown = render("view_" + view, "--ssao horizon --view " + view, &r);
        EXPECT_EQ(offLines(r.out), 0u) << view << ":\n" << r.out;
        EXPECT_GT(differing(shown, scene, 8), scene.rgba.size() / 20) << view << " looks like the picture";
        if (view == "depth") {
            // A log scale (white 0.25 m, black 64 m): the arena's court reads in greys. The old
            // linear 0..50 m ramp put 76 % of this view above 200 (mean 214).
            std::size_t bright = 0;
            for (std::size_t i = 0; i < shown.rgba.size(); i += 4) bright += shown.rgba[i] > 200;
            EXPECT_LT(bright, shown.rgba.size() / 4 / 10) << "the depth view is almost white";
        }
    }
    const ProcessResult bad = game("--view bogus");
    EXPECT_NE(bad.code, 0);
    EXPECT_NE(bad.out.find("unknown view 'bogus', expected one of scene, ao, albedo"), std::string::npos) << bad.out;
}
