// See sign_light.h.
#include "signs/sign_light.h"

#include "decals/glyph.h"
#include "decals/sdf.h"
#include "map/asset_path.h"
#include "map/entity_values.h"
#include "signs/signs_shared.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace obscura::signs {

namespace {
constexpr double kPi = 3.14159265358979323846;

// The stored mask's bounds. At most 2048 texels a side: the raster the distances come from is 4x
// finer, and 4 x 2048 = 8192 is decals::kMaxMaskEdge, the rasteriser's bound (GL 3.3 also only
// promises 1024..2048-texel textures on the drivers we run on: llvmpipe's limit is larger, but a
// sign is never worth more). At most 2^19 texels in all: the raster then has 2^23 pixels, ~75 MB
// while it is baked (a byte of mask and two floats of EDT a pixel), once per sign at level load.
// A long text (48 letters at 64 texels a letter is ~2300 texels wide) or a large margin gets
// coarser texels instead: texelsPerLetter falls until the plate fits.
constexpr int kMaxMaskSide = 2048;
constexpr long long kMaxMaskTexels = 1LL << 19;
constexpr int kRasterFactor = 4;  // raster pixels a stored texel, each way

// The keys' other bounds: a margin up to the letters' own bound; the intensity within what an
// 8-bit-exposed frame can show from a few centimetres of lamp (the default 6 is ~1 of irradiance
// at 2.5 m); a cone from 1 degree to a half space (beyond 90 degrees every point in front is
// inside it anyway: the lamp is behind the plate).
constexpr double kMaxMargin = kMaxLetterHeight, kMaxIntensity = 1000, kMinCone = 1, kMaxCone = 90;
const char* const kDefaultFont = "DejaVuSans-Bold.ttf";

struct Skip {
    std::string why;
};

std::string number(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

// One number; `fallback` when the key is absent. Skips a sign whose value is not exactly one
// finite number.
double numberOf(const map::LevelEntity& e, const char* key, double fallback, const char* unit) {
    if (!e.has(key)) return fallback;
    double v = 0;
    if (!map::valueNumbers(e.value(key), 1, &v))
        throw Skip{std::string("'") + key + "' is " + map::quotedValue(e.value(key)) + ", expected " + unit};
    if (!std::isfinite(v)) throw Skip{std::string("non-finite ") + key + " " + map::quotedValue(e.value(key))};
    return v;
}

// A length in metres within (lo, hi] (lo open unless `zeroAllowed`).
double metresOf(const map::LevelEntity& e, const char* key, double fallback, double hi, bool zeroAllowed = false) {
    const double m = numberOf(e, key, fallback, "metres");
    if (m < 0 || (m == 0 && !zeroAllowed) || m > hi)
        throw Skip{std::string(key) + " " + e.value(key) + " m is outside " + (zeroAllowed ? "[0, " : "(0, ") + number(hi) + "]"};
    return m;
}

std::string findFont(const std::string& name, const std::vector<std::string>& fontDirs) {
    if (name.empty()) throw Skip{"empty 'font'"};
    if (name.find('/') != std::string::npos || name.find('\\') != std::string::npos || name == "." || name == "..")
        throw Skip{"font " + map::quotedValue(name) + " is not a bare file name (fonts are looked up in the font folders)"};
    // Confined to the font folders themselves: a link beside the level that leads elsewhere is refused.
    const map::AssetPath found = map::resolveAsset(name, fontDirs, fontDirs, "the font folders");
    if (!found.error.empty()) throw Skip{"font " + map::quotedValue(name) + " " + found.error};
    if (!found.file.empty()) return found.file;
    std::string dirs;
    for (const auto& d : fontDirs) dirs += (dirs.empty() ? "" : ", ") + d;
    throw Skip{"font " + map::quotedValue(name) + " not found in " + (dirs.empty() ? std::string("(no font folder)") : dirs)};
}

SignSpec readSign(const map::Level& level, const map::LevelEntity& e, const std::vector<std::string>& fontDirs,
                  std::vector<std::string>& clamped) {
    SignSpec s;
    if (std::string why = map::readOrigin(e, s.centre); !why.empty()) throw Skip{why};
    map::Orientation turn;
    if (std::string why = map::readOrientation(e, turn); !why.empty()) throw Skip{why};
    s.right = turn.right, s.up = turn.up, s.facing = turn.facing;

    if (!e.has("text")) throw Skip{"no 'text'"};
    s.text = e.value("text");
    if (map::valueWords(s.text).empty()) throw Skip{"empty text"};
    if (s.text.size() > kMaxText) throw Skip{"text longer than " + std::to_string(kMaxText) + " characters"};
    s.fontFile = findFont(e.has("font") ? e.value("font") : std::string(kDefaultFont), fontDirs);

    s.letterHeight = metresOf(e, "size", s.letterHeight, kMaxLetterHeight);
    s.margin = metresOf(e, "margin", s.margin, kMaxMargin, true);
    if (std::string why = map::readColour(e, "_color", s.lightColour); !why.empty()) throw Skip{why};
    if (std::string why = map::readColour(e, "plate_color", s.plateColour); !why.empty()) throw Skip{why};
    if (e.has("light")) {
        s.intensity = numberOf(e, "light", s.intensity, "a number");
        if (s.intensity < 0 || s.intensity > kMaxIntensity)
            throw Skip{"light " + e.value("light") + " is outside [0, " + number(kMaxIntensity) + "]"};
    }
    s.lightRadius = metresOf(e, "light_radius", s.lightRadius, kMaxLightRadius);
    s.range = metresOf(e, "range", s.range, kMaxRange);
    if (e.has("cone")) {
        const double cone = numberOf(e, "cone", s.coneDegrees, "degrees");
        s.coneDegrees = std::clamp(cone, kMinCone, kMaxCone);
        if (s.coneDegrees != cone)
            clamped.push_back("cone " + e.value("cone") + " degrees clamped to " + number(s.coneDegrees));
    }

    // The lamp: `light_origin` (map coordinates) wins over `light_distance` behind the centre.
    if (e.has("light_origin")) {
        double q[3];
        if (!map::valueNumbers(e.value("light_origin"), 3, q))
            throw Skip{"'light_origin' is " + map::quotedValue(e.value("light_origin")) + ", expected three numbers"};
        if (!std::isfinite(q[0] + q[1] + q[2])) throw Skip{"non-finite light_origin " + map::quotedValue(e.value("light_origin"))};
        s.lamp = map::mapPointToWorld({q[0], q[1], q[2]}, level.unitsPerMetre);
        const double behind = dot(s.centre - s.lamp, s.facing);
        if (!(behind > 0)) throw Skip{"the light is in front of the sign's plane (light_origin " + e.value("light_origin") + ")"};
        if (length(s.lamp - s.centre) > kMaxLightDistance)
            throw Skip{"light_origin is " + number(length(s.lamp - s.centre)) + " m from the sign, over " + number(kMaxLightDistance)};
    } else {
        const double behind = numberOf(e, "light_distance", 0.3, "metres");
        if (behind <= 0) throw Skip{"the light is in front of the sign's plane (light_distance " + e.value("light_distance") + ")"};
        if (behind > kMaxLightDistance)
            throw Skip{"light_distance " + e.value("light_distance") + " m is outside (0, " + number(kMaxLightDistance) + "]"};
        s.lamp = s.centre - s.facing * behind;
    }
    return s;
}

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}
}  // namespace

