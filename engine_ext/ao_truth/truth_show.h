// What the truth key can show (plain C++, no Embree: the settings and the config fuzzer validate
// the names with it alone).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace obscura::ao_truth {

// What the truth key shows over the frame: nothing, the reference, the active mode's AO alone
// (its AO buffer, as scored), or the heat map. The key cycles them in this order.
enum class Show { Off, Reference, Mode, HeatMap };
const std::vector<std::string>& showNames();  // "off", "reference", "mode", "heatmap"
std::optional<Show> showFromName(const std::string& name);
const std::string& showName(Show s);
Show nextShow(Show s);

}  // namespace obscura::ao_truth
