// obscura_signref: the ray-traced ground truth of the back-lit signs' light shafts (issue 15;
// signref/shaft_reference.h has the integral), at the size of the game's half-resolution volume
// buffer, and the measures the table needs. README.md has the whole story.
//
//   render   obscura_signref --level L --pose "x y z yaw pitch" [--fov 90] [--width 640 --height 360]
//              [--haze 0.02] [--smoke smoke.dump] [--spp 4] [--step 0.02] [--shadow-step 0.05] [--lamp-samples 16]
//              [--far 50] [--threads N] [--seed 1] [--spread M] [--hole "sign x y r"]... [--law]
//              [--out ref.pfm] [--png preview.png [--preview-scale S]] [--compare game.pfm]...
//            prints per --compare: "signref rmse=... rmse_off=... mean_ref=... max_ref=... pixels=...
//            channels=rgb file=..."
//   edge     obscura_signref --level L --edge-from "x y z" --edge-to "x y z" [--edge-points 201]
//              [--edge-sign 0] [--lamp-samples 4096]
//            prints "signref-edge width1090=... penumbra=... penumbra1090=... sphere1090=... cos_axis=...
//            b=... a=... ratio=... ratio_sphere=..." (ratio: against 2Rb/a's 10-90 % equivalent)
//   measure  obscura_signref --measure-pfm game_lit.pfm --from "px py" --to "px py"
//              [--level L --pose P [--fov 90]]: the 10-90 % width of the luminance along the pixel
//              segment, in pixels (and metres when the level and pose let it map the ends)
#include "core/image.h"
#include "core/pfm.h"
#include "map/asset_path.h"
#include "map/map_compile.h"
#include "raytrace/level_triangles.h"
#include "signref/shaft_reference.h"
#include "smoke/smoke_dump.h"

#include <boost/program_options.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <thread>

namespace po = boost::program_options;
using namespace obscura;

namespace {
std::vector<double> numbers(const std::string& text, std::size_t count, const char* option) {
    std::istringstream is(text);
    std::vector<double> v;
    double d;
    while (is >> d) v.push_back(d);
    if (!is.eof() || v.size() != count || !std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); }))
        throw po::error(std::string("--") + option + " needs " + std::to_string(count) + " numbers, got '" + text + "'");
    return v;
}

struct Scene {
    map::Level level;
    std::unique_ptr<RayScene> rays;
};

Scene loadScene(const std::string& levelPath) {
    Scene s;
    s.level = map::loadLevel(levelPath);
    auto triangles = levelTriangles(s.level);
    addModelTriangles(s.level, map::levelSearchDirs(levelPath, OBSCURA_DATA_DIR), triangles);
    s.rays = std::make_unique<RayScene>(triangles);
    return s;
}

std::vector<signref::SignLight> loadSigns(const map::Level& level, const std::vector<std::string>& fontDirs, double spread,
                                          const std::vector<std::string>& holes) {
    std::vector<std::string> warnings;
    std::vector<signref::SignLight> out;
    for (signs::SignSpec& spec : signs::readSignLights(level, fontDirs, warnings)) {
        signref::SignLight s;
        s.mask = signs::bakeMask(spec, spread >= 0 ? spread : signs::maxPenumbraRadius(spec));
        s.spec = std::move(spec);
        out.push_back(std::move(s));
    }
    for (const auto& w : warnings) std::cerr << "signref: " << w << "\n";
    for (const auto& h : holes) {
        const auto v = numbers(h, 4, "hole");
        const auto i = static_cast<std::size_t>(v[0]);
        if (v[0] < 0 || v[0] != std::floor(v[0]) || i >= out.size())
            throw po::error("--hole '" + h + "': sign " + std::to_string(v[0]) + " is not one of the level's " +
                            std::to_string(out.size()) + " light_signs");
        if (!(v[3] > 0)) throw po::error("--hole '" + h + "': the radius must be positive");
        out[i].holes.push_back({v[1], v[2], v[3]});
    }
    return out;
}

