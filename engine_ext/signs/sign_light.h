// Back-lit text signs (issue 15), the plain-C++ core: the `light_sign` entity, the letters' mask as
// a distance field, bullet holes in it, and the light that passes through it. No OGRE: the GLSL
// (shaders/signs/sign_light.glsl) mirrors throughSign() line for line, and the ray-traced reference
// (tools/signref) calls it directly, so game and reference share one definition of the light.
//
// Geometry. A sign is a flat opaque plate (its housing hides the lamp: no light leaves except
// through the plate) centred at `centre`, spanned by `right` and `up`, facing `facing` (towards the
// room; the light travels along it). The lamp is a sphere of `lightRadius` at `lamp`, behind the
// plate. Light reaches a point p in front of the plate only
// along the segment p -> lamp, which crosses the plate's plane at one point q; it passes where q
// lies inside a letter (or a bullet hole). With a spherical lamp the edge of a letter casts a
// penumbra: the lamp seen from p through the plane is a disc of radius r = R b / (a + b) in the
// plane (R the lamp's radius, b = p's distance in front of the plane, a = the lamp's behind it),
// so a receiver's penumbra is 2 R b / a wide, the issue's "radius x distance behind the sign /
// distance in front". The visible fraction of that disc at a straight edge a signed
// distance d inside the letter is the disc-segment area, discEdgeFraction(d, r) (exact for
// straight edges, the letters' curves are large against r).
//
// Plate coordinates: metres, x along `right`, y along `up`, from the centre; the plate spans
// [-halfWidth, halfWidth] x [-halfHeight, halfHeight].
#pragma once

#include "core/vec3.h"
#include "map/level.h"

#include <cstddef>
#include <string>
#include <vector>

