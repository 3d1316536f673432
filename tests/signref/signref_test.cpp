// tools/signref/shaft_reference.h: the integral against a brute force, the sampled lamp against
// the penumbra law, the level's occlusion, determinism, and the medium's smoke noise.
#include <gtest/gtest.h>

#include "signref/shaft_reference.h"

#include <cmath>

using namespace obscura;
using namespace obscura::signref;

namespace {
// A sign at the origin facing +z, its lamp 0.3 m behind. Its mask is shut everywhere; `holes`
// open it: a hole of radius 1000 centred 1000 m to the left is (to 1e-4 m over a metre) the
// straight edge x = 0, open at x < 0; one of radius 100 at the centre opens the whole plate.
SignLight testSign(double lampRadius, std::vector<signs::Hole> holes) {
    SignLight s;
    s.spec.where = "test";
    s.spec.text = "X";
    s.spec.centre = {0, 0, 0};
    s.spec.lamp = {0, 0, -0.3};
    s.spec.lightRadius = lampRadius;
    s.spec.range = 64;
    s.mask.width = s.mask.height = 1;
    s.mask.texel = 100;
    s.mask.halfWidth = s.mask.halfHeight = 50;
    s.mask.spread = 0.01;
    s.mask.distance = {-0.01f};
    s.holes = std::move(holes);
    return s;
}
const std::vector<signs::Hole> kOpen{{0, 0, 100}};
const std::vector<signs::Hole> kEdge{{-1000, 0, 1000}};
}  // namespace

TEST(SignrefPhase, IsHenyeyGreensteinTimesPi) {
    EXPECT_NEAR(phaseHG(0.3, 0.0), 0.25, 1e-15);  // isotropic: 1 / (4 pi) x pi
    // the integral over the sphere of HG is 1: of phase x pi, pi (midpoint rule in cos theta)
    double sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) sum += phaseHG(-1 + (i + 0.5) * 2.0 / n, kShaftG) * 2.0 / n * 2 * 3.14159265358979323846;
    EXPECT_NEAR(sum, 3.14159265358979323846, 1e-6);
}

TEST(SignrefIntegral, PureHazeMatchesABruteForceIntegral) {
    // An open plate (throughSign's law is exact there: share 1), a tiny lamp, a uniform haze, no
    // geometry: alongRay against a fine midpoint rule of the header's own signIrradiance.
    const RayScene empty({});
    const Medium haze{0.15, nullptr};
    const SignLight sign = testSign(1e-4, kOpen);
    const ShaftReference ref(empty, {sign}, haze);
    const Vec3 eye{0.8, 0.5, 6}, dir = normalize(Vec3{-0.1, -0.05, -1});
    const double tmax = 7;  // through the plate's plane (nothing behind it is lit)
    ShaftOptions opt;
    opt.step = 0.002;
    opt.lampSamples = 1;
    Rng rng(7);
    const Vec3 got = ref.alongRay(eye, dir, tmax, opt, rng);

    Vec3 want;
    const int n = 400000;
    const double dt = tmax / n;
    for (int i = 0; i < n; ++i) {
        const double t = (i + 0.5) * dt;
        const Vec3 p = eye + dir * t;
        const Vec3 e = signs::signIrradiance(sign.spec, sign.mask, sign.holes, p);
        // dimmed on the way from the camera (t) and from the lamp (|p - lamp|) alike
        want += e * (std::exp(-haze.haze * (t + length(p - sign.spec.lamp))) * haze.haze *
                     phaseHG(dot(dir, normalize(p - sign.spec.lamp)), kShaftG) * dt);
    }
    ASSERT_GT(want.x, 0);
    EXPECT_NEAR(got.x / want.x, 1, 2e-3);
    EXPECT_NEAR(got.y / want.y, 1, 2e-3);
    EXPECT_NEAR(got.z / want.z, 1, 2e-3);
}

TEST(SignrefIntegral, UniformSourceMatchesTheClosedForm) {
    // Far from a dim lamp the source is nearly constant along a short ray: L = S (1 - exp(-s t)).
    const RayScene empty({});
    const Medium haze{0.8, nullptr};
    SignLight sign = testSign(1e-4, kOpen);
    sign.spec.lamp = {0, 0, -40};  // 40 m behind: over the ray (0.5 m long, 3 m in front) E varies 1e-3
    const ShaftReference ref(empty, {sign}, haze);
    const Vec3 eye{0, 0, 3}, dir{1, 0, 0};
    ShaftOptions opt;
    opt.step = 0.01;
    opt.lampSamples = 1;
    opt.shadowStep = 0;  // the source as it leaves the lamp (the haze between would dim it e^-34)
    Rng rng(3);
    const Vec3 got = ref.alongRay(eye, dir, 0.5, opt, rng);
    const Vec3 e = unshadowedIrradiance(sign.spec, eye + dir * 0.25);
    const double phase = phaseHG(dot(dir, normalize(eye + dir * 0.25 - sign.spec.lamp)), kShaftG);
    EXPECT_NEAR(got.x / (e.x * phase * (1 - std::exp(-0.8 * 0.5))), 1, 2e-3);
}

