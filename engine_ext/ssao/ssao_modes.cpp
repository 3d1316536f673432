// See ssao_modes.h.
#include "ssao/ssao_modes.h"

#include <algorithm>

namespace obscura::ssao {

const std::vector<std::string>& modeNames() {
    static const std::vector<std::string> names = {"off", "crytek", "hemisphere", "cone", "horizon", "heightfield", "gtao", "combined"};
    return names;
}

bool readsHeightMap(const std::string& mode) { return mode == "heightfield" || mode == "combined"; }

double truthRadius(const std::string& mode, double radius, double largeRadius) {
    return mode == "combined" && largeRadius > radius ? largeRadius : radius;
}

bool isMode(const std::string& name) {
    const auto& m = modeNames();
    return std::find(m.begin(), m.end(), name) != m.end();
}

std::string cycleMode(const std::string& current, int step) {
    const auto& m = modeNames();
    const auto it = std::find(m.begin(), m.end(), current);
    const long n = static_cast<long>(m.size());
    const long i = it == m.end() ? 0 : static_cast<long>(it - m.begin());
    return m[static_cast<std::size_t>(((i + step) % n + n) % n)];
}

}  // namespace obscura::ssao