std::vector<SignSpec> readSignLights(const map::Level& level, const std::vector<std::string>& fontDirs,
                                     std::vector<std::string>& warnings) {
    std::vector<SignSpec> out;
    for (const map::LevelEntity& e : level.entities) {
        if (e.classname != "light_sign") continue;
        const std::string where = e.where(level.sourcePath);
        std::vector<std::string> clamped;
        try {
            SignSpec s = readSign(level, e, fontDirs, clamped);
            s.where = where;
            out.push_back(std::move(s));
            for (const auto& c : clamped) warnings.push_back(where + ": light_sign: " + c);
        } catch (const Skip& skip) {
            warnings.push_back(where + ": light_sign skipped: " + skip.why);
        }
    }
    return out;
}

double SignMask::at(double x, double y, double* gx, double* gy) const {
    if (width <= 0 || height <= 0) {  // no mask: no letter anywhere
        if (gx) *gx = 0, *gy = 0;
        return -std::numeric_limits<double>::infinity();
    }
    const double uRaw = (x + halfWidth) / texel - 0.5, vRaw = (halfHeight - y) / texel - 0.5;
    const double u = std::clamp(uRaw, 0.0, width - 1.0);
    const double v = std::clamp(vRaw, 0.0, height - 1.0);
    const int i0 = std::min(static_cast<int>(u), width - 1), j0 = std::min(static_cast<int>(v), height - 1);
    const int i1 = std::min(i0 + 1, width - 1), j1 = std::min(j0 + 1, height - 1);
    const double fu = u - i0, fv = v - j0;
    auto d = [&](int i, int j) { return static_cast<double>(distance[static_cast<std::size_t>(j) * width + i]); };
    if (gx) {
        // The bilinear patch's own slope (per metre; v grows downwards, y upwards); 0 across a
        // clamped border.
        *gx = uRaw == u ? ((d(i1, j0) - d(i0, j0)) * (1 - fv) + (d(i1, j1) - d(i0, j1)) * fv) / texel : 0.0;
        *gy = vRaw == v ? -((d(i0, j1) - d(i0, j0)) * (1 - fu) + (d(i1, j1) - d(i1, j0)) * fu) / texel : 0.0;
    }
    return (d(i0, j0) * (1 - fu) + d(i1, j0) * fu) * (1 - fv) + (d(i0, j1) * (1 - fu) + d(i1, j1) * fu) * fv;
}