// The lamp's light dimmed on its way by a physical haze: e^(-sigma d), d the distance to the lamp
// (43 m here, varying by 3 mm over the ray).
TEST(SignrefIntegral, TheHazeDimsTheLampsLightOnItsWay) {
    const RayScene empty({});
    const Medium haze{0.1, nullptr};
    SignLight sign = testSign(1e-4, kOpen);
    sign.spec.lamp = {0, 0, -40};
    const ShaftReference ref(empty, {sign}, haze);
    const Vec3 eye{0, 0, 3}, dir{1, 0, 0};
    ShaftOptions opt;
    opt.step = 0.01;
    opt.lampSamples = 1;
    Rng a(3), b(3);
    const Vec3 dimmed = ref.alongRay(eye, dir, 0.5, opt, a);
    opt.shadowStep = 0;
    const Vec3 open = ref.alongRay(eye, dir, 0.5, opt, b);
    EXPECT_NEAR(dimmed.x / open.x, std::exp(-0.1 * length(eye + dir * 0.25 - sign.spec.lamp)), 1e-4);
}

// Medium::opticalDepth over a segment half inside a smoke grid: the haze's share exactly, the
// smoke's only inside the grid's box, against a 1 mm sum of Medium::at over the whole segment.
TEST(SignrefMedium, OpticalDepthCountsTheSmokeInsideItsGridOnly) {
    smoke::SmokeDump dump;
    dump.time = 0.7;
    dump.sigma = 4;
    smoke::DumpVolume v;
    v.nx = v.ny = v.nz = 8;
    v.origin = {0, 0, 0};
    v.cellSize = 0.25;
    v.density.resize(512);
    for (int i = 0; i < 512; ++i) v.density[static_cast<std::size_t>(i)] = 0.2f + 0.1f * static_cast<float>(i % 7);
    dump.volumes.push_back(v);
    const Medium m{0.05, &dump, -1};
    const Vec3 a{-1.5, 0.9, 1.1}, b{1.1, 1.3, 0.7};  // enters the 2 m box at x = 0
    double sum = 0;
    const int n = 20000;
    for (int k = 0; k < n; ++k) {
        double sigmaT;
        Vec3 sigmaS;
        m.at(a + (b - a) * ((k + 0.5) / n), sigmaT, sigmaS);
        sum += sigmaT * length(b - a) / n;
    }
    EXPECT_NEAR(m.opticalDepth(a, b, 0.01, 0.5), sum, 2e-3 * sum);
    EXPECT_GT(sum, 0.05 * length(b - a) + 0.5) << "the segment crosses smoke";
    EXPECT_DOUBLE_EQ(m.opticalDepth({-3, 1, 1}, {-1, 1, 1}, 0.01, 0.5), 0.05 * 2) << "outside the grid: the haze alone";
}

TEST(SignrefLamp, OpenPlateShowsTheWholeLampAndAWallHidesIt) {
    const SignLight sign = testSign(0.03, kOpen);
    Rng rng(1);
    EXPECT_EQ(lampShare(sign, nullptr, {0.2, 0.1, 2}, 64, rng), 1.0);
    EXPECT_EQ(lampShare(sign, nullptr, {0.2, 0.1, -0.1}, 64, rng), 0.0);  // behind the plate
    // a 2 x 2 m wall at z = 1 between the point and the plate; the plate is not in the scene
    TriangleMesh wall;
    wall.vertices = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    wall.indices = {0, 1, 2, 0, 2, 3};
    const RayScene scene({wall});
    EXPECT_EQ(lampShare(sign, &scene, {0.2, 0.1, 2}, 64, rng), 0.0);
    EXPECT_EQ(lampShare(sign, &scene, {0.2, 0.1, 0.5}, 64, rng), 1.0);  // between the wall and the plate
}

