// See truth_show.h.
#include "ao_truth/truth_show.h"

#include <algorithm>

namespace obscura::ao_truth {

const std::vector<std::string>& showNames() {
    static const std::vector<std::string> names = {"off", "reference", "mode", "heatmap"};
    return names;
}

std::optional<Show> showFromName(const std::string& name) {
    const auto& all = showNames();
    const auto at = std::find(all.begin(), all.end(), name);
    if (at == all.end()) return std::nullopt;
    return static_cast<Show>(at - all.begin());
}

const std::string& showName(Show s) { return showNames().at(static_cast<std::size_t>(s)); }

Show nextShow(Show s) { return static_cast<Show>((static_cast<int>(s) + 1) % static_cast<int>(showNames().size())); }

}  // namespace obscura::ao_truth