SignMask bakeMask(const SignSpec& sign, double spread, int texelsPerLetter) {
    if (!(sign.letterHeight > 0) || !std::isfinite(sign.letterHeight)) throw std::runtime_error(sign.where + ": the letter height must be positive");
    if (!(sign.margin >= 0) || !std::isfinite(sign.margin)) throw std::runtime_error(sign.where + ": the margin must not be negative");
    if (texelsPerLetter < 1) throw std::runtime_error("bakeMask: texelsPerLetter must be at least 1");
    // BakeError (a std::runtime_error) names the font or the character.
    decals::TextLayout text = decals::textLayout(sign.fontFile, sign.text);
    const double lh = sign.letterHeight;
    const double plateW = (text.x1 - text.x0) * lh + 2 * sign.margin, plateH = (text.y1 - text.y0) * lh + 2 * sign.margin;
    // The texel: texelsPerLetter a letter height, coarser where the plate would not fit the bounds.
    double texel = lh / texelsPerLetter;
    texel = std::max({texel, plateW / kMaxMaskSide, plateH / kMaxMaskSide, std::sqrt(plateW * plateH / kMaxMaskTexels)});
    SignMask m;
    m.texel = texel;
    m.width = std::clamp(static_cast<int>(std::ceil(plateW / texel - 1e-9)), 1, kMaxMaskSide);
    m.height = std::clamp(static_cast<int>(std::ceil(plateH / texel - 1e-9)), 1, kMaxMaskSide);
    // The plate is whole texels: the margin grows by under half a texel a side, so that texel
    // centres sit at -halfWidth + (i + 0.5) texel exactly (at() and the shader's lookup).
    m.halfWidth = m.width * texel / 2, m.halfHeight = m.height * texel / 2;
    m.spread = std::max(0.0, spread);

    // The outlines in metres from the plate's top-left corner, y down, the text centred.
    const double cx = (text.x0 + text.x1) / 2, cy = (text.y0 + text.y1) / 2;
    for (auto& c : text.shape.contours)
        for (decals::Point& p : c) p = {m.halfWidth + (p.x - cx) * lh, m.halfHeight - (p.y - cy) * lh};
    const double fine = texel / kRasterFactor;  // metres a raster pixel
    const decals::Mask raster = decals::rasterize(text.shape, m.width * kRasterFactor, m.height * kRasterFactor, 1 / fine);
    const decals::Field sd = decals::signedDistance(raster);  // raster pixels, > 0 inside

    // Each stored texel's centre is the corner of four raster pixels: their bilinear mean.
    m.distance.resize(static_cast<std::size_t>(m.width) * m.height);
    const float lim = static_cast<float>(m.spread);
    for (int j = 0; j < m.height; ++j)
        for (int i = 0; i < m.width; ++i) {
            const double d = sd.bilinear((i + 0.5) * kRasterFactor, (j + 0.5) * kRasterFactor) * fine;
            m.distance[static_cast<std::size_t>(j) * m.width + i] = std::clamp(static_cast<float>(d), -lim, lim);
        }
    return m;
}