TEST(SignrefLamp, HalfTheLampAtTheEdgesShadowLine) {
    const SignLight sign = testSign(0.03, kEdge);
    Rng rng(2);
    EXPECT_NEAR(lampShare(sign, nullptr, {0, 0.3, 2}, 16384, rng), 0.5, 0.01);
    EXPECT_EQ(lampShare(sign, nullptr, {0.5, 0.3, 2}, 256, rng), 0.0);
    EXPECT_EQ(lampShare(sign, nullptr, {-0.5, 0.3, 2}, 256, rng), 1.0);
}

TEST(SignrefEdge, DiscProfileShare) {
    // the 10 % and 90 % points of the disc-segment profile, +-0.68705 r
    EXPECT_NEAR(discEdge1090Share(), 0.6870488, 1e-6);
    EXPECT_NEAR(signs::discEdgeFraction(0.6870488, 1.0), 0.9, 1e-6);
}

TEST(SignrefEdge, Width1090OfARamp) {
    std::vector<double> s, v;
    for (int i = 0; i <= 100; ++i) {
        s.push_back(i * 0.01);
        v.push_back(std::clamp((i * 0.01 - 0.3) / 0.4, 0.0, 1.0) * 5 + 2);  // 2..7 over 0.3..0.7 m
    }
    double w = 0, s50 = 0;
    ASSERT_TRUE(width1090(s, v, w, s50));
    EXPECT_NEAR(w, 0.32, 1e-9);
    EXPECT_NEAR(s50, 0.5, 1e-9);
    std::reverse(v.begin(), v.end());  // falling: the same width
    ASSERT_TRUE(width1090(s, v, w, s50));
    EXPECT_NEAR(w, 0.32, 1e-9);
    EXPECT_FALSE(width1090(s, std::vector<double>(s.size(), 1.0), w, s50));  // flat
}

TEST(SignrefEdge, SampledTruthMatchesThePenumbraLaw) {
    // A straight edge, lamp R = 0.03 m at a = 0.3 m behind, receivers b = 2 m in front: the
    // penumbra is 2 R b / a = 0.4 m wide, its 10-90 % width 0.687 x that = 0.2748 m.
    const SignLight sign = testSign(0.03, kEdge);
    const EdgeMeasure m = measureEdge(sign, nullptr, {-0.5, 0.3, 2}, {0.5, 0.3, 2}, 201, 4096, 5);
    ASSERT_TRUE(m.found);
    EXPECT_NEAR(m.b, 2, 1e-6);
    EXPECT_NEAR(m.a, 0.3, 1e-12);
    EXPECT_NEAR(m.penumbra, 0.4, 1e-6);
    EXPECT_NEAR(m.penumbra1090, 0.6870488 * 0.4, 1e-6);
    EXPECT_NEAR(m.width1090 / m.penumbra1090, 1, 0.03);
}

TEST(SignrefRender, DeterministicAcrossThreadsAndCullingIsExact) {
    // A room-like box around the sign, a camera looking at it through the shafts.
    TriangleMesh floor;
    floor.vertices = {{-5, -2.5, -1}, {5, -2.5, -1}, {5, -2.5, 8}, {-5, -2.5, 8}};
    floor.indices = {0, 2, 1, 0, 3, 2};
    const RayScene scene({floor});
    const Medium haze{0.05, nullptr};
    const ShaftReference ref(scene, {testSign(0.03, {{0.1, 0.05, 0.08}, {-0.15, 0.0, 0.05}})}, haze);
    CameraPose pose;
    pose.eye = {1.5, -0.5, 4};
    pose.yaw = 0.3;
    ShaftOptions opt;
    opt.spp = 2;
    opt.step = 0.05;
    opt.lampSamples = 4;
    const FloatImage a = ref.render(pose, 24, 14, opt, 1);
    const FloatImage b = ref.render(pose, 24, 14, opt, 3);
    EXPECT_EQ(a.rgb, b.rgb);
    opt.cull = false;
    const FloatImage c = ref.render(pose, 24, 14, opt, 2);
    EXPECT_EQ(a.rgb, c.rgb);
    double sum = 0;
    for (float f : a.rgb) sum += f;
    EXPECT_GT(sum, 0);  // the holes' shafts are in view
}

TEST(SignrefCompare, RmseAndTheOffBaseline) {
    FloatImage ref{2, 1, {1, 2, 3, 0, 0, 0}}, game{2, 1, {1, 2, 3, 0, 0, 6}};
    const ShaftError e = compareShafts(ref, game);
    EXPECT_NEAR(e.rmse, std::sqrt(36.0 / 6), 1e-12);
    EXPECT_NEAR(e.rmseOff, std::sqrt(14.0 / 6), 1e-12);
    EXPECT_NEAR(e.meanRef, 1.0, 1e-12);
    EXPECT_EQ(e.maxRef, 3.0);
    EXPECT_EQ(e.pixels, 2u);
    EXPECT_THROW(compareShafts(ref, FloatImage{1, 2, {0, 0, 0, 0, 0, 0}}), std::runtime_error);
    game.rgb[0] = NAN;
    EXPECT_THROW(compareShafts(ref, game), std::runtime_error);
}

