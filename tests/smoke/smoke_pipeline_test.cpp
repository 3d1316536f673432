// The smoke's worker (smoke/smoke_pipeline.h): each frame it publishes is, bit for bit, the
// synchronous manager's frame after the step before, whatever the thread timing; a failed release
// changes nothing; the lamps are chosen by their reach and brightness at the smoke's boxes.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <random>
#include <thread>

#include "smoke/smoke_pipeline.h"
#include "smoke/smoke_shared.h"
#include "smoke_test_levels.h"

using namespace obscura;
using namespace obscura::smoke;

namespace {
constexpr double kDt = 0.05;
constexpr int kSteps = 16;
const Vec3 kSun = normalize(Vec3{0.3, 1, 0.2});
const Vec3 kShot{1, 0, 0};  // every carve: 4 m along +x

// A script of what a game does to its smoke: the releases and shots before step s (0-based).
const std::vector<std::pair<int, Vec3>> kSpawns{{0, {-1.5, 0.3, 0}}, {6, {1.5, 0.3, 0.5}}};
const std::vector<std::pair<int, Vec3>> kCarves{{4, {-3, 1.0, 0}}, {9, {-3, 0.6, 0.4}}};
const std::vector<SmokeLamp> kLevelLamps{{{-2.0, 2.2, 0.0}, {1.0, 0.8, 0.6}, 5.0}, {{3.0, 2.2, 1.0}, {0.4, 0.5, 1.0}, 4.0}};
const std::vector<SmokeLamp> kSignLamps{{{0.0, 2.0, -1.2}, {3.0, 2.5, 2.0}, 6.0}};

const map::Level& level() {
    static const map::Level l = testlevels::doorwayRooms();
    return l;
}

// FNV-1a over the frame's volumes: ids, fields, lamp maps, and the lamps chosen.
std::uint64_t hashOf(const SmokeFrame& f) {
    std::uint64_t h = 1469598103934665603ull;
    auto bytes = [&h](const void* p, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) h = (h ^ static_cast<const unsigned char*>(p)[i]) * 1099511628211ull;
    };
    for (const auto& v : f.volumes) {
        bytes(&v.id, sizeof v.id);
        bytes(v.fields.data(), v.fields.size() * sizeof(float));
        bytes(v.lamps.data(), v.lamps.size() * sizeof(float));
    }
    for (const Vec3& p : f.lamps.shadowed) bytes(&p, sizeof p);
    bytes(&f.lamps.shadowedLevelLamps, sizeof f.lamps.shadowedLevelLamps);
    return h;
}

// The script through a pipeline: each step's published frame hashed. With a seed, the game
// thread sleeps a random 0..3 ms around every call: a different timing each run.
std::vector<std::uint64_t> playPipeline(std::uint32_t seed) {
    SmokePipeline p(4, testlevels::small(24), level(), {});
    p.setLamps(kLevelLamps, kSignLamps);
    std::mt19937 rng(seed);
    auto pause = [&] {
        if (seed) std::this_thread::sleep_for(std::chrono::microseconds(rng() % 3000));
    };
    std::vector<std::uint64_t> hashes;
    for (int s = 0; s < kSteps; ++s) {
        for (const auto& [at, where] : kSpawns)
            if (at == s) p.spawn(where), pause();
        for (const auto& [at, where] : kCarves)
            if (at == s) p.carve(where, kShot, 4.0, 0.8), pause();
        p.step(kDt, {}, kSun);
        pause();
        hashes.push_back(hashOf(p.published()));
        EXPECT_EQ(p.published().version, static_cast<std::uint64_t>(s)) << "step " << s;
    }
    return hashes;
}
}  // namespace

TEST(SmokePipeline, PublishesTheSynchronousFrameOfTheStepBeforeBitForBit) {
    const std::vector<std::uint64_t> piped = playPipeline(0);
    SmokeManager sync(4, testlevels::small(24));
    SmokeFrame frame;
    std::uint64_t before = hashOf(frame);  // before the first step: nothing
    int volumes = 0;
    for (int s = 0; s < kSteps; ++s) {
        EXPECT_EQ(piped[s], before) << "step " << s;
        for (const auto& [at, where] : kSpawns)
            if (at == s) sync.spawn(level(), {}, where);
        for (const auto& [at, where] : kCarves)
            if (at == s) sync.carve(where, kShot, 4.0, 0.8);
        sync.step(kDt);
        sync.computeTransmittance(kSun);
        exportFrame(sync, kLevelLamps, kSignLamps, frame);
        before = hashOf(frame);
        volumes = std::max(volumes, static_cast<int>(frame.volumes.size()));
    }
    EXPECT_EQ(volumes, 2);  // both clouds were there and visible: the hashes covered them
    EXPECT_FALSE(frame.volumes.front().lamps.empty());
}

TEST(SmokePipeline, TheSameFramesWhateverTheThreadTiming) {
    const std::vector<std::uint64_t> steady = playPipeline(0);
    EXPECT_EQ(playPipeline(7), steady);
    EXPECT_EQ(playPipeline(1234), steady);
}

TEST(SmokePipeline, AFailedReleaseChangesNothing) {
    SmokePipeline p(4, testlevels::small(24), level(), {});
    p.spawn({0, 1.0, -1.0});  // inside the wall left of the door: no grid fits
    EXPECT_TRUE(p.mayHoldSmoke());  // not known until its step ran
    p.step(kDt, {}, kSun);
    p.step(kDt, {}, kSun);
    EXPECT_TRUE(p.published().volumes.empty());
    EXPECT_FALSE(p.mayHoldSmoke());
    EXPECT_TRUE(p.settled().volumes().empty());
    p.carve({-3, 1, 0}, kShot, 4.0, 0.8);  // nothing to carve: not even queued
    EXPECT_FALSE(p.mayHoldSmoke());
}

TEST(SmokeLamps, TheBrightestInReachFirstAndTheSignsTakeAtMostTwoChannels) {
    const std::vector<SmokeBox> boxes{{{0, 0, 0}, {2, 2, 2}}};
    const std::vector<SmokeLamp> levelLamps{
        {{5, 1, 1}, {1, 1, 1}, 2.0},     // 3 m from the box, reaches 2 m: out
        {{3, 1, 1}, {1, 1, 1}, 4.0},     // 1 m away: (1 - 1/4)^2 = 0.5625
        {{-1, 1, 1}, {2, 2, 2}, 4.0},    // 1 m away, twice as bright: first
        {{1, 1, 1}, {0.1, 0.1, 0.1}, 1.0},  // inside: 0.1, last
    };
    const std::vector<SmokeLamp> signs{{{1, 4, 1}, {1, 1, 1}, 5.0}, {{1, 1, 3.5}, {1, 1, 1}, 5.0}, {{1, 1, -3}, {1, 1, 1}, 5.0}};
    const LampChoice c = chooseLamps(boxes, levelLamps, signs);
    ASSERT_EQ(c.bound.size(), 3u);
    EXPECT_EQ(c.bound[0].position.x, -1);
    EXPECT_EQ(c.bound[1].position.x, 3);
    EXPECT_EQ(c.bound[2].position.x, 1);
    // Two sign channels (the nearest: 1.5 m and 2 m away; the one 3 m away is left out), two level.
    ASSERT_EQ(c.shadowed.size(), kShadowedLamps);
    EXPECT_EQ(c.shadowedLevelLamps, 2u);
    EXPECT_EQ(c.shadowed[2].z, 3.5);
    EXPECT_EQ(c.shadowed[3].y, 4);
    // No box, no lamp.
    EXPECT_TRUE(chooseLamps({}, levelLamps, signs).bound.empty());
}