double maxPenumbraRadius(const SignSpec& sign) {
    // r = R b / (a + b) grows with b; a point within `range` of the lamp lies at most range - a in
    // front of the plane (its distance along the facing from the lamp is at most the range).
    const double a = dot(sign.centre - sign.lamp, sign.facing);
    const double b = sign.range - a;
    if (!(b > 0) || !(a + b > 0)) return 0;
    return sign.lightRadius * b / (a + b);
}

void SignHoles::add(const Hole& h) {
    holes_.push_back(h);
    if (holes_.size() > static_cast<std::size_t>(SIGN_MAX_HOLES)) holes_.erase(holes_.begin());
}

double openDistance(const SignMask& mask, const std::vector<Hole>& holes, double x, double y) {
    double d = mask.at(x, y);
    for (const Hole& h : holes) d = std::max(d, h.radius - std::hypot(x - h.x, y - h.y));
    return d;
}

double discEdgeFraction(double d, double r) {
    const double x = std::clamp(d / r, -1.0, 1.0);
    return 0.5 + (x * std::sqrt(1 - x * x) + std::asin(x)) / kPi;
}

bool planeCrossing(const SignSpec& sign, const Vec3& p, double& x, double& y) {
    const double b = dot(p - sign.centre, sign.facing);
    const double a = dot(sign.centre - sign.lamp, sign.facing);
    if (!(b > 0) || !(a > 0)) return false;
    const Vec3 q = p + (sign.lamp - p) * (b / (a + b));
    x = dot(q - sign.centre, sign.right);
    y = dot(q - sign.centre, sign.up);
    return true;
}

double penumbraRadius(const SignSpec& sign, const Vec3& p) {
    const double b = dot(p - sign.centre, sign.facing);
    const double a = dot(sign.centre - sign.lamp, sign.facing);
    if (!(a + b > 0)) return 0;
    return sign.lightRadius * b / (a + b);
}

double penumbraAcrossEdge(double r, const Vec3& towardLamp, const SignSpec& sign, double gx, double gy) {
    const double cosPsi = std::fabs(dot(towardLamp, sign.facing));
    const double tx = dot(towardLamp, sign.right), ty = dot(towardLamp, sign.up), tilt = std::hypot(tx, ty);
    const double g = std::hypot(gx, gy);
    if (!(tilt > 1e-9) || !(g > 1e-12) || !(cosPsi > 1e-6)) return r;
    const double c = (gx * tx + gy * ty) / (g * tilt);  // cosine between the edge's normal and the tilt
    return r * std::sqrt(c * c / (cosPsi * cosPsi) + (1 - c * c));
}

