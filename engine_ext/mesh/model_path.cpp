// See model_path.h.
#include "mesh/model_path.h"

#include <filesystem>

namespace obscura::mesh {

std::string findModelFile(const std::string& model, const std::vector<std::string>& searchDirs) {
    namespace fs = std::filesystem;
    if (model.empty()) return {};
    const fs::path m(model);
    std::vector<fs::path> candidates;
    if (m.is_absolute())
        candidates.push_back(m);
    else
        for (const std::string& dir : searchDirs) candidates.push_back(fs::path(dir) / m);
    for (const fs::path& c : candidates) {
        std::error_code ec;
        if (!fs::is_regular_file(c, ec)) continue;
        const fs::path canonical = fs::canonical(c, ec);
        return ec ? c.string() : canonical.string();
    }
    return {};
}

}  // namespace obscura::mesh