namespace obscura::signs {

// One `light_sign` entity as read from a level (keys and defaults: entity_classes.cpp).
struct SignSpec {
    std::string where;          // "file:line" of the entity, for messages
    std::string text;           // 1..kMaxText characters (Latin-1 bytes)
    std::string fontFile;       // the resolved font path (fonts-dejavu-core by default)
    Vec3 centre;                // world, metres
    Vec3 right{1, 0, 0}, up{0, 1, 0}, facing{0, 0, 1};  // orthonormal; facing = cross(right, up)
    double letterHeight = 0.4;  // metres: the font's em on the plate (`size`)
    double margin = 0.1;        // metres of plate around the text
    Vec3 plateColour{0.05, 0.05, 0.06};   // linear albedo of the plate's front
    Vec3 lightColour{1.0, 0.85, 0.6};     // linear
    double intensity = 6;       // radiance scale: irradiance at 1 m, straight through, unoccluded
    Vec3 lamp;                  // the lamp's centre, world metres, behind the plate (`light_distance`
                                // behind the centre, or `light_origin`)
    double lightRadius = 0.03;  // metres (> 0): the lamp's sphere, the penumbra's width
    double coneDegrees = 75;    // half angle about `facing` beyond which the lamp gives nothing
    double range = 12;          // metres from the lamp where the light has faded to zero
};

// Accepted ranges (the reasons in sign_light.cpp).
constexpr std::size_t kMaxText = 48;
constexpr double kMaxLetterHeight = 4, kMaxLightDistance = 8, kMaxLightRadius = 1, kMaxRange = 64;

// Every valid light_sign of `level`, in file order. `fontDirs`: where a `font` key's bare file name
// is looked for (the game passes /usr/share/fonts/truetype/dejavu). A bad sign (empty text, a font
// that is not found, size or radius <= 0 or out of range, the lamp in front of the plate) is
// skipped with "file:line: light_sign skipped: <why>" added to `warnings`; a value merely clamped
// adds "file:line: light_sign: <what>" and the sign stays.
std::vector<SignSpec> readSignLights(const map::Level& level, const std::vector<std::string>& fontDirs,
                                     std::vector<std::string>& warnings);

// The letters as a signed distance field over the whole plate: metres, > 0 inside a letter (where
// light passes), exact (EDT of a fine raster) out to `spread`, clamped to +-spread beyond.
struct SignMask {
    int width = 0, height = 0;          // texels
    double texel = 0;                   // metres a texel
    double halfWidth = 0, halfHeight = 0;  // the plate, metres (text extent + margin)
    double spread = 0;                  // metres
    std::vector<float> distance;        // width * height, row-major, top row (+y) first
    // Bilinear between texel centres, clamped at the border; plate coordinates in metres. With
    // gx, gy: the bilinear patch's gradient there too (per metre; 0 across a clamped border).
    double at(double x, double y, double* gx = nullptr, double* gy = nullptr) const;
};

// The mask of `sign`: its text laid out with the font's advances, at `texelsPerLetter` texels per
// letterHeight (the stored resolution; the raster it is computed from is 4x finer). Throws
// std::runtime_error naming the font or character that cannot be read.
SignMask bakeMask(const SignSpec& sign, double spread, int texelsPerLetter = 64);

// The widest penumbra the sign casts within its range: the spread its mask needs (metres).
double maxPenumbraRadius(const SignSpec& sign);

// A bullet hole through the plate: an open disc in plate coordinates (metres).
struct Hole {
    double x = 0, y = 0, radius = 0;
};
// A sign's holes, at most SIGN_MAX_HOLES (shaders/signs/signs_shared.h); the oldest closes first.
class SignHoles {
public:
    void add(const Hole& h);
    const std::vector<Hole>& holes() const { return holes_; }
    void clear() { holes_.clear(); }

private:
    std::vector<Hole> holes_;
};

// The mask with the holes: max(mask distance, radius - distance to each hole's centre).
double openDistance(const SignMask& mask, const std::vector<Hole>& holes, double x, double y);

// Fraction of a disc of radius r (> 0) on the inner side of a straight edge its centre lies a
// signed distance d inside of (d < 0: outside): 0 at d <= -r, 1/2 at 0, 1 at d >= r.
double discEdgeFraction(double d, double r);

// Where the segment from p to the lamp's centre crosses the plate's plane, in plate coordinates;
// false when p is not in front of the plate (on the lamp's side or in its plane).
bool planeCrossing(const SignSpec& sign, const Vec3& p, double& x, double& y);

// The lamp's disc radius in the plate's plane seen from p (metres): R b / (a + b), with
// b = dot(p - centre, facing) and a = dot(centre - lamp, facing) (p in front: b > 0).
double penumbraRadius(const SignSpec& sign, const Vec3& p);

// The lamp's disc radius across an edge whose in-plane normal is (gx, gy) (plate axes), seen along
// `towardLamp` (unit, p -> lamp): a sphere seen at psi off the plate's normal images in the plane as
// an ellipse 1 / cos(psi) longer along the tilt (the in-plane part of towardLamp), so across an edge
// whose normal makes angle e with the tilt its half-width is r sqrt(cos^2 e / cos^2 psi + sin^2 e);
// the disc-segment fraction of that ellipse is the disc's at that radius (an affine map keeps areas'
// ratios). r unchanged on the axis or where the edge's normal is undefined.
double penumbraAcrossEdge(double r, const Vec3& towardLamp, const SignSpec& sign, double gx, double gy);

// The share of the lamp that p sees through the sign, 0..1 (no other geometry: the game's shadow
// map and the reference's rays add that):
//   0 unless planeCrossing(p) gives (x, y);
//   d = min(openDistance(x, y), halfWidth - |x|, halfHeight - |y|)   (the plate's edge is opaque)
//   (gx, gy) = the gradient of the term that decides d: the mask's bilinear patch (SignMask::at),
//   the winning hole's radial direction, or the plate edge's axis
//   (beyond |d| cos psi >= penumbraRadius the lamp is all seen or all hidden: no gradient needed;
//   where the plate edge's distance alone is below -penumbraRadius / cos psi the result is 0 and
//   the mask is not read)
//   cone = smoothstep(cos(coneDegrees), cos(0.85 coneDegrees), dot(normalize(p - lamp), facing))
//   throughSign = discEdgeFraction(d, penumbraAcrossEdge(max(penumbraRadius(p), 1e-6),
//                                  normalize(lamp - p), gx, gy)) x cone
double throughSign(const SignSpec& sign, const SignMask& mask, const std::vector<Hole>& holes, const Vec3& p);

// A box holding every point the sign's light reaches (signIrradiance > 0): the pyramid from the
// lamp through the plate, widened by the lamp's penumbra, cut where its axis passes the range
// (no point of it beyond the range is lit). The renderer skips a sign whose box is out of view.
void beamBounds(const SignSpec& sign, const SignMask& mask, Vec3& lo, Vec3& hi);

// The light the lamp sends to p through the sign, before occlusion by geometry: irradiance on a
// surface facing the lamp (linear rgb) = lightColour x intensity x throughSign x window(d) /
// max(d, lightRadius)^2, d = |p - lamp|, window(d) = clamp(1 - (d / range)^4, 0, 1)^2 (inverse
// square, faded to exactly 0 at the range: Karis 2013).
Vec3 signIrradiance(const SignSpec& sign, const SignMask& mask, const std::vector<Hole>& holes, const Vec3& p);

}  // namespace obscura::signs