double luminance(const float* c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

void writePreview(const FloatImage& img, double scale, const std::string& path) {
    if (!(scale > 0)) {  // auto: the 99th percentile of the luminance maps to 0.9
        std::vector<double> lum;
        for (std::size_t i = 0; i < img.rgb.size(); i += 3) lum.push_back(luminance(&img.rgb[i]));
        std::sort(lum.begin(), lum.end());
        const double p99 = lum.empty() ? 0 : lum[std::min(lum.size() - 1, lum.size() * 99 / 100)];
        scale = p99 > 0 ? 0.9 / p99 : 1;
        std::cerr << "signref: preview scale " << scale << "\n";
    }
    Image png{img.width, img.height, std::vector<std::uint8_t>(static_cast<std::size_t>(img.width) * img.height * 4, 255)};
    for (std::size_t i = 0; i * 3 < img.rgb.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double v = std::clamp(img.rgb[i * 3 + c] * scale, 0.0, 1.0);
            png.rgba[i * 4 + c] = static_cast<std::uint8_t>(std::lround(std::pow(v, 1 / 2.2) * 255));
        }
    writePng(png, path);
}

// The luminance along a pixel segment of a PFM (bilinear), and its 10-90 % width.
int measurePfm(const std::string& file, const std::string& fromText, const std::string& toText, const Scene* scene,
               const CameraPose* pose) {
    const FloatImage img = readPfm(file);
    const auto a = numbers(fromText, 2, "from"), b = numbers(toText, 2, "to");
    for (const auto* p : {&a, &b})
        if ((*p)[0] < 0 || (*p)[1] < 0 || (*p)[0] > img.width || (*p)[1] > img.height)
            throw po::error("--from/--to: a point lies outside the " + std::to_string(img.width) + "x" + std::to_string(img.height) + " image");
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    const int n = std::max(3, static_cast<int>(std::ceil(len * 4)) + 1);  // 4 samples a pixel
    std::vector<double> s, v;
    auto lum = [&](int x, int y) {
        x = std::clamp(x, 0, img.width - 1), y = std::clamp(y, 0, img.height - 1);
        return luminance(&img.rgb[(static_cast<std::size_t>(y) * img.width + x) * 3]);
    };
    for (int i = 0; i < n; ++i) {
        const double f = static_cast<double>(i) / (n - 1);
        const double x = a[0] + (b[0] - a[0]) * f - 0.5, y = a[1] + (b[1] - a[1]) * f - 0.5;  // pixel centres at +0.5
        const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
        const double fx = x - x0, fy = y - y0;
        s.push_back(f * len);
        v.push_back((lum(x0, y0) * (1 - fx) + lum(x0 + 1, y0) * fx) * (1 - fy) + (lum(x0, y0 + 1) * (1 - fx) + lum(x0 + 1, y0 + 1) * fx) * fy);
    }
    double width = 0, s50 = 0;
    if (!signref::width1090(s, v, width, s50)) {
        std::cout << "signref-measure width1090_px=none file=" << file << " (the profile does not cross 10 % and 90 %)\n";
        return 1;
    }
    std::cout << "signref-measure width1090_px=" << width;
    if (scene && pose) {
        double ta, tb;
        Vec3 n1;
        const Vec3 da = cameraRay(*pose, img.width, img.height, a[0], a[1]), db = cameraRay(*pose, img.width, img.height, b[0], b[1]);
        if (len > 0 && scene->rays->intersect(pose->eye, da, 0, 1e4, ta, n1) && scene->rays->intersect(pose->eye, db, 0, 1e4, tb, n1)) {
            const double metresPerPixel = length((pose->eye + db * tb) - (pose->eye + da * ta)) / len;
            std::cout << " width1090_m=" << width * metresPerPixel << " metres_per_px=" << metresPerPixel;
        } else {
            std::cout << " width1090_m=none";
        }
    }
    std::cout << " file=" << file << "\n";
    return 0;
}
}  // namespace