TEST(SignrefMedium, SmokeNoiseMirrorsTheShader) {
    // smokeHash(0): fract(0.1) = 0.1, x 17 = 1.7, fract(1.7^3 x 5.1) = fract(25.0563)
    EXPECT_NEAR(smokeHash({0, 0, 0}), 0.0563, 1e-9);
    // the noise interpolates the lattice's hashes: at a lattice point it is the hash
    EXPECT_NEAR(smokeNoise({3, -2, 5}), smokeHash({3, -2, 5}), 1e-12);
    // kNoiseTurn is a rotation
    const Vec3 v{0.3, -1.2, 2.5};
    EXPECT_NEAR(length(noiseTurn(v)), length(v), 1e-12);
    EXPECT_NEAR(noiseTurn({1, 0, 0}).y, 0.80, 1e-15);  // its first column: GLSL is column-major
    for (int i = 0; i < 1000; ++i) {
        const double d = smokeDetail({i * 0.037, i * 0.011 - 3, i * 0.023}, 1.5);
        EXPECT_GE(d, 0.40);
        EXPECT_LE(d, 1.30);
    }
    // the drift: detail(p, t) = detail(p + (0, -0.3 t, 0), 0)
    EXPECT_DOUBLE_EQ(smokeDetail({1, 2, 3}, 2.0), smokeDetail({1, 2 - 0.6, 3}, 0.0));
}

TEST(SignrefMedium, SmokeAddsExtinctionAndItsAlbedo) {
    smoke::SmokeDump dump;
    dump.time = 0.5;
    dump.sigma = 4;
    smoke::DumpVolume v;
    v.nx = v.ny = v.nz = 2;
    v.origin = {0, 0, 0};
    v.cellSize = 0.25;
    v.density.assign(8, 1.0f);
    dump.volumes.push_back(v);
    const Medium m{0.1, &dump};
    double st;
    Vec3 ss;
    const Vec3 p{0.2, 0.3, 0.1};
    m.at(p, st, ss);
    const double smoke = 4 * smokeDetail(p, 0.5);
    EXPECT_NEAR(st, 0.1 + smoke, 1e-12);
    EXPECT_NEAR(ss.x, 0.1 + 0.9 * smoke, 1e-12);
    EXPECT_NEAR(ss.z, 0.1 + 0.88 * smoke, 1e-12);
    m.at({0.6, 0.3, 0.1}, st, ss);  // outside the grid: the haze alone
    EXPECT_EQ(st, 0.1);
    dump.volumes[0].density.assign(8, 0.003f);  // below the march's cutoff
    m.at(p, st, ss);
    EXPECT_EQ(st, 0.1);
}

TEST(SignrefLaw, AgreesWithTheTruthWhereTheLawIsExactAndSeesWalls) {
    // An open plate and a tiny lamp: throughSign is 1 where the truth's share is 1.
    const RayScene empty({});
    const Medium haze{0.1, nullptr};
    const ShaftReference ref(empty, {testSign(1e-4, kOpen)}, haze);
    const Vec3 eye{0.5, 0.2, 4}, dir = normalize(Vec3{-0.1, 0, -1});
    ShaftOptions opt;
    opt.step = 0.05;
    opt.lampSamples = 2;
    Rng r1(9), r2(9);
    const Vec3 truth = ref.alongRay(eye, dir, 5, opt, r1);
    opt.law = true;
    const Vec3 law = ref.alongRay(eye, dir, 5, opt, r2);
    EXPECT_NEAR(law.x / truth.x, 1, 1e-9);
    // a wall between the point and the plate hides the law's light too
    TriangleMesh wall;
    wall.vertices = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    wall.indices = {0, 1, 2, 0, 2, 3};
    const RayScene scene({wall});
    const SignLight sign = testSign(0.03, kOpen);
    EXPECT_EQ(lawIrradiance(sign, &scene, {0.2, 0.1, 2}).x, 0.0);
    EXPECT_GT(lawIrradiance(sign, &scene, {0.2, 0.1, 0.5}).x, 0.0);
    EXPECT_EQ(lawIrradiance(sign, nullptr, {0.2, 0.1, 2}).x, signs::signIrradiance(sign.spec, sign.mask, sign.holes, {0.2, 0.1, 2}).x);
}
