// See session.h.
#include "cache_dir.h"
#include "session.h"

#include "map/asset_path.h"
#include "map/entity_values.h"
#include "map/map_compile.h"
#include "mesh/ogre_mesh_reader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace obscura {

namespace {
double degToRad(double d) { return d * 3.14159265358979323846 / 180.0; }

sim::SimConfig simConfig(const Settings& settings) {
    sim::SimConfig config;
    config.tickRate = settings.tickRate;
    config.seed = settings.seed;
    if (!settings.startPose.empty()) {
        std::istringstream is(settings.startPose);
        double x, y, z, yaw, pitch;
        is >> x >> y >> z >> yaw >> pitch;
        config.overrideStart = true;
        const sim::PlayerTuning standing;
        config.startFeet = {x, y - (standing.standHeight - standing.eyeBelowTop), z};
        config.startYaw = degToRad(yaw);
        config.startPitch = degToRad(pitch);
    }
    return config;
}

// misc_model meshes as static colliders and smoke obstacles, read without the renderer.
std::vector<TriangleMesh> modelColliders(const map::Level& level, const Settings& settings) {
    std::vector<TriangleMesh> meshes;
    const map::LevelFiles files(settings.level, Session::modelSearchDirs(settings));
    for (const auto& m : level.models) {
        const std::string file = files.require(m.mesh, settings.level + ":" + std::to_string(m.pos.line) + ": misc_model", "'model'");
        meshes.push_back(mesh::meshTriangles(mesh::readOgreMesh(file), {m.origin, m.yaw, m.scale}));
    }
    return meshes;
}
}  // namespace

Vec3 parseVec3(const std::string& text) {
    std::istringstream is(text);
    Vec3 p;
    is >> p.x >> p.y >> p.z;
    return p;
}

map::Level Session::loadLevel(const Settings& settings, std::vector<std::string>* warnings, map::LoadTimes* times) {
    map::CompileOptions options;
    options.unitsPerMetre = settings.mapScale;
    options.skill = settings.skill;
    const auto t0 = std::chrono::steady_clock::now();
    map::MapFile file = map::loadMapFile(settings.level);
    // Obscura's own entities for the level, `<name>.ent` beside it or in media/levels/ (a real
    // Quake map, which nobody here may edit, gets its signs there: media/levels/e3m4.ent).
    // Confined like every file a level names: an overlay that links out of the roots is refused.
    const std::filesystem::path levelPath(settings.level);
    const map::LevelFiles files(settings.level, modelSearchDirs(settings));
    const std::vector<std::string> overlayDirs = {levelPath.parent_path().string(),
                                                  (std::filesystem::path(settings.dataDir) / "media/levels").string()};
    const std::string overlayName = levelPath.stem().string() + ".ent";
    const map::AssetPath overlay = map::resolveAsset(overlayName, overlayDirs, files.roots());
    if (!overlay.error.empty()) throw std::runtime_error(settings.level + ": entity overlay '" + overlayName + "' " + overlay.error);
    if (!overlay.file.empty()) map::addEntityOverlay(file, overlay.file);
    const auto t1 = std::chrono::steady_clock::now();
    map::Level level = map::compileLevel(file, options, warnings);
    if (times) {
        times->parseMs = std::chrono::duration<double, std::milli>(t1 - t0).count();
        times->compileMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count();
    }
    return level;
}

std::vector<std::string> Session::modelSearchDirs(const Settings& settings) {
    return map::levelSearchDirs(settings.level, settings.dataDir);
}

namespace {
// The level's static light from the cache, or baked now (a line on stdout either way, and the
// bake's progress on long levels).
lightbake::BakeOutcome bakeLight(const map::Level& level) {
    const auto log = [](const std::string& line) { std::cout << line << std::endl; };
    lightbake::BakeOutcome out = lightbake::bakeOrLoad(level, lightbake::bakeSkyOf(level), {}, cacheDir(), log);
    const lightbake::BakeStats& s = out.bake.stats;
    std::cout << "light bake: " << (out.fromCache ? "read from the cache" : "baked") << " in " << out.seconds << " s ("
              << s.charts << " faces, " << out.bake.atlas.width << " x " << out.bake.atlas.height << " lightmap texels, "
              << s.probes << " probes" << (out.fromCache ? "" : ", " + std::to_string(s.rays / 1000000) + " M rays") << ")" << std::endl;
    return out;
}
}  // namespace

Session::Session(const Settings& settings, map::Level level, const Vec3& towardSun)
    : level_(std::move(level)),
      durations_(settings.tickRate),
      colliders_(modelColliders(level_, settings)),
      sim_(level_, simConfig(settings), colliders_),
      smoke_(level_, colliders_, towardSun, settings.tickRate, settings.smokeResolution),
      decals_(settings, level_, modelSearchDirs(settings), sim_),
      signs_(level_, {OBSCURA_SIGN_FONT_DIR, std::filesystem::path(settings.level).parent_path().string()}),
      light_(bakeLight(level_)),
      previousPlayer_(sim_.player()) {
    for (std::size_t i = 0; i < sim_.movers().count(); ++i) previousMoverOffsets_.push_back(sim_.movers().offset(i));
    std::vector<smoke::SmokeLamp> signLamps;  // shadowed by the smoke in the signs' shafts
    for (const signs::SignSpec& s : signs_.specs()) signLamps.push_back({s.lamp, s.lightColour * s.intensity, s.range});
    smoke_.setSignLamps(std::move(signLamps));
    if (!settings.smokeAt.empty()) smoke_.spawn(parseVec3(settings.smokeAt));
    worldtype_ = sim::worldtypeOf(level_);
}

void Session::showMessage(const std::string& value) {
    if (value.empty()) return;
    centreMessage_ = map::messageText(value);
    centreTicks_ = durations_.centrePrintTicks;
}

void Session::step(const sim::PlayerCommand& cmd) {
    previousPlayer_ = sim_.player();
    for (std::size_t i = 0; i < previousMoverOffsets_.size(); ++i) previousMoverOffsets_[i] = sim_.movers().offset(i);
    sim_.step(cmd);
    const auto& events = sim_.events();
    // A teleport is a cut: the view does not glide from the old place to the new one.
    for (const auto& e : events)
        if (e.type == sim::SimEventType::Teleport) previousPlayer_ = sim_.player();
    smoke_.onTick(events, sim_);
    decals_.onTick(events, sim_);
    signs_.onTick(events);
    hitMarker_ = std::max(0.0, hitMarker_ - durations_.hitMarkerFadePerTick);
    if (centreTicks_ > 0) --centreTicks_;
    for (const auto& e : events) {
        if (e.type == sim::SimEventType::TargetHit) hitMarker_ = 1.0;
        if (e.type == sim::SimEventType::Message && e.notice != sim::Notice::None)
            showMessage(sim::noticeText(e.notice, worldtype_));
        else if (e.type == sim::SimEventType::Message)
            showMessage(level_.entities.at(static_cast<std::size_t>(e.id)).value("message"));
        if (e.type == sim::SimEventType::ChangeLevel) changeLevel_ = e.id;
    }
}

}  // namespace obscura