double throughSign(const SignSpec& sign, const SignMask& mask, const std::vector<Hole>& holes, const Vec3& p) {
    double x = 0, y = 0;
    if (!planeCrossing(sign, p, x, y)) return 0;
    const Vec3 towardLamp = normalize(sign.lamp - p);
    const double cosPsi = std::fabs(dot(towardLamp, sign.facing));
    const double r0 = std::max(penumbraRadius(sign, p), 1e-6);
    // Outside the plate by more than the widest the lamp's image can be, the opaque edge alone hides
    // all of it (the open distance is at most the edge's): the mask is not read (most of a frame).
    if (std::min(mask.halfWidth - std::fabs(x), mask.halfHeight - std::fabs(y)) * cosPsi <= -r0) return 0;
    // The open distance (openDistance, then the plate's opaque edge) and the gradient of the term
    // that decides it: the mask's bilinear slope, a hole's radial one, or the edge's axis.
    double gx = 0, gy = 0;
    double d = mask.at(x, y, &gx, &gy);
    for (const Hole& hole : holes) {
        const double r = std::hypot(x - hole.x, y - hole.y), inside = hole.radius - r;
        if (inside <= d) continue;
        d = inside;
        gx = r > 0 ? -(x - hole.x) / r : 0.0, gy = r > 0 ? -(y - hole.y) / r : 0.0;
    }
    if (mask.halfWidth - std::fabs(x) < d) d = mask.halfWidth - std::fabs(x), gx = x > 0 ? -1.0 : 1.0, gy = 0;
    if (mask.halfHeight - std::fabs(y) < d) d = mask.halfHeight - std::fabs(y), gx = 0, gy = y > 0 ? -1.0 : 1.0;
    const double cone = kPi / 180 * sign.coneDegrees;
    const double inCone = smoothstep(std::cos(cone), std::cos(0.85 * cone), -dot(towardLamp, sign.facing));
    // Beyond the widest the ellipse can be (r0 / cos psi) the point sees all of the lamp or none
    // (most of a beam).
    if (std::fabs(d) * cosPsi >= r0) return (d > 0 ? 1.0 : 0.0) * inCone;
    return discEdgeFraction(d, penumbraAcrossEdge(r0, towardLamp, sign, gx, gy)) * inCone;
}

Vec3 signIrradiance(const SignSpec& sign, const SignMask& mask, const std::vector<Hole>& holes, const Vec3& p) {
    const double d = length(p - sign.lamp);
    const double f = d / sign.range, f4 = f * f * f * f;
    const double w = std::clamp(1 - f4, 0.0, 1.0);
    const double window = w * w;
    const double r = std::max(d, sign.lightRadius);
    return sign.lightColour * (sign.intensity * throughSign(sign, mask, holes, p) * window / (r * r));
}

void beamBounds(const SignSpec& sign, const SignMask& mask, Vec3& lo, Vec3& hi) {
    // The penumbra reaches at most the lamp's radius past an edge in the plate's plane, stretched
    // by 1 / cos psi off the axis (penumbraAcrossEdge); within the cone (<= 90 degrees, where
    // 1 / cos grows without bound) 4x covers psi up to 75 degrees, the widest default cone, and
    // the plate's own edge (the light's whole share is on its inner side) past that.
    const double margin = 4 * sign.lightRadius + 1e-3;
    const double a = std::max(dot(sign.centre - sign.lamp, sign.facing), 1e-6);
    // Points lit lie within `range` of the lamp, so along the axis no further than range: the
    // pyramid's corners scaled out to that plane bound it.
    const double scale = std::max(sign.range, a) / a;
    lo = hi = sign.lamp;
    for (int c = 0; c < 4; ++c) {
        const Vec3 corner = sign.centre + sign.right * ((c & 1 ? 1 : -1) * (mask.halfWidth + margin)) +
                            sign.up * ((c & 2 ? 1 : -1) * (mask.halfHeight + margin));
        const Vec3 far = sign.lamp + (corner - sign.lamp) * scale;
        lo = {std::min(lo.x, far.x), std::min(lo.y, far.y), std::min(lo.z, far.z)};
        hi = {std::max(hi.x, far.x), std::max(hi.y, far.y), std::max(hi.z, far.z)};
    }
}

}  // namespace obscura::signs
