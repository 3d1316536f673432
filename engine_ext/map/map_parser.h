// Parser for Quake `.map` files as TrenchBroom writes them: entities of quoted key/value pairs and
// brushes of faces, each face either classic Quake
//   ( x y z ) ( x y z ) ( x y z ) TEXTURE xoff yoff rot xscale yscale
// or Valve-220 (worldspawn "mapversion" "220")
//   ( x y z ) ( x y z ) ( x y z ) TEXTURE [ ux uy uz uoff ] [ vx vy vz voff ] rot xscale yscale
// either optionally followed by Quake 2's `contents surfaceflags value` (kept in MapFace).
// `//` comments anywhere. Quake 3 `patchDef2`/`brushDef*` blocks are skipped with a warning.
// Reference: the Quake map format as documented by the Quake Wiki and TrenchBroom's manual.
#pragma once

#include "map/level.h"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace obscura::map {

// A malformed map: the message is `file:line:column: problem`.
struct MapError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Limits on what one .map may hold; beyond them loading stops with a `file:line:column` error.
// Each is far above real maps (LibreQuake e3m4, 3.2 MB: 1,301 entities, 3,441 brushes, 22,180
// faces, at most 31 faces in a brush) and low enough that a hostile file stays cheap: a brush's
// faces are clipped against each other (O(faces^2)), so 128 faces cost ~16k clips, where 16k
// planes in one brush took about a minute.
constexpr std::size_t kMaxMapFileBytes = 64u << 20;
constexpr std::size_t kMaxEntitiesPerMap = 65536;
constexpr std::size_t kMaxKeysPerEntity = 1024;
constexpr std::size_t kMaxBrushesPerMap = 65536;
constexpr std::size_t kMaxFacesPerBrush = 128;
constexpr std::size_t kMaxFacesPerMap = 1u << 18;

struct MapFace {
    Vec3 points[3];  // map units, Quake axes (Z up)
    std::string texture;
    bool valve220 = false;
    Vec3 uAxis, vAxis;  // Valve-220 only
    double uOffset = 0, vOffset = 0, rotation = 0, uScale = 1, vScale = 1;
    // Quake 2 / Quake 3 / ericw faces end with `contents flags value` (qfiles.h's CONTENTS_*,
    // SURF_*; value is e.g. a light's brightness); hasFlags says whether this face wrote them.
    bool hasFlags = false;
    std::uint32_t contents = 0, surfaceFlags = 0;
    int value = 0;
    SourcePos pos;
};

struct MapBrush {
    std::vector<MapFace> faces;
    SourcePos pos;
};

struct MapEntity {
    std::vector<std::pair<std::string, std::string>> keys;
    std::vector<MapBrush> brushes;
    SourcePos pos;
    std::string file;  // the file it was read from when not the map's own (an overlay: addEntityOverlay)
    const std::string& value(const std::string& key) const;  // "" when absent
    bool has(const std::string& key) const;
};

struct MapFile {
    std::string path;
    std::vector<MapEntity> entities;
    std::vector<std::string> warnings;  // skipped blocks, `file:line: ...`
};

MapFile parseMap(std::string_view text, const std::string& fileName);
// Throws MapError if unreadable (missing, a directory or device, over kMaxMapFileBytes) or malformed.
MapFile loadMapFile(const std::string& path);

}  // namespace obscura::map
