// See level_triangles.h.
#include "raytrace/level_triangles.h"

#include "map/asset_path.h"
#include "mesh/ogre_mesh_reader.h"

#include <iostream>
#include <stdexcept>

namespace obscura {

std::vector<TriangleMesh> levelTriangles(const map::Level& level) {
    TriangleMesh m;
    for (const auto& b : level.brushes)
        for (const auto& f : b.faces) {
            if (!f.visible || f.sky) continue;  // sky: map/surface_rules.h
            const auto base = static_cast<std::uint32_t>(m.vertices.size());
            for (const auto& v : f.vertices) m.vertices.push_back(v.position);
            for (std::uint32_t i = 1; i + 1 < f.vertices.size(); ++i)
                m.indices.insert(m.indices.end(), {base, base + i, base + i + 1});
        }
    return {m};
}

// mesh::Transform is render::modelTransform, bit for bit.
void addModelTriangles(const map::Level& level, const std::vector<std::string>& searchDirs,
                       std::vector<TriangleMesh>& out, const std::string& logPrefix) {
    const map::LevelFiles files(level.sourcePath, searchDirs);
    for (const auto& m : level.models) {
        const std::string file = files.require(m.mesh, level.sourcePath + ":" + std::to_string(m.pos.line) + ": misc_model", "'model'");
        const mesh::MeshFile meshFile = mesh::readOgreMesh(file);
        out.push_back(mesh::meshTriangles(meshFile, {m.origin, m.yaw, m.scale}));
        if (logPrefix.empty()) continue;
        std::cerr << logPrefix << ": model " << m.mesh << " bounds ";
        if (meshFile.bounds) {
            // as Ogre::Vector3 prints (single precision)
            auto print = [](const Vec3& v) {
                std::cerr << "Vector3(" << static_cast<float>(v.x) << ", " << static_cast<float>(v.y) << ", "
                          << static_cast<float>(v.z) << ")";
            };
            print(meshFile.bounds->min);
            std::cerr << " .. ";
            print(meshFile.bounds->max);
        } else {
            std::cerr << "(none in the file)";
        }
        std::cerr << "\n";
    }
}

}  // namespace obscura
