// The AO modes O cycles through, in order. Plain C++ so settings and replays can validate names.
#pragma once

#include <string>
#include <vector>

namespace obscura::ssao {

// "off", then one name per compositor in media/ssao/ssao.compositor.
const std::vector<std::string>& modeNames();
bool isMode(const std::string& name);
// Whether the mode marches the level's top-down height map (the game bakes it for these).
bool readsHeightMap(const std::string& mode);
// The radius whose ray-traced truth the mode estimates (what the truth key traces): the combined
// mode's large radius where it reaches past the small one, every other mode's radius.
double truthRadius(const std::string& mode, double radius, double largeRadius);
// The next (step +1) or previous (step -1) mode, wrapping around.
std::string cycleMode(const std::string& current, int step);

}  // namespace obscura::ssao