int main(int argc, char** argv) {
    std::string levelPath, poseText, out, png, smokeFile, edgeFrom, edgeTo, measureFile, fromText, toText;
    std::vector<std::string> compare, holes, fontDirs;
    int width = 0, height = 0, threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    int edgePoints = 201, edgeSign = 0, lampSamples = -1;
    double fov = 90, haze = 0.02, hazeExtinction = -1, spread = -1, previewScale = 0;
    signref::ShaftOptions opt;
    po::options_description desc("obscura_signref options");
    desc.add_options()("level", po::value(&levelPath), ".map level (its light_signs and triangles)")
        ("pose", po::value(&poseText), "eye 'x y z yaw pitch' (metres, degrees), as the game's --start-pose")
        ("fov", po::value(&fov), "horizontal field of view, degrees (90)")
        ("width", po::value(&width), "image width (640, or the first --compare image's)")
        ("height", po::value(&height), "image height (360, or the first --compare image's)")
        ("haze", po::value(&haze), "uniform haze scattering, per metre (0.02)")
        ("haze-extinction", po::value(&hazeExtinction), "the haze's extinction per metre (default: = --haze, a physical "
                                                         "haze; 0: the game's thin-haze model, which neglects it)")
        ("smoke", po::value(&smokeFile), "a smoke dump (engine_ext/smoke/smoke_dump.h) for the medium")
        ("spp", po::value(&opt.spp), "view rays a pixel, stratified over its area (4)")
        ("step", po::value(&opt.step), "metres between points along a ray (0.02)")
        ("shadow-step", po::value(&opt.shadowStep), "metres between points from a lit point to the lamp through the medium (0.05; 0: the lamp's light not dimmed by it)")
        ("lamp-samples", po::value(&lampSamples), "directions to the lamp's sphere at each point (16; edge: 4096)")
        ("far", po::value(&opt.far), "metres a ray that hits nothing is marched (50)")
        ("threads", po::value(&threads), "worker threads (all cores); the image does not depend on it")
        ("seed", po::value(&opt.seed), "random seed (1)")
        ("spread", po::value(&spread), "the masks' distance spread, metres (maxPenumbraRadius of each sign)")
        ("hole", po::value(&holes)->composing(), "'sign x y r': a bullet hole (plate metres), repeatable")
        ("font-dir", po::value(&fontDirs)->composing(), "where fonts are looked for (/usr/share/fonts/truetype/dejavu)")
        ("no-cull", "sample the lamp at every point (no footprint test)")
        ("no-geometry", "no occlusion by the level between a point and the plate")
        ("law", "E from the game's law (signIrradiance + one occlusion ray), not the sampled lamp")
        ("out", po::value(&out), "the reference, PFM (rgb in-scattered radiance)")
        ("png", po::value(&png), "a preview PNG")("preview-scale", po::value(&previewScale), "the preview's exposure (auto)")
        ("compare", po::value(&compare)->composing(), "the game's volume buffer dump (PFM), repeatable")
        ("edge-from", po::value(&edgeFrom), "edge mode: the receiver line's start 'x y z'")
        ("edge-to", po::value(&edgeTo), "edge mode: its end 'x y z'")
        ("edge-points", po::value(&edgePoints), "edge mode: points along it (201)")
        ("edge-sign", po::value(&edgeSign), "edge mode: which light_sign (0)")
        ("measure-pfm", po::value(&measureFile), "measure mode: a full-resolution HDR image (PFM)")
        ("from", po::value(&fromText), "measure mode: 'px py' (pixels from the top-left)")
        ("to", po::value(&toText), "measure mode: 'px py'")("help", "this text");
    try {
        po::variables_map vm;
        po::store(po::parse_command_line(argc, argv, desc), vm);
        po::notify(vm);
        if (vm.count("help")) {
            std::cout << desc;
            return 0;
        }
        if (fontDirs.empty()) fontDirs.push_back("/usr/share/fonts/truetype/dejavu");
        opt.cull = !vm.count("no-cull");
        opt.geometry = !vm.count("no-geometry");
        opt.law = vm.count("law") > 0;
        if (!(opt.step > 0) || !std::isfinite(opt.step)) throw po::error("--step must be a positive number of metres");
        if (opt.spp < 1) throw po::error("--spp must be at least 1");
        if (!(opt.shadowStep >= 0) || !std::isfinite(opt.shadowStep)) throw po::error("--shadow-step must be 0 or a positive number of metres");
        if (vm.count("lamp-samples") && lampSamples < 1) throw po::error("--lamp-samples must be at least 1");
        if (!(haze >= 0) || !std::isfinite(haze)) throw po::error("--haze must not be negative");
        if (!(opt.far > 0)) throw po::error("--far must be positive");
        if (threads < 1) throw po::error("--threads must be at least 1");

        CameraPose pose;
        const bool havePose = !poseText.empty();
        if (havePose && !parsePose(poseText, fov, pose)) throw po::error("--pose needs 'x y z yaw pitch', got '" + poseText + "'");
        if (!(fov > 0 && fov < 180)) throw po::error("--fov must lie in (0, 180) degrees");

        if (!measureFile.empty()) {
            if (fromText.empty() || toText.empty()) throw po::error("--measure-pfm needs --from and --to");
            std::unique_ptr<Scene> scene;
            if (!levelPath.empty() && havePose) scene = std::make_unique<Scene>(loadScene(levelPath));
            return measurePfm(measureFile, fromText, toText, scene.get(), scene ? &pose : nullptr);
        }
        if (levelPath.empty()) throw po::error("--level is required (or --measure-pfm)");

        if (!edgeFrom.empty() || !edgeTo.empty()) {
            if (edgeFrom.empty() || edgeTo.empty()) throw po::error("edge mode needs both --edge-from and --edge-to");
            const auto f = numbers(edgeFrom, 3, "edge-from"), t = numbers(edgeTo, 3, "edge-to");
            if (edgePoints < 3) throw po::error("--edge-points must be at least 3");
            const Scene scene = loadScene(levelPath);
            const auto signs = loadSigns(scene.level, fontDirs, spread, holes);
            if (edgeSign < 0 || static_cast<std::size_t>(edgeSign) >= signs.size())
                throw po::error("--edge-sign " + std::to_string(edgeSign) + ": the level has " + std::to_string(signs.size()) + " light_signs");
            const auto m = signref::measureEdge(signs[static_cast<std::size_t>(edgeSign)], opt.geometry ? scene.rays.get() : nullptr,
                                                {f[0], f[1], f[2]}, {t[0], t[1], t[2]}, edgePoints,
                                                lampSamples > 0 ? lampSamples : 4096, opt.seed);
            if (!m.found) {
                std::cout << "signref-edge width1090=none (the lamp's share does not cross 10 % and 90 % along the line)\n";
                return 1;
            }
            std::cout << "signref-edge width1090=" << m.width1090 << " penumbra=" << m.penumbra
                      << " penumbra1090=" << m.penumbra1090 << " sphere1090=" << m.sphere1090 << " cos_axis=" << m.cosAxis
                      << " b=" << m.b << " a=" << m.a << " ratio=" << (m.penumbra1090 > 0 ? m.width1090 / m.penumbra1090 : 0)
                      << " ratio_sphere=" << (m.sphere1090 > 0 ? m.width1090 / m.sphere1090 : 0) << "\n";
            return 0;
        }

        if (!havePose) throw po::error("--pose is required to render");
        if (out.empty() && png.empty() && compare.empty()) throw po::error("nothing to do: give --out, --png or --compare");
        std::vector<FloatImage> games;
        for (const auto& c : compare) games.push_back(readPfm(c));
        if (width == 0) width = games.empty() ? 640 : games.front().width;
        if (height == 0) height = games.empty() ? 360 : games.front().height;
        if (width < 1 || height < 1) throw po::error("--width and --height must be positive");
        opt.lampSamples = lampSamples > 0 ? lampSamples : 16;

        const Scene scene = loadScene(levelPath);
        auto signs = loadSigns(scene.level, fontDirs, spread, holes);
        if (signs.empty()) std::cerr << "signref: " << levelPath << " has no light_sign: the reference is black\n";
        smoke::SmokeDump dump;
        signref::Medium medium;
        medium.haze = haze;
        medium.hazeExtinction = hazeExtinction;
        if (!smokeFile.empty()) {
            dump = smoke::readSmokeDump(smokeFile);
            medium.smoke = &dump;
        }
        const signref::ShaftReference ref(*scene.rays, std::move(signs), medium);
        const auto t0 = std::chrono::steady_clock::now();
        const FloatImage img = ref.render(pose, width, height, opt, threads);
        const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::cerr << "signref: " << width << "x" << height << ", " << opt.spp << " rays a pixel, " << opt.step << " m steps, "
                  << (opt.law ? std::string("the law's light (not the truth)") : std::to_string(opt.lampSamples) + " lamp samples") << ", in " << secs << " s on " << threads << " threads\n";
        if (!out.empty()) writePfm(img, out);
        if (!png.empty()) writePreview(img, previewScale, png);
        for (std::size_t i = 0; i < games.size(); ++i) {
            signref::ShaftError e;
            try {
                e = signref::compareShafts(img, games[i]);
            } catch (const std::runtime_error& err) {
                throw std::runtime_error(compare[i] + ": " + err.what());
            }
            std::cout << "signref rmse=" << e.rmse << " rmse_off=" << e.rmseOff << " mean_ref=" << e.meanRef
                      << " max_ref=" << e.maxRef << " pixels=" << e.pixels << " channels=rgb file=" << compare[i] << "\n";
        }
    } catch (const po::error& e) {
        std::cerr << "obscura_signref: " << e.what() << "\n(--help lists the options)\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "obscura_signref: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
