// obscura_aoref: the ray-traced AO reference of a level view (engine_ext/ssao/ao_reference.h),
// written as a grey PNG, and optionally compared with the game's AO-only capture of the same view.
//
//   obscura_aoref --level L --pose "x y z yaw pitch" [--fov 90] [--width 320] [--height 180]
//                 [--radius 0.6] [--rays 256] [--scale 1] --out ref.png [--compare game_ao.png]... [--compare-off]
//
// --scale S traces S x S sub-pixels of rays/S^2 rays each for every pixel and averages them (so a
// pixel is its footprint's mean AO, with the same rays in all); a --compare image may then be the
// game's capture at S times the size, averaged down the same way (aoref/ao_compare.h, boxAverage).
// A pixel sees geometry when at least half of its sub-pixels do.
//
// The game side: obscura --headless --start-pose "..." --hud off --ssao MODE, AO-only view (P).
// Prints, for each --compare image (one trace serves them all) and with --compare-off for `off` (an
// all-white frame, scored the same way), "aoref mae=... rmse=... bias=... pixels=... occluded_mae=...
// occluded_bias=... occluded_pixels=... occluded_share=... file=..." (aoref/ao_compare.h): over the
// pixels that see geometry, and over those whose reference is below 0.95.
#include "aoref/ao_compare.h"
#include "core/image.h"
#include "map/asset_path.h"
#include "map/map_compile.h"
#include "raytrace/level_triangles.h"
#include "ssao/ao_reference.h"

#include <boost/program_options.hpp>

#include <chrono>
#include <filesystem>
#include <cmath>
#include <iostream>

namespace po = boost::program_options;
using namespace obscura;

int main(int argc, char** argv) {
    std::string levelPath, poseText, out;
    std::vector<std::string> compare;
    int width = 320, height = 180, rays = 256, scale = 1;
    double fov = 90, radius = 0.6;
    po::options_description desc("obscura_aoref options");
    desc.add_options()("level", po::value(&levelPath)->required(), ".map level")
        ("pose", po::value(&poseText)->required(), "eye 'x y z yaw pitch' (metres, degrees)")
        ("fov", po::value(&fov), "horizontal field of view, degrees (90)")("width", po::value(&width), "")
        ("height", po::value(&height), "")("radius", po::value(&radius), "AO radius, metres (0.6)")
        ("rays", po::value(&rays), "rays per pixel (256)")
        ("scale", po::value(&scale), "sub-pixels a side, averaged (1)")("out", po::value(&out)->required(), "reference PNG")
        ("compare", po::value(&compare)->composing(), "the game's AO-only capture of the same view (repeatable)")
        ("compare-off", "also score `off`: an all-white frame");
    try {
        po::variables_map vm;
        po::store(po::parse_command_line(argc, argv, desc), vm);
        po::notify(vm);
        CameraPose pose;
        if (!parsePose(poseText, fov, pose)) throw po::error("--pose needs 'x y z yaw pitch'");
        if (scale < 1 || scale > 8) throw po::error("--scale must be 1..8");
        if (rays < scale * scale) throw po::error("--rays must be at least --scale squared");

        const map::Level level = map::loadLevel(levelPath);
        auto triangles = levelTriangles(level);
        addModelTriangles(level, map::levelSearchDirs(levelPath, OBSCURA_DATA_DIR), triangles, "aoref");
        const ssao::AoReference ref(triangles);
        const auto t0 = std::chrono::steady_clock::now();
        const ssao::AoImage fine = ref.render(pose, width * scale, height * scale, radius, rays / (scale * scale), 2);
        ssao::AoImage img{width, height, aoref::boxAverage(fine.ao, fine.width, fine.height, scale), {}};
        const std::vector<float> hitShare = aoref::boxAverage(
            std::vector<float>(fine.hit.begin(), fine.hit.end()), fine.width, fine.height, scale);
        for (float h : hitShare) img.hit.push_back(h >= 0.5f ? 1 : 0);
        const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

        Image png{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4, 255)};
        for (std::size_t i = 0; i < img.ao.size(); ++i)
            for (int c = 0; c < 3; ++c) png.rgba[i * 4 + c] = static_cast<std::uint8_t>(std::lround(img.ao[i] * 255.0f));
        writePng(png, out);
        std::cerr << "aoref: " << width << "x" << height << " x " << rays << " rays in " << secs << " s\n";

        if (vm.count("compare-off"))
            std::cout << "aoref " << aoref::formatAoError(aoref::compareAo(img.ao, img.hit, aoref::whiteAo(img.ao.size())))
                      << " file=off\n";
        for (const auto& file : compare) {
            const Image game = readPng(file);
            const int s = game.width == width * scale && game.height == height * scale ? scale : 1;
            if (game.width != width * s || game.height != height * s)
                throw std::runtime_error(file + ": neither the reference's size nor --scale times it");
            const std::vector<float> ao = aoref::boxAverage(aoref::aoFromRgba8(game.rgba), game.width, game.height, s);
            std::cout << "aoref " << aoref::formatAoError(aoref::compareAo(img.ao, img.hit, ao))
                      << " file=" << file << "\n";
        }
    } catch (const po::error& e) {
        std::cerr << "obscura_aoref: " << e.what() << "\n" << desc;
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "obscura_aoref: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
