// Liquids: which brushes are water, slime, lava or teleporter, how opaque they are drawn, and
// whether a point is inside one. Plain C++ (no OGRE, no Bullet): the compiler classifies brushes
// with it, the simulation asks it where the player is, the game asks it where the camera is.
//
// Classification follows Quake's and ericw-tools' conventions:
//   - a texture named `*...` is a liquid; `*slime...` slime, `*lava...` lava, `*tele...` a
//     teleporter, anything else (`*water1`, `*04water`, `*blood1`) water (Quake's qbsp);
//   - Quake 2 faces carry CONTENTS_LAVA 8, CONTENTS_SLIME 16, CONTENTS_WATER 32 in their content
//     flags (Quake 2's qfiles.h): those win over the name;
//   - `*waterskip`, `*slimeskip`, `*lavaskip`, `*teleskip` and `*skip` faces are not drawn (ericw
//     qbsp's skip faces for liquids), but still bound the volume.
// Opacity, as QuakeSpasm's R_ParseWorldspawn reads it: worldspawn `wateralpha`, `slimealpha`,
// `lavaalpha`, `telealpha`, each with or without a leading underscore (`_wateralpha`); a kind
// without its own key uses the water one; none at all: 1, opaque, as in Quake. A liquid brush
// entity's own `alpha`/`_alpha` (QuakeSpasm's entity alpha), then its own liquid keys, win over
// worldspawn's. Quake 2's
// SURF_TRANS33 / SURF_TRANS66 surface flags give 0.33 / 0.66.
#pragma once

#include "map/level.h"
#include "map/surface_rules.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace obscura::map {

// Quake 2 content bits (qfiles.h); the surface flags (TRANS33/66 among them) are in surface_rules.h.
constexpr std::uint32_t kQ2ContentsLava = 8, kQ2ContentsSlime = 16, kQ2ContentsWater = 32;

LiquidKind liquidKindOfTexture(const std::string& texture);  // None unless it starts with '*'
LiquidKind liquidKindOfContents(std::uint32_t q2Contents);             // None without a liquid bit
bool isLiquidSkipTexture(const std::string& texture);        // *waterskip, *slimeskip, *lavaskip, *teleskip, *skip
const char* liquidName(LiquidKind kind);                     // "water", "slime", ... ("none")
// Which of two overlapping liquids counts: lava 4, slime 3, water 2, teleporter 1, none 0.
int liquidHarm(LiquidKind kind);

// The worldspawn alpha key of `kind` (`[_]wateralpha`, ...): its value if present. A present key
// that is not a number from 0 to 1 sets `problem` (the caller warns naming the line) and gives
// nothing.
std::optional<double> liquidAlphaKey(const LevelEntity& entity, const std::string& key, std::string* problem);
// The opacity of a liquid of `kind` owned by `owner` (worldspawn or a brush entity), from the
// keys above; problems are appended to `problems`: where the entity holding the key opens, and
// "'key' value 'v' ...".
struct LiquidKeyProblem {
    SourcePos at;
    std::string what;
};
double liquidAlpha(const LevelEntity& worldspawn, const LevelEntity& owner, LiquidKind kind, std::vector<LiquidKeyProblem>* problems);

// True if p lies inside the convex brush (on its boundary counts), from its faces' planes. A brush
// without faces (built from hull points only) contains nothing.
bool pointInBrush(const LevelBrush& brush, const Vec3& p);

// The level's liquid volumes, for point queries.
class LiquidQuery {
public:
    LiquidQuery() = default;
    explicit LiquidQuery(const Level& level);
    // The liquid at p: the most harmful of the volumes containing it (lava over slime over water;
    // a teleporter counts below water), None outside all.
    LiquidKind at(const Vec3& p) const;
    bool empty() const { return volumes_.empty(); }
    std::size_t size() const { return volumes_.size(); }

private:
    struct Plane {
        Vec3 normal;  // outward, unit
        double dist;  // dot(normal, p) <= dist inside
    };
    struct Volume {
        LiquidKind kind;
        Aabb bounds;
        std::vector<Plane> planes;
    };
    std::vector<Volume> volumes_;
};

// Hides liquid faces that lie against a solid brush (the sides and bottom of a pool, as qbsp
// drops faces outside the world): a face is hidden when the point 1 cm out from its centre lies
// inside a solid worldspawn brush. Returns how many faces it hid.
std::size_t hideBuriedLiquidFaces(Level& level);

}  // namespace obscura::map
