// See render_view.h.
#include "lightbake/baked_light_view.h"
#include "app/render_view.h"

#include "app/combat_view.h"
#include "app/truth_key.h"
#include "map/map_lights.h"
#include "raytrace/level_triangles.h"
#include "render/hud.h"
#include "render/level_geometry.h"
#include "render/level_lighting.h"
#include "render/level_materials.h"
#include "render/liquid_view.h"
#include "render/model_loader.h"
#include "render/ogre_convert.h"
#include "render/prop_view.h"
#include "session.h"
#include "decals/decal_render.h"
#include "core/pfm.h"
#include "frame/frame.h"
#include "frame/frame_shared.h"
#include "signs/sign_render.h"
#include "smoke/smoke_render.h"
#include "ssao/ssao_compositor.h"
#include "ssao/ssao_modes.h"

#include <Ogre.h>
#include <algorithm>
#include <OgreOverlaySystem.h>
#include <OgreRTShaderSystem.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

namespace obscura {

namespace {

static_assert(map::kAmbientAreaGrace == FRAME_AMBIENT_AREA_GRACE, "the C++ and GLSL ambient areas agree");

// The level's env_ambient areas as the frame takes them; past FRAME_MAX_AMBIENT_AREAS a line names
// the first one dropped.
std::vector<frame::AmbientBox> ambientBoxes(const map::Level& level, const std::string& path) {
    std::vector<frame::AmbientBox> out;
    for (const map::AmbientArea& a : level.ambientAreas) {
        if (out.size() == FRAME_MAX_AMBIENT_AREAS) {
            std::cerr << "obscura: " << path << ":" << a.pos.line << ": env_ambient: the level has "
                      << level.ambientAreas.size() << " of them; only the first " << FRAME_MAX_AMBIENT_AREAS
                      << " are drawn (this one and the rest are not)\n";
            break;
        }
        out.push_back({render::toOgre(a.box.min), render::toOgre(a.box.max), static_cast<float>(a.scale), static_cast<float>(a.blend)});
    }
    return out;
}
constexpr double kPi = 3.14159265358979323846;
double degToRad(double d) { return d * kPi / 180.0; }

// Settings give the horizontal FOV (what players tune); OGRE wants the vertical one.
Ogre::Radian verticalFov(double horizontalDegrees, double aspect) {
    return Ogre::Radian(static_cast<Ogre::Real>(2.0 * std::atan(std::tan(degToRad(horizontalDegrees) * 0.5) / aspect)));
}
}  // namespace

RenderView::AoSettings RenderView::aoSettings(const Settings& s) {
    return {s.ssao, s.ssaoRadius, s.ssaoLargeRadius, s.ssaoIntensity, s.ssaoSamples, s.ssaoResolution, s.aoOnly, s.exposure};
}

RenderView::RenderView(const Context& context, const Settings& settings, const Session& session)
    : root_(context.root), window_(context.window), overlays_(context.overlays), shaders_(context.shaders) {
    const map::Level& level = session.level();
    scene_ = root_.createSceneManager();
    scene_->addRenderQueueListener(&overlays_);
    shaders_.addSceneManager(scene_);
    scene_->setAmbientLight(Ogre::ColourValue(0.3f, 0.3f, 0.3f));

    camera_ = scene_->createCamera("PlayerCamera");
    // Near plane 5 cm: the capsule keeps the eye at least its radius (0.35 m) from walls.
    camera_->setNearClipDistance(0.05f);
    camera_->setFarClipDistance(2000.0f);
    cameraNode_ = scene_->getRootSceneNode()->createChildSceneNode();
    cameraNode_->attachObject(camera_);

    if (settings.headless) {
        offscreen_ = Ogre::TextureManager::getSingleton().createManual(
            "Obscura/Offscreen", Ogre::RGN_DEFAULT, Ogre::TEX_TYPE_2D, static_cast<Ogre::uint>(settings.width),
            static_cast<Ogre::uint>(settings.height), 0, Ogre::PF_BYTE_RGB, Ogre::TU_RENDERTARGET);
        target().setAutoUpdated(true);
    }
    viewport_ = target().addViewport(camera_);
    viewport_->setBackgroundColour(Ogre::ColourValue(0.05f, 0.05f, 0.06f));
    viewport_->setMaterialScheme(Ogre::RTShader::ShaderGenerator::DEFAULT_SCHEME_NAME);
    viewport_->setOverlaysEnabled(true);
    const double aspect = static_cast<double>(viewport_->getActualWidth()) / viewport_->getActualHeight();
    camera_->setAspectRatio(static_cast<Ogre::Real>(aspect));
    camera_->setFOVy(verticalFov(settings.fov, aspect));

    materials_ = std::make_unique<render::LevelMaterials>(Ogre::RGN_DEFAULT);
    auto start = std::chrono::steady_clock::now();
    render::applyLevelLighting(level);
    render::createSun(*scene_, level);
    levelGeometry_ = std::make_unique<render::LevelGeometry>(*scene_, level, *materials_, &session.light().atlas);
    // After the level's materials exist: every one with the bake's units gets its textures.
    bakedLight_ = std::make_unique<lightbake::BakedLightView>(session.light());
    liquids_ = map::LiquidQuery(level);
    // misc_model meshes, visible only: the session built their colliders from the same files.
    const auto modelDirs = Session::modelSearchDirs(settings);
    for (const auto& m : level.models)
        render::placeModel(*scene_, m, settings.level, modelDirs, Ogre::RGN_DEFAULT, *materials_);
    props_ = std::make_unique<render::PropView>(*scene_, *materials_);

    const auto& s = levelGeometry_->stats();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::ostringstream os;
    os << "level " << settings.level << ": " << level.brushes.size() << " brushes, " << s.triangles << " triangles in "
       << s.batches << " batches (" << s.chunks << " chunks, " << s.liquidBatches << " translucent liquid), " << s.lights << " lights, " << level.models.size()
       << " models, " << materials_->generatedCount() << " generated materials; scene built in " << ms << " ms";
    Ogre::LogManager::getSingleton().logMessage(os.str());
    std::cout << os.str() << "\n";

    frame::FrameSettings fs;
    fs.maxRenderTargets = settings.debugMaxRenderTargets;
    fs.unsupportedFormats = settings.debugUnsupportedFormats;
    frame_ = std::make_unique<frame::Frame>(*viewport_, *camera_, fs);
    frame_->setAmbientAreas(ambientBoxes(level, settings.level));
    for (const auto& m : materials_->liquidMaterials()) frame_->addSceneMaterial(m);  // they read gbufferDepth
    ao_ = std::make_unique<ssao::AmbientOcclusion>(settings.seed);
    smoke_ = std::make_unique<smoke::SmokeRender>();
    // Room for every decal the session can hold: the ring's cap and the fixed ones (signs).
    decals_ = std::make_unique<decals::DecalRender>(*scene_, session.decals().set().capacity(), session.decals().signTiles());
    frame_->add(*decals_);
    frame_->add(*ao_);
    frame_->add(*smoke_);
    // The back-lit signs: their plates in the scene, the lettered light on surfaces (lighting stage)
    // and the shafts, marched with the smoke in the one volumetric pass.
    signs_ = std::make_unique<signs::SignRender>(*scene_, session.signs().specs(), session.signs().masks(),
                                                 static_cast<float>(settings.signHaze),
                                                 render::kSkyVisibilityFlag | render::kLiquidVisibilityFlag);
    setSigns(settings.signMode, settings.signHaze);
    for (const auto& m : signs_->meshuggahMaterials()) frame_->addSceneMaterial(m);  // they read gbufferDepth
    frame_->add(signs_->surfaces());
    frame_->add(signs_->shafts());
    // The heightfield mode's height map, over the level's brushes (models stand inside them), with
    // the movers where the simulation starts them.
    if (!level.bounds.empty())
        heightBounds_ = Ogre::AxisAlignedBox(render::toOgre(level.bounds.min), render::toOgre(level.bounds.max));
    const sim::Movers& movers = session.sim().movers();
    for (std::size_t i = 0; i < movers.count(); ++i) {
        levelGeometry_->setMoverOffset(movers.entityIndex(i), movers.offset(i));
        bakedMoverOffsets_.push_back(movers.offset(i));
    }
    latestMoverOffsets_ = bakedMoverOffsets_;
    if (!heightBounds_.isNull()) ao_->buildHeightMap(*scene_, heightBounds_, render::kSkyVisibilityFlag | render::kLiquidVisibilityFlag);
    applyAo(aoSettings(settings));
    if (settings.view != "scene") {
        frame_->setView(settings.view);
        if (frame_->view() != settings.view) {
            std::string all;
            for (const auto& v : frame_->views()) all += (all.empty() ? "" : ", ") + v;
            throw std::runtime_error("setting view: unknown view '" + settings.view + "', expected one of " + all);
        }
    }

    // The truth key's tracer gets the level's triangles as tools/aoref loads them (the movers where
    // the level starts them), when something is first shown. The session outlives this view.
    fov_ = settings.fov;
    auto meshes = [&level, modelDirs] {
        auto triangles = levelTriangles(level);
        addModelTriangles(level, modelDirs, triangles);
        return triangles;
    };
    truth_ = std::make_unique<TruthKey>(*frame_, meshes, settings.truthThreads);
    setTruth(settings.truth, settings.truthRays);

    combat_ = std::make_unique<CombatView>(*scene_, *materials_, *cameraNode_, session.durations());
    hud_ = std::make_unique<render::Hud>();
    hud_->setPanelVisible(settings.showDebugPanel);
}

RenderView::~RenderView() {
    // Order matters (see shared/README): our OGRE objects first, then the scene manager.
    hud_.reset();
    frame_.reset();  // before the techniques plugged into it
    truth_.reset();
    smoke_.reset();
    signs_.reset();
    combat_.reset();
    ao_.reset();
    decals_.reset();
    props_.reset();
    bakedLight_.reset();
    levelGeometry_.reset();
    materials_.reset();
    shaders_.removeSceneManager(scene_);
    // The window outlives the view (a trigger_changelevel builds the next level's on it).
    target().removeViewport(viewport_->getZOrder());
    if (offscreen_) {
        Ogre::TextureManager::getSingleton().remove(offscreen_);
        offscreen_.reset();
    }
    scene_->removeRenderQueueListener(&overlays_);
    root_.destroySceneManager(scene_);
}

Ogre::RenderTarget& RenderView::target() {
    if (offscreen_) return *offscreen_->getBuffer()->getRenderTarget();
    return window_;
}

void RenderView::setSigns(const std::string& mode, double haze) {
    signs_->setMode(mode == "off"         ? signs::SignMode::Off
                    : mode == "meshuggah" ? signs::SignMode::Meshuggah
                                          : signs::SignMode::Shafts);
    signs_->setHaze(static_cast<float>(haze));
}

void RenderView::applyAo(const AoSettings& a) {
    ssao::AoKnobs k;
    k.radius = a.radius;
    k.largeRadius = a.largeRadius;
    k.intensity = a.intensity;
    k.samples = a.samples;
    k.resolution = a.resolution;
    ao_->setKnobs(k);
    ao_->setMode(a.mode);  // the frame rebuilds its chain at the next frame
    aoRadius_ = ssao::truthRadius(a.mode, a.radius, a.largeRadius);  // the truth traces what the mode estimates
    if (truth_) truth_->aoChanged();
    aoMode_ = a.mode;
    rebakeHeightMapIfStale();
    if (a.aoOnly) frame_->setView("ao");
    else if (frame_->view() == "ao") frame_->setView("scene");
    frame_->setExposure(static_cast<float>(a.exposure));
}

std::string RenderView::cycleView() {
    const auto views = frame_->views();
    auto at = std::find(views.begin(), views.end(), frame_->view());
    frame_->setView(at == views.end() || at + 1 == views.end() ? views.front() : *(at + 1));
    return frame_->view();
}

std::string RenderView::aoStatus() const {
    return frame_->offReason(*ao_).empty() ? ao_->mode() : ao_->mode() + " (off here)";
}

void RenderView::setTruth(const std::string& show, int rays) {
    truth_->set(ao_truth::showFromName(show).value_or(ao_truth::Show::Off), rays);  // validated by the settings
}

bool RenderView::truthShown() const { return truth_->show() != ao_truth::Show::Off; }

void RenderView::waitTruth() const { truth_->waitDone(); }

void RenderView::setFov(double horizontalDegrees) {
    fov_ = horizontalDegrees;
    camera_->setFOVy(verticalFov(horizontalDegrees, camera_->getAspectRatio()));
}

void RenderView::resized(int width, int height, double horizontalFov) {
    camera_->setAspectRatio(static_cast<Ogre::Real>(width) / static_cast<Ogre::Real>(height));
    setFov(horizontalFov);  // the vertical FOV follows the aspect
}

double RenderView::smokeUploadMs() const { return smoke_->lastUpdateMs(); }

void RenderView::onTick(const std::vector<sim::SimEvent>& events) {
    combat_->onTick(events);
}

void RenderView::update(const Session& session, double alpha) {
    const auto& a = session.previousPlayer();
    const auto& b = session.sim().player();
    const Vec3 ea = a.eye(), eb = b.eye();
    eye_ = ea + (eb - ea) * alpha;
    // Interpolate angles along the short way round.
    double dyaw = b.yaw - a.yaw;
    dyaw = std::remainder(dyaw, 2.0 * kPi);
    const double yaw = a.yaw + dyaw * alpha;
    const double pitch = a.pitch + (b.pitch - a.pitch) * alpha;
    yaw_ = yaw;
    pitch_ = pitch;
    cameraNode_->setPosition(static_cast<float>(eye_.x), static_cast<float>(eye_.y), static_cast<float>(eye_.z));
    cameraNode_->setOrientation(Ogre::Quaternion(Ogre::Radian(static_cast<float>(yaw)), Ogre::Vector3::UNIT_Y) *
                                Ogre::Quaternion(Ogre::Radian(static_cast<float>(pitch)), Ogre::Vector3::UNIT_X));
    using Shape = render::PropPose::Shape;
    std::vector<render::PropPose> poses;
    for (const auto& body : session.sim().bodyPoses()) {
        const bool barrel = body.shape == sim::Simulation::BodyPose::Shape::Cylinder;
        poses.push_back({body.position, body.qx, body.qy, body.qz, body.qw, body.halfExtents,
                         barrel ? Shape::Cylinder : Shape::Box, barrel ? "barrel" : "crate"});
    }
    for (const auto& g : session.sim().grenades())
        poses.push_back({g.position, g.qx, g.qy, g.qz, g.qw, Vec3{g.radius, g.radius, g.radius}, Shape::Sphere, "metal"});
    props_->update(poses);
    const sim::Movers& movers = session.sim().movers();
    bool resting = true;
    for (std::size_t i = 0; i < movers.count(); ++i) {
        const Vec3 a = session.previousMoverOffsets().at(i), b = movers.offset(i);
        levelGeometry_->setMoverOffset(movers.entityIndex(i), a + (b - a) * alpha);
        resting &= a == b;
        latestMoverOffsets_.at(i) = b;
        heightMapStale_ |= b != bakedMoverOffsets_.at(i);
    }
    // The baked AO height map follows the movers once they have all come to rest (a door open).
    if (resting) rebakeHeightMapIfStale();
    combat_->update(session.sim().targets());
}

void RenderView::rebakeHeightMapIfStale() {
    // Only the height-map modes read the map; another mode bakes when it switches to one.
    if (!heightMapStale_ || !ssao::readsHeightMap(aoMode_) || heightBounds_.isNull()) return;
    ao_->buildHeightMap(*scene_, heightBounds_, render::kSkyVisibilityFlag | render::kLiquidVisibilityFlag);
    bakedMoverOffsets_ = latestMoverOffsets_;
    heightMapStale_ = false;
}

RenderView::Listener RenderView::listener() const {
    const Ogre::Quaternion q = cameraNode_->getOrientation();
    return {eye_, render::fromOgre(q * Ogre::Vector3::NEGATIVE_UNIT_Z), render::fromOgre(q * Ogre::Vector3::UNIT_Y)};
}

void RenderView::draw(const Session& session, const Frame& frame) {
    render::HudState hs;
    hs.visible = frame.hudVisible;
    hs.crosshair = frame.crosshair;
    hs.frameMs = frame.frameMs;
    hs.frameMsIsFixed = frame.frameMsIsFixed;
    hs.status.push_back("AO: " + aoStatus() + (frame_->view() == "ao" ? " (AO only)" : ""));
    if (!frame.notice.empty()) hs.status.push_back(frame.notice);
    if (frame_->view() != "scene" && frame_->view() != "ao") hs.status.push_back("view: " + frame_->view() + " (V)");
    truth_->beforeRender(CameraPose{eye_, yaw_, pitch_, fov_}, static_cast<int>(viewport_->getActualWidth()),
                         static_cast<int>(viewport_->getActualHeight()), aoRadius_);
    for (const auto& line : truth_->hudLines(aoStatus())) hs.status.push_back(line);
    // Health shows only once slime or lava took some (the usual HUD stays as it was).
    const auto& player = session.sim().player();
    if (player.health < 100 || session.sim().deaths() > 0)
        hs.status.push_back("health " + std::to_string(player.health) +
                            (session.sim().deaths() > 0 ? ", died " + std::to_string(session.sim().deaths()) + "x" : std::string()));
    const auto& w = session.sim().weapon();
    hs.magazine = w.magazine;
    hs.magazineSize = w.magazineSize;
    hs.reserve = w.reserve;
    hs.reloadProgress = w.reloading ? w.reloadProgress : -1.0;
    hs.score = session.sim().score();
    hs.hitMarker = session.hitMarker();
    hs.centreMessage = session.centreMessage();
    hs.throwCharge = session.sim().throwCharge() > 0 ? session.sim().throwCharge() : -1.0;
    hud_->update(hs);

    // The smoke: new fields to the GPU when it stepped; then the frame's chain for this frame's
    // techniques (AO mode, smoke or none), outside the render.
    const GameSmoke& smoke = session.smoke();
    smoke_->update(smoke.frame(), static_cast<float>(smoke.seconds()), static_cast<float>(smoke.settings().shadowSigma));
    decals_->update(session.decals().list(), session.decals().version());
    signs_->update(session.signs().holes(), session.signs().version(), *camera_);
    smoke_->cull(*camera_, !signs_->shafts().compositor().empty());
    frame_->update(static_cast<float>(smoke.seconds()));
    // The liquids' warp runs on simulation time (replays draw the same frames); the camera's
    // liquid, if any, tints and fogs the view.
    render::setLiquidView(static_cast<double>(session.sim().tick()) * session.sim().dt(), liquids_.at(eye_));
    root_.renderOneFrame();
    truth_->afterRender([this](int& w, int& h) {
        // The mode's AO (red) as its last pass wrote it; the 1x1 stand-in (1, 0) while AO is off.
        const Ogre::TexturePtr tex = frame_->published("aoMap");
        w = static_cast<int>(tex->getWidth());
        h = static_cast<int>(tex->getHeight());
        const std::vector<float> rgba = readRgba(tex);
        std::vector<float> ao(rgba.size() / 4);
        for (std::size_t i = 0; i < ao.size(); ++i) ao[i] = rgba[i * 4];
        return ao;
    });
}

void RenderView::skipDraw(const Frame& frame) {
    if (frame.hudVisible) hud_->recordFrame(frame.frameMs);
}

std::vector<float> RenderView::readRgba(const Ogre::TexturePtr& tex) const {
    const auto w = tex->getWidth(), h = tex->getHeight();
    std::vector<float> stored(static_cast<std::size_t>(w) * h * 4), out(stored.size());
    tex->getBuffer()->blitToMemory(Ogre::PixelBox(w, h, 1, Ogre::PF_FLOAT32_RGBA, stored.data()));
    // blitToMemory gives a render texture stored upside down (GL's, flipY) with the picture's top
    // row first; one stored the right way up, bottom row first.
    const std::size_t row = static_cast<std::size_t>(w) * 4;
    for (std::size_t y = 0; y < h; ++y) {
        const std::size_t from = frame_->flipY() ? y : h - 1 - y;
        std::copy(stored.begin() + static_cast<std::ptrdiff_t>(from * row), stored.begin() + static_cast<std::ptrdiff_t>((from + 1) * row),
                  out.begin() + static_cast<std::ptrdiff_t>(y * row));
    }
    return out;
}

void RenderView::finishFrame() {
    // GL queues work; llvmpipe runs it when something waits. Reading one pixel back makes each
    // timed frame include its own rendering instead of a later frame's.
    Ogre::uint8 pixel[4];
    Ogre::PixelBox box(1, 1, 1, Ogre::PF_BYTE_RGBA, pixel);
    target().copyContentsToMemory(Ogre::Box(0, 0, 1, 1), box);
}

void RenderView::writeBufferDump(const std::string& unit, const std::string& path) {
    bool standIn = false;
    const Ogre::TexturePtr tex = frame_->published(unit, &standIn);
    if (!tex) throw std::runtime_error(path + ": the frame has no buffer " + unit);
    FloatImage out;
    if (standIn) {  // nothing marched: no in-scattered light, at the size the pass would have had
        out.width = std::max(1, static_cast<int>(viewport_->getActualWidth() * FRAME_VOLUME_SCALE));
        out.height = std::max(1, static_cast<int>(viewport_->getActualHeight() * FRAME_VOLUME_SCALE));
        out.rgb.assign(static_cast<std::size_t>(out.width) * out.height * 3, 0.f);
    } else {
        out.width = static_cast<int>(tex->getWidth());
        out.height = static_cast<int>(tex->getHeight());
        const std::vector<float> rgba = readRgba(tex);
        out.rgb.resize(static_cast<std::size_t>(out.width) * out.height * 3);
        for (std::size_t i = 0; i < rgba.size() / 4; ++i)
            for (int c = 0; c < 3; ++c) out.rgb[i * 3 + c] = rgba[i * 4 + c];
    }
    writePfm(out, path);
}

void RenderView::writeIrradianceDump(const std::string& path) {
    const Ogre::TexturePtr direct = frame_->published("gbufferLight"), ambient = frame_->published("gbufferAmbient");
    if (!direct || !ambient) throw std::runtime_error(path + ": the frame has no G-buffer light");
    FloatImage out;
    out.width = static_cast<int>(direct->getWidth());
    out.height = static_cast<int>(direct->getHeight());
    const std::vector<float> d = readRgba(direct), a = readRgba(ambient);
    out.rgb.resize(static_cast<std::size_t>(out.width) * out.height * 3);
    for (std::size_t i = 0; i < d.size() / 4; ++i)
        for (int c = 0; c < 3; ++c) out.rgb[i * 3 + c] = d[i * 4 + c] + a[i * 4 + c];
    writePfm(out, path);
}

int RenderView::settleVolumes() { return frame_->settleVolumes(); }

void RenderView::writeScreenshot(const std::string& path) {
    Ogre::RenderTarget& t = target();
    Ogre::Image image(Ogre::PF_BYTE_RGB, t.getWidth(), t.getHeight());
    t.copyContentsToMemory(image.getPixelBox(), image.getPixelBox());
    image.save(path);
}

std::string RenderView::saveScreenshot(const std::string& path) noexcept {
    try {
        // OGRE's own message for a failed save names neither the file nor the reason.
        if (!std::ofstream(path, std::ios::binary | std::ios::app))
            return "cannot write '" + path + "': " + std::strerror(errno);
        writeScreenshot(path);
        return {};
    } catch (const std::exception& e) {
        std::remove(path.c_str());  // no empty or half-written file left behind
        return "cannot write '" + path + "': " + e.what();
    }
}

const render::LevelGeometryStats& RenderView::levelStats() const { return levelGeometry_->stats(); }

}  // namespace obscura
