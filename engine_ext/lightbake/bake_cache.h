// The bake on disk: one file a level in <cache>/lightbake/, named by the level's path, holding the
// bake's key (a hash of everything the bake reads: the baked faces, the sky faces, the lights, the
// sky and the settings) and a checksum of its payload. A missing file is baked quietly; a
// truncated, corrupt or stale one (the level or the bake changed) is baked again with one line
// saying why, and replaced. Nothing is written outside <cache>/lightbake/. Plain C++.
#pragma once

#include "lightbake/light_bake.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace obscura::lightbake {

// Bumped whenever the bake's arithmetic or the file's layout changes (old files then read as stale).
constexpr std::uint32_t kBakeVersion = 6;

std::uint64_t bakeKey(const map::Level& level, const BakeSky& sky, const BakeSettings& settings);

// <cacheDir>/lightbake/<the level file's name>-<a hash of its absolute path>.bake
std::string cacheFile(const std::string& cacheDir, const std::string& levelPath);

// The bake in `file` if it holds `key` for this level; else nullopt, with `why` saying what was
// wrong ("" when the file does not exist).
std::optional<LightBake> loadBake(const std::string& file, const map::Level& level, std::uint64_t key, std::string& why);
// Writes through a temporary file beside it and a rename: a crash leaves the old file or none.
// Throws std::runtime_error naming the file when it cannot be written.
void saveBake(const std::string& file, std::uint64_t key, const LightBake& bake);

struct BakeOutcome {
    LightBake bake;
    bool fromCache = false;
    double seconds = 0;  // the bake's or the load's wall time
    std::string file;
};

// The level's bake from the cache, or baked (and stored) when the cache lacks it. `log` gets the
// lines a player sees: why a cache file was not used, the bake's progress, a write failure (the
// game then runs on the fresh bake without storing it).
BakeOutcome bakeOrLoad(const map::Level& level, const BakeSky& sky, const BakeSettings& settings, const std::string& cacheDir,
                       const std::function<void(const std::string&)>& log);

}  // namespace obscura::lightbake
