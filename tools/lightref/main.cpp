// obscura_lightref: the irradiance a view should show (light_reference.h, path-traced) and the
// error table's row for it: the RMSE of today's frame (the game's --irradiance-dump of the same
// pose and size), of the model before the light bake, and of showing nothing.
//   obscura_lightref --level L --pose "x y z yaw pitch" [--fov 90] [--width 160 --height 90]
//                    [--samples 64] [--bounces 3] [--frame F.pfm] [--out reference.pfm]
#include "light_reference.h"

#include "core/pfm.h"
#include "map/map_compile.h"

#include <boost/program_options.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>

namespace po = boost::program_options;
using namespace obscura;

int main(int argc, char** argv) {
    std::string levelPath, poseText, framePath, out;
    int width = 160, height = 90;
    double fov = 90;
    lightref::ReferenceSettings s;
    po::options_description desc("obscura_lightref options");
    desc.add_options()("level", po::value(&levelPath)->required(), ".map level")(
        "pose", po::value(&poseText)->required(), "eye 'x y z yaw pitch' (metres, degrees)")(
        "fov", po::value(&fov), "horizontal field of view, degrees (90)")("width", po::value(&width), "")("height", po::value(&height), "")(
        "samples", po::value(&s.samples), "paths a pixel (64)")("bounces", po::value(&s.bounces), "diffuse bounces (3)")(
        "frame", po::value(&framePath), "the game's --irradiance-dump of the same view")("out", po::value(&out), "the reference as PFM");
    try {
        po::variables_map vm;
        po::store(po::parse_command_line(argc, argv, desc), vm);
        po::notify(vm);
        CameraPose pose;
        if (!parsePose(poseText, fov, pose)) throw po::error("--pose needs 'x y z yaw pitch'");
        if (width < 1 || height < 1 || width > 4096 || height > 4096) throw po::error("--width and --height must be 1..4096");
        if (s.samples < 1 || s.bounces < 1) throw po::error("--samples and --bounces must be at least 1");
        const map::Level level = map::loadLevel(levelPath);
        const auto t0 = std::chrono::steady_clock::now();
        const lightref::Irradiance ref = lightref::pathTraced(level, pose, width, height, s);
        const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const lightref::Irradiance before = lightref::beforeTheBake(level, pose, width, height);
        if (!out.empty()) writePfm({ref.width, ref.height, ref.rgb}, out);
        double mean = 0;
        std::size_t n = 0;
        for (std::size_t i = 0; i < ref.surface.size(); ++i)
            if (ref.surface[i]) {
                mean += 0.2126 * ref.rgb[i * 3] + 0.7152 * ref.rgb[i * 3 + 1] + 0.0722 * ref.rgb[i * 3 + 2];
                ++n;
            }
        mean = n ? mean / n : 0;
        const double nothing = lightref::rmse(ref, std::vector<float>(ref.rgb.size(), 0.0f));
        const double old = lightref::rmse(ref, before.rgb);
        std::printf("lightref %dx%d, %d paths x %d bounces in %.1f s: reference mean %.4f; RMSE nothing %.4f, before the bake %.4f",
                    width, height, s.samples, s.bounces, secs, mean, nothing, old);
        if (!framePath.empty()) {
            const FloatImage frame = readPfm(framePath);
            if (frame.width != width || frame.height != height)
                throw std::runtime_error(framePath + ": " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                                         ", not the reference's " + std::to_string(width) + "x" + std::to_string(height));
            const double now = lightref::rmse(ref, frame.rgb);
            std::printf(", the frame %.4f (%.1fx lower than before)", now, now > 0 ? old / now : 0.0);
        }
        std::printf("\n");
    } catch (const po::error& e) {
        std::cerr << "obscura_lightref: " << e.what() << "\n" << desc;
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "obscura_lightref: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
