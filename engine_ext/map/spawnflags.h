// Quake's and Quake 2's spawnflags that keep an entity out of a game: the same bits in both
// (Quake's ED_LoadFromFile, Quake 2's g_spawn.c). Obscura is a single-player game, so
// NOT_DEATHMATCH entities stay, and an entity flagged out of every skill (E1M1's deathmatch-only
// walls, spawnflags 1792) is left out at all of them. Worldspawn is never left out.
#pragma once

namespace obscura::map {

constexpr int kSpawnNotEasy = 256, kSpawnNotMedium = 512, kSpawnNotHard = 1024, kSpawnNotDeathmatch = 2048;
constexpr int kMinSkill = 0, kMaxSkill = 3;  // easy, normal, hard, nightmare (Quake's `skill` cvar)
constexpr int kDefaultSkill = 1;             // Quake's default

// True if an entity with `spawnflags` is not spawned at `skill` (nightmare tests NOT_HARD, as Quake).
constexpr bool leftOutAtSkill(int spawnflags, int skill) {
    return (spawnflags & (skill <= 0 ? kSpawnNotEasy : skill == 1 ? kSpawnNotMedium : kSpawnNotHard)) != 0;
}

}  // namespace obscura::map
