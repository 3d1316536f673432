// obscura_lightbake: bakes a level's static light ahead of play (engine_ext/lightbake), into the
// cache the game reads at load, and prints what it cost.
//   obscura_lightbake LEVEL.map [--cache DIR] [--threads N] [--force]
// DIR defaults to the game's ($XDG_CACHE_HOME/obscura, else ~/.cache/obscura).
#include "lightbake/bake_cache.h"
#include "map/map_compile.h"

#include <boost/program_options.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

using namespace obscura;
namespace po = boost::program_options;

int main(int argc, char** argv) {
    std::string levelPath, cacheDir;
    int threads = 0;
    po::options_description desc("obscura_lightbake LEVEL.map [options]");
    desc.add_options()("help", "this text")("level", po::value(&levelPath), "the .map to bake")(
        "cache", po::value(&cacheDir), "the cache folder (default: the game's)")(
        "threads", po::value(&threads), "threads (default: every hardware thread)")("force", "bake even when the cache holds it");
    po::positional_options_description pos;
    pos.add("level", 1);
    po::variables_map vm;
    try {
        po::store(po::command_line_parser(argc, argv).options(desc).positional(pos).run(), vm);
        po::notify(vm);
    } catch (const std::exception& e) {
        std::cerr << "obscura_lightbake: " << e.what() << "\n" << desc;
        return 2;
    }
    if (vm.count("help") || levelPath.empty()) {
        std::cout << desc;
        return levelPath.empty() && !vm.count("help") ? 2 : 0;
    }
    if (cacheDir.empty()) {
        const char* xdg = std::getenv("XDG_CACHE_HOME");
        const char* home = std::getenv("HOME");
        cacheDir = xdg && *xdg ? std::string(xdg) + "/obscura" : std::string(home ? home : ".") + "/.cache/obscura";
    }
    try {
        const map::Level level = map::loadLevel(levelPath);
        lightbake::BakeSettings settings;
        settings.threads = threads;
        const lightbake::BakeSky sky = lightbake::bakeSkyOf(level);
        if (vm.count("force")) std::filesystem::remove(lightbake::cacheFile(cacheDir, level.sourcePath));
        const auto log = [](const std::string& line) { std::cerr << line << "\n"; };
        const lightbake::BakeOutcome out = lightbake::bakeOrLoad(level, sky, settings, cacheDir, log);
        const auto& s = out.bake.stats;
        std::error_code ec;
        const auto bytes = std::filesystem::file_size(out.file, ec);
        std::printf("%s: %s in %.3f s: %zu faces, atlas %d x %d (%.3f m a texel, %.0f%% buried), %zu probes (%.2f m), %zu lights, %.1f M rays (direct %.1f s, bounces %.1f s, probes %.1f s); %s %.1f MB\n",
                    levelPath.c_str(), out.fromCache ? "read from the cache" : "baked", out.seconds, s.charts,
                    out.bake.atlas.width, out.bake.atlas.height, out.bake.atlas.texel, 100.0 * s.buried / std::max<std::size_t>(1, s.texels), s.probes, out.bake.probes.cell, s.lights,
                    s.rays / 1e6, s.directSeconds, s.bounceSeconds, s.probeSeconds, out.file.c_str(), ec ? 0.0 : bytes / 1e6);
    } catch (const std::exception& e) {
        std::cerr << "obscura_lightbake: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
