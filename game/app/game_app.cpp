// See game_app.h.
#include "app/game_app.h"

#include "app/combat_view.h"
#include "app/game_audio.h"
#include "app/game_smoke.h"
#include "app/pause_menu.h"
#include "app/sdl_keys.h"
#include "core/fixed_step.h"
#include "timedemo_stats.h"
#include "map/map_compile.h"
#include "render/hud.h"
#include "render/level_geometry.h"
#include "render/ogre_convert.h"
#include "render/level_lighting.h"
#include "render/level_materials.h"
#include "render/model_loader.h"
#include "render/prop_view.h"
#include "replay/replay_recorder.h"
#include "replay/replay_script.h"
#include "sim/simulation.h"
#include "frame/frame.h"
#include "ssao/ssao_compositor.h"
#include "ssao/ssao_knobs.h"
#include "ssao/ssao_modes.h"

#include <Ogre.h>
#include <OgreImGuiInputListener.h>
#include <OgreOverlaySystem.h>
#include <OgreRTShaderSystem.h>
#include <SDL2/SDL.h>
#include <imgui.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#ifndef OBSCURA_DATA_DIR
#define OBSCURA_DATA_DIR "."
#endif
#ifndef OBSCURA_GENERATED_DIR
#define OBSCURA_GENERATED_DIR "."
#endif
#ifndef OBSCURA_OGRE_PLUGIN_DIR
#define OBSCURA_OGRE_PLUGIN_DIR "/usr/lib/x86_64-linux-gnu/OGRE"
#endif

namespace obscura {

namespace {
// Headless runs with no --ticks: 5 s of game time, enough to settle physics and show the level.
constexpr long kDefaultHeadlessTicks = 300;
// The hidden window only carries the GL context; frames go to an offscreen texture.
constexpr unsigned kHiddenWindowSize = 64;

double degToRad(double d) { return d * 3.14159265358979323846 / 180.0; }

// "x y z" (validated by the settings table already).
Vec3 parseVec3(const std::string& text) {
    std::istringstream is(text);
    Vec3 p;
    is >> p.x >> p.y >> p.z;
    return p;
}
}  // namespace

GameApp::GameApp(Settings settings, const SettingsParser& parser)
    : OgreBites::ApplicationContext("Obscura"), settings_(std::move(settings)), parser_(parser), input_(settings_) {
    if (settings_.dataDir.empty()) settings_.dataDir = OBSCURA_DATA_DIR;
    if (settings_.level.empty()) settings_.level = dataPath("media/levels/arena.map");
    if (settings_.headless && settings_.ticks == 0) settings_.ticks = kDefaultHeadlessTicks;
}

GameApp::~GameApp() = default;

std::string GameApp::dataPath(const std::string& relative) const {
    return (std::filesystem::path(settings_.dataDir) / relative).string();
}

void GameApp::createRoot() {
    // Our own log (Bites would print hundreds of coloured lines to stdout otherwise).
    std::string logFile = settings_.logFile;
    if (logFile.empty()) {
        // $XDG_CACHE_HOME/obscura/obscura.log (tests point XDG_CACHE_HOME into the build tree).
        const char* xdg = std::getenv("XDG_CACHE_HOME");
        const char* home = std::getenv("HOME");
        const std::filesystem::path dir = std::filesystem::path(xdg && *xdg ? xdg : std::string(home ? home : "/tmp") + "/.cache") / "obscura";
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        logFile = (dir / "obscura.log").string();
    }
    auto* logs = new Ogre::LogManager();
    logs->createLog(logFile, true, false, false);
    mRoot = OGRE_NEW Ogre::Root("", "", "");
    mRoot->loadPlugin(OBSCURA_OGRE_PLUGIN_DIR "/RenderSystem_GL3Plus");
    mRoot->loadPlugin(OBSCURA_OGRE_PLUGIN_DIR "/Codec_STBI");  // PNG load/save
    mOverlaySystem = OGRE_NEW Ogre::OverlaySystem();
}

bool GameApp::oneTimeConfig() {
    Ogre::RenderSystem* rs = mRoot->getRenderSystemByName("OpenGL 3+ Rendering Subsystem");
    if (!rs) throw std::runtime_error("OGRE's RenderSystem_GL3Plus is not available (libogre-1.12 install?)");
    rs->setConfigOption("Full Screen", settings_.fullscreen && !settings_.headless ? "Yes" : "No");
    rs->setConfigOption("VSync", settings_.vsync && !settings_.headless ? "Yes" : "No");
    mRoot->setRenderSystem(rs);
    return true;
}

void GameApp::setup() {
    mRoot->initialise(false);
    if (settings_.headless) {
        Ogre::NameValuePairList misc{{"hidden", "true"}};
        auto win = createWindow("Obscura (headless)", kHiddenWindowSize, kHiddenWindowSize, misc);
        SDL_HideWindow(win.native);
    } else {
        createWindow("Obscura", static_cast<Ogre::uint32>(settings_.width), static_cast<Ogre::uint32>(settings_.height));
    }
    locateResources();
    if (!initialiseRTShaderSystem()) throw std::runtime_error("cannot initialise OGRE's RTSS");
    loadResources();
    mRoot->addFrameListener(this);
    addInputListener(this);
}

void GameApp::locateResources() {
    auto& rgm = Ogre::ResourceGroupManager::getSingleton();
    // RTSS shader library (Debian ships it; the rest of Debian's resources.cfg points at missing files).
    const std::string rtss = "/usr/share/OGRE/Media/RTShaderLib";
    rgm.addResourceLocation(rtss + "/GLSL", "FileSystem", Ogre::RGN_INTERNAL);
    rgm.addResourceLocation(rtss + "/materials", "FileSystem", Ogre::RGN_INTERNAL);
    // Debian installs OgreUnifiedShader.h (needed by RTSS shaders) beside the shadow-volume programs.
    rgm.addResourceLocation("/usr/share/OGRE/Media/ShadowVolume", "FileSystem", Ogre::RGN_INTERNAL);
    // Our own resources (media/resources.cfg lists them relative to the data folder).
    Ogre::ConfigFile cf;
    cf.load(dataPath("media/resources.cfg"));
    for (const auto& [section, settings] : cf.getSettingsBySection()) {
        for (const auto& [type, location] : settings) {
            std::string path = location;
            if (path.rfind("@generated/", 0) == 0)
                path = std::string(OBSCURA_GENERATED_DIR) + "/" + path.substr(11);
            else if (path.front() != '/')
                path = dataPath(path);
            rgm.addResourceLocation(path, type, section);
        }
    }
}

void GameApp::shutdown() {
    // Order matters (see shared/README): our OGRE objects first, then RTSS, overlays, root.
    imguiInput_.reset();
    frame_.reset();  // before the techniques plugged into it
    hud_.reset();
    menu_.reset();
    smoke_.reset();
    combat_.reset();
    audio_.reset();
    ao_.reset();
    props_.reset();
    levelGeometry_.reset();
    materials_.reset();
    if (scene_ && mShaderGenerator) mShaderGenerator->removeSceneManager(scene_);
    if (offscreen_) {
        Ogre::TextureManager::getSingleton().remove(offscreen_);
        offscreen_.reset();
    }
    if (scene_) {
        scene_->removeRenderQueueListener(mOverlaySystem);
        mRoot->destroySceneManager(scene_);
        scene_ = nullptr;
    }
    OgreBites::ApplicationContext::shutdown();
}

void GameApp::loadLevel() {
    map::CompileOptions options;
    options.unitsPerMetre = settings_.mapScale;
    std::vector<std::string> warnings;
    level_ = std::make_unique<map::Level>(map::loadLevel(settings_.level, options, &warnings));
    for (const auto& w : warnings) Ogre::LogManager::getSingleton().logWarning(w);
    if (!warnings.empty())
        std::cerr << "obscura: " << warnings.size() << " warnings loading " << settings_.level
                  << " (see the log)\n";
    if (!level_->unknownClassnames.empty()) {
        std::string list;
        for (const auto& c : level_->unknownClassnames) list += (list.empty() ? "" : ", ") + c;
        Ogre::LogManager::getSingleton().logMessage("level: unknown entity classes (ignored): " + list);
    }
}

void GameApp::createScene() {
    scene_ = mRoot->createSceneManager();
    scene_->addRenderQueueListener(mOverlaySystem);
    mShaderGenerator->addSceneManager(scene_);
    scene_->setAmbientLight(Ogre::ColourValue(0.3f, 0.3f, 0.3f));

    camera_ = scene_->createCamera("PlayerCamera");
    // Near plane 5 cm: the capsule keeps the eye at least its radius (0.35 m) from walls.
    camera_->setNearClipDistance(0.05f);
    camera_->setFarClipDistance(2000.0f);
    cameraNode_ = scene_->getRootSceneNode()->createChildSceneNode();
    cameraNode_->attachObject(camera_);

    Ogre::RenderTarget* target = getRenderWindow();
    if (settings_.headless) {
        offscreen_ = Ogre::TextureManager::getSingleton().createManual(
            "Obscura/Offscreen", Ogre::RGN_DEFAULT, Ogre::TEX_TYPE_2D, static_cast<Ogre::uint>(settings_.width),
            static_cast<Ogre::uint>(settings_.height), 0, Ogre::PF_BYTE_RGB, Ogre::TU_RENDERTARGET);
        target = offscreen_->getBuffer()->getRenderTarget();
        target->setAutoUpdated(true);
    }
    viewport_ = target->addViewport(camera_);
    viewport_->setBackgroundColour(Ogre::ColourValue(0.05f, 0.05f, 0.06f));
    viewport_->setMaterialScheme(Ogre::RTShader::ShaderGenerator::DEFAULT_SCHEME_NAME);
    viewport_->setOverlaysEnabled(true);
    const double aspect = static_cast<double>(viewport_->getActualWidth()) / viewport_->getActualHeight();
    camera_->setAspectRatio(static_cast<Ogre::Real>(aspect));
    // Settings give the horizontal FOV (what players tune); OGRE wants the vertical one.
    const double fovY = 2.0 * std::atan(std::tan(degToRad(settings_.fov) * 0.5) / aspect);
    camera_->setFOVy(Ogre::Radian(static_cast<Ogre::Real>(fovY)));

    materials_ = std::make_unique<render::LevelMaterials>(Ogre::RGN_DEFAULT);
    auto start = std::chrono::steady_clock::now();
    render::applyLevelLighting(*level_);
    render::createSun(*scene_, *level_);
    levelGeometry_ = std::make_unique<render::LevelGeometry>(*scene_, *level_, *materials_);

    // misc_model meshes: rendered, and their triangles become static colliders.
    std::vector<TriangleMesh> modelMeshes;
    const std::vector<std::string> modelDirs = {std::filesystem::path(settings_.level).parent_path().string(),
                                                settings_.dataDir, std::filesystem::current_path().string()};
    for (const auto& m : level_->models)
        modelMeshes.push_back(render::placeModel(*scene_, m, settings_.level, modelDirs, Ogre::RGN_DEFAULT, *materials_));

    sim::SimConfig config;
    config.tickRate = settings_.tickRate;
    config.seed = settings_.seed;
    if (!settings_.startPose.empty()) {
        std::istringstream is(settings_.startPose);
        double x, y, z, yaw, pitch;
        is >> x >> y >> z >> yaw >> pitch;
        config.overrideStart = true;
        const sim::PlayerTuning standing;
        config.startFeet = {x, y - (standing.standHeight - standing.eyeBelowTop), z};
        config.startYaw = degToRad(yaw);
        config.startPitch = degToRad(pitch);
    }
    sim_ = std::make_unique<sim::Simulation>(*level_, config, modelMeshes);
    smoke_ = std::make_unique<GameSmoke>(*level_, modelMeshes, render::computeLevelLighting(*level_).sunDirection,
                                         1.0 / settings_.tickRate);
    if (!settings_.smokeAt.empty()) smoke_->spawn(parseVec3(settings_.smokeAt));
    previousPlayer_ = std::make_unique<sim::PlayerState>(sim_->player());
    props_ = std::make_unique<render::PropView>(*scene_, *materials_);

    const auto& s = levelGeometry_->stats();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::ostringstream os;
    os << "level " << settings_.level << ": " << level_->brushes.size() << " brushes, " << s.triangles
       << " triangles in " << s.batches << " batches (" << s.chunks << " chunks), " << s.lights << " lights, "
       << level_->models.size() << " models, " << materials_->generatedCount() << " generated materials; scene built in " << ms << " ms";
    Ogre::LogManager::getSingleton().logMessage(os.str());
    std::cout << os.str() << "\n";

    frame::FrameSettings fs;
    fs.maxRenderTargets = settings_.debugMaxRenderTargets;
    fs.unsupportedFormats = settings_.debugUnsupportedFormats;
    fs.exposure = static_cast<float>(settings_.exposure);
    frame_ = std::make_unique<frame::Frame>(*viewport_, *camera_, fs);
    ao_ = std::make_unique<ssao::AmbientOcclusion>(settings_.seed);
    frame_->add(*ao_);
    frame_->add(smoke_->technique());
    // The heightfield mode's height map, over the level's brushes (models stand inside them).
    if (!level_->bounds.empty())
        ao_->buildHeightMap(*scene_, Ogre::AxisAlignedBox(render::toOgre(level_->bounds.min), render::toOgre(level_->bounds.max)),
                            render::kSkyVisibilityFlag);
    applyAoSettings();

    combat_ = std::make_unique<CombatView>(*scene_, *materials_, *cameraNode_);
    // Sounds load once, here (a malformed WAV stops the game at load time, naming the file); with
    // no audio device the game runs silent after one warning line.
    audio_ = std::make_unique<GameAudio>(settings_, dataPath("media/sounds"));

    hud_ = std::make_unique<render::Hud>();
    hud_->setPanelVisible(settings_.showDebugPanel);
    PauseMenu::Hooks hooks;
    hooks.set = [this](const std::string& key, const std::string& value) { applySetting(key, value, "menu"); };
    hooks.resize = [this](int w, int h) { resizeWindow(w, h); };
    hooks.resume = [this] { setMenuOpen(false); };
    hooks.quit = [this] { quit_ = true; };
    hooks.click = [this] { audio_->uiClick(); };
    menu_ = std::make_unique<PauseMenu>(settings_, hooks);
    imguiInput_ = std::make_unique<OgreBites::ImGuiInputListener>();  // after the HUD made ImGui's context
    hud_->setMenu([this] { menu_->draw(); });
    hud_->addPanelSection("Player", [this] {
        const auto& p = sim_->player();
        ImGui::Text("tick %llu", static_cast<unsigned long long>(sim_->tick()));
        ImGui::Text("feet %.2f %.2f %.2f", p.feet.x, p.feet.y, p.feet.z);
        ImGui::Text("speed %.2f m/s %s", std::hypot(p.velocity.x, p.velocity.z), p.onGround ? "on ground" : "in air");
    });
    hud_->addPanelSection("Ambient occlusion", [this] {
        ImGui::Text("mode: %s (O / Shift+O)", aoStatus().c_str());
        float radius = static_cast<float>(settings_.ssaoRadius), intensity = static_cast<float>(settings_.ssaoIntensity);
        bool changed = ImGui::SliderFloat("radius (m)", &radius, static_cast<float>(ssao::kRadius.min),
                                          static_cast<float>(ssao::kRadius.max));
        changed |= ImGui::SliderFloat("intensity", &intensity, static_cast<float>(ssao::kIntensity.min),
                                       static_cast<float>(ssao::kIntensity.max));
        changed |= ImGui::SliderInt("samples", &settings_.ssaoSamples, static_cast<int>(ssao::kSamples.min),
                                    static_cast<int>(ssao::kSamples.max));
        changed |= ImGui::Checkbox("AO only", &settings_.aoOnly);
        if (changed) {
            settings_.ssaoRadius = radius;
            settings_.ssaoIntensity = intensity;
            applyAoSettings();
        }
    });
    hud_->addPanelSection("Level", [this] {
        const auto& st = levelGeometry_->stats();
        ImGui::Text("%zu batches, %zu triangles, %zu lights", st.batches, st.triangles, st.lights);
    });
}

void GameApp::applyAoSettings() {
    ssao::AoKnobs k;
    k.radius = settings_.ssaoRadius;
    k.intensity = settings_.ssaoIntensity;
    k.samples = settings_.ssaoSamples;
    k.resolution = settings_.ssaoResolution;
    ao_->setKnobs(k);
    ao_->setMode(settings_.ssao);  // the frame rebuilds its chain at the next frame
    frame_->setView(settings_.aoOnly ? frame::View::AO : frame::View::Scene);
    frame_->setExposure(static_cast<float>(settings_.exposure));
}

std::string GameApp::aoStatus() const {
    // A mode this GPU cannot run was turned off by the frame with a message: say so.
    return frame_->offReason(*ao_).empty() ? ao_->mode() : ao_->mode() + " (off here)";
}

void GameApp::stepSimulation() {
    // A recording carries expected hashes once a second of game time, so a diverging playback
    // names the tick where it first went wrong.
    if (recorder_ && sim_->tick() > 0 && sim_->tick() % static_cast<std::uint64_t>(settings_.tickRate) == 0)
        recorder_->hash(static_cast<std::int64_t>(sim_->tick()) - 1, sim_->stateHashHex());
    handleTriggeredActions();
    *previousPlayer_ = sim_->player();
    sim_->step(input_.takeCommand());
    // One way: what happened this tick goes to sound, effects and the HUD.
    const auto& events = sim_->events();
    audio_->onEvents(events);
    combat_->onTick(events);
    smoke_->onTick(events, *sim_);
    hitMarker_ = std::max(0.0, hitMarker_ - 1.0 / 15.0);  // fades over a quarter second
    for (const auto& e : events)
        if (e.type == sim::SimEventType::TargetHit) hitMarker_ = 1.0;
}

void GameApp::handleTriggeredActions() {
    for (Action a : input_.takeTriggered()) {
        switch (a) {
            case Action::ToggleDebug: hud_->setPanelVisible(!hud_->panelVisible()); break;
            case Action::Menu: setMenuOpen(!menu_->isOpen()); break;
            case Action::Screenshot: writeScreenshot("obscura-" + std::to_string(sim_->tick()) + ".png"); break;
            case Action::CycleAo:
                // Shift+O steps backwards.
                settings_.ssao = ssao::cycleMode(settings_.ssao, input_.isKeyDown("lshift") || input_.isKeyDown("rshift") ? -1 : 1);
                applyAoSettings();
                break;
            case Action::AoOnlyView:
                settings_.aoOnly = !settings_.aoOnly;
                applyAoSettings();
                break;
            default: break;  // movement actions are read as held states
        }
    }
}

void GameApp::updateView(double alpha) {
    const auto& a = *previousPlayer_;
    const auto& b = sim_->player();
    const Vec3 ea = a.eye(), eb = b.eye();
    const Vec3 eye = ea + (eb - ea) * alpha;
    // Interpolate angles along the short way round.
    double dyaw = b.yaw - a.yaw;
    dyaw = std::remainder(dyaw, 2.0 * 3.14159265358979323846);
    const double yaw = a.yaw + dyaw * alpha;
    const double pitch = a.pitch + (b.pitch - a.pitch) * alpha;
    cameraNode_->setPosition(static_cast<float>(eye.x), static_cast<float>(eye.y), static_cast<float>(eye.z));
    cameraNode_->setOrientation(Ogre::Quaternion(Ogre::Radian(static_cast<float>(yaw)), Ogre::Vector3::UNIT_Y) *
                                Ogre::Quaternion(Ogre::Radian(static_cast<float>(pitch)), Ogre::Vector3::UNIT_X));
    using Shape = render::PropPose::Shape;
    std::vector<render::PropPose> poses;
    for (const auto& b : sim_->bodyPoses()) {
        const bool barrel = b.shape == sim::Simulation::BodyPose::Shape::Cylinder;
        poses.push_back({b.position, b.qx, b.qy, b.qz, b.qw, b.halfExtents, barrel ? Shape::Cylinder : Shape::Box,
                         barrel ? "barrel" : "crate"});
    }
    for (const auto& g : sim_->grenades())
        poses.push_back({g.position, g.qx, g.qy, g.qz, g.qw, Vec3{g.radius, g.radius, g.radius}, Shape::Sphere, "metal"});
    props_->update(poses);
    combat_->update(sim_->targets());

    const Ogre::Quaternion q = cameraNode_->getOrientation();
    const Ogre::Vector3 forward = q * Ogre::Vector3::NEGATIVE_UNIT_Z, up = q * Ogre::Vector3::UNIT_Y;
    audio_->update(eye, render::fromOgre(forward), render::fromOgre(up), b.velocity);
}

void GameApp::setMenuOpen(bool open) {
    menu_->setOpen(open);
    input_.releaseAll();  // keys held when the menu opened must not stay held behind it
    if (settings_.headless) return;  // nothing to grab; replays never pause
    mouseGrabbed_ = !open;
    setWindowGrab(mouseGrabbed_);
}

void GameApp::resizeWindow(int width, int height) {
    if (settings_.headless) return;  // the offscreen target keeps the size the run was started with
    settings_.width = width;
    settings_.height = height;
    SDL_SetWindowSize(mWindows.front().native, width, height);
    getRenderWindow()->resize(static_cast<unsigned>(width), static_cast<unsigned>(height));
    camera_->setAspectRatio(static_cast<Ogre::Real>(width) / static_cast<Ogre::Real>(height));
    applySetting("fov", std::to_string(settings_.fov), "menu");  // the vertical FOV follows the aspect
}

void GameApp::renderFrame(double frameMs) {
    render::HudState hs;
    hs.visible = settings_.hud;
    hs.crosshair = !menu_->isOpen();
    hs.frameMs = frameMs;
    hs.frameMsIsFixed = settings_.headless;
    hs.status.push_back("AO: " + aoStatus() + (settings_.aoOnly ? " (AO only)" : ""));
    const auto& w = sim_->weapon();
    hs.magazine = w.magazine;
    hs.magazineSize = w.magazineSize;
    hs.reserve = w.reserve;
    hs.reloadProgress = w.reloading ? w.reloadProgress : -1.0;
    hs.score = sim_->score();
    hs.hitMarker = hitMarker_;
    hs.throwCharge = sim_->throwCharge() > 0 ? sim_->throwCharge() : -1.0;
    hud_->update(hs);
    smoke_->render();
    frame_->update(static_cast<float>(static_cast<double>(sim_->tick()) / settings_.tickRate));
    mRoot->renderOneFrame();
}

void GameApp::finishFrame() {
    // GL queues work; llvmpipe runs it when something waits. Reading one pixel back makes each
    // timed frame include its own rendering instead of a later frame's.
    Ogre::RenderTarget* target = getRenderWindow();
    if (offscreen_) target = offscreen_->getBuffer()->getRenderTarget();
    Ogre::uint8 pixel[4];
    Ogre::PixelBox box(1, 1, 1, Ogre::PF_BYTE_RGBA, pixel);
    target->copyContentsToMemory(Ogre::Box(0, 0, 1, 1), box);
}

void GameApp::writeScreenshot(const std::string& path) {
    Ogre::RenderTarget* target = getRenderWindow();
    if (offscreen_) target = offscreen_->getBuffer()->getRenderTarget();
    const auto w = target->getWidth(), h = target->getHeight();
    Ogre::Image image(Ogre::PF_BYTE_RGB, w, h);
    target->copyContentsToMemory(image.getPixelBox(), image.getPixelBox());
    image.save(path);
}

void GameApp::prepareReplay() {
    const std::string& path = !settings_.timedemo.empty() ? settings_.timedemo : settings_.replay;
    if (path.empty()) return;
    // Every `set` is validated now, against a scratch copy: a bad value fails before the first frame.
    auto known = [this](const std::string& key) { return parser_.isRuntime(key); };
    script_ = std::make_unique<replay::Script>(replay::loadScript(path, known));
    Settings scratch = settings_;
    for (const auto& c : script_->commands)
        if (c.type == replay::Command::Type::Set)
            parser_.apply(c.name, c.value, scratch, script_->fileName + ":" + std::to_string(c.line));

    // The script's header decides the level, seed, resolution and tick rate.
    namespace fs = std::filesystem;
    fs::path level = script_->level;
    if (level.is_relative()) {
        const fs::path besideScript = fs::path(path).parent_path() / level;
        level = fs::exists(besideScript) ? besideScript : fs::path(settings_.dataDir) / level;
    }
    if (!fs::is_regular_file(level))
        throw replay::ScriptError(path + ": level '" + script_->level + "' not found");
    settings_.level = level.string();
    settings_.seed = script_->seed;
    settings_.width = script_->width;
    settings_.height = script_->height;
    settings_.tickRate = script_->tickRate;
    if (!script_->start.empty()) settings_.startPose = script_->start;
    settings_.vsync = false;
    if (settings_.replay.size()) settings_.headless = true;

    if (!settings_.replay.empty()) {
        // Fail now, not at the first capture, if the folder cannot be written.
        std::error_code ec;
        fs::create_directories(settings_.captureDir, ec);
        const fs::path probe = fs::path(settings_.captureDir) / ".obscura-write-test";
        std::ofstream(probe.string()) << "";
        if (ec || !fs::exists(probe))
            throw std::runtime_error("capture folder '" + settings_.captureDir + "' cannot be written");
        fs::remove(probe, ec);
    }
}

std::string GameApp::rendererDescription() const {
    const Ogre::RenderSystemCapabilities* caps = mRoot->getRenderSystem()->getCapabilities();
    std::ostringstream os;
    os << caps->getDeviceName() << " | " << caps->getRenderSystemName() << " | driver "
       << caps->getDriverVersion().toString() << " | OGRE " << OGRE_VERSION_MAJOR << "." << OGRE_VERSION_MINOR << "."
       << OGRE_VERSION_PATCH;
    return os.str();
}

int GameApp::run() {
    prepareReplay();
    // OGRE's GL3Plus is GLX-only: SDL must use X11 (not Wayland or a dummy driver), and even a
    // headless run needs an X display for the GL context. Say so before OGRE trips over it.
    SDL_SetHint(SDL_HINT_VIDEODRIVER, "x11");
    if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
        const char* display = std::getenv("DISPLAY");
        throw std::runtime_error(std::string("cannot open an X display (DISPLAY=") + (display ? display : "unset") +
                                 "): " + SDL_GetError() +
                                 ". Run under Xvfb, e.g. `xvfb-run -a obscura --headless`, or use scripts/play.sh");
    }
    if (!settings_.record.empty())
        recorder_ = std::make_unique<replay::Recorder>(settings_.level, settings_.seed, settings_.width,
                                                       settings_.height, settings_.tickRate);
    initApp();
    if (!mRoot || getRenderWindow() == nullptr) throw std::runtime_error("OGRE failed to initialise (see the log)");
    loadLevel();
    createScene();

    const int code = script_ ? runReplay(!settings_.timedemo.empty()) : runLive();

    if (!settings_.screenshot.empty()) {
        writeScreenshot(settings_.screenshot);
        std::cout << "screenshot " << settings_.screenshot << "\n";
        // Where the camera was, in --start-pose's form: the player may have been moved by physics
        // from the pose asked for, and tools/aoref traces its reference from this one.
        const auto& p = sim_->player();
        const Vec3 eye = p.eye();
        std::printf("camera-pose %.4f %.4f %.4f %.4f %.4f\n", eye.x, eye.y, eye.z, p.yaw * 180.0 / 3.14159265358979323846,
                    p.pitch * 180.0 / 3.14159265358979323846);
    }
    if (recorder_) writeRecording();
    std::cout << "state-hash " << sim_->stateHashHex() << "\n";
    closeApp();
    return code;
}

int GameApp::runLive() {
    if (!settings_.headless) {
        mouseGrabbed_ = true;
        setWindowGrab(true);
    }
    const double dt = 1.0 / settings_.tickRate;
    FixedStepClock clock(dt);
    auto last = std::chrono::steady_clock::now();
    double frameMs = dt * 1000.0;
    while (!quit_) {
        pollEvents();
        if (settings_.headless) {
            // Deterministic: exactly one tick per rendered frame, no wall clock involved.
            stepSimulation();
            updateView(1.0);
        } else {
            const auto now = std::chrono::steady_clock::now();
            const double frameSeconds = std::chrono::duration<double>(now - last).count();
            last = now;
            frameMs = frameSeconds * 1000.0;
            // The pause menu pauses the game (the clock does not bank the time either).
            const int ticks = clock.advance(frameSeconds);
            if (!menu_->isOpen())
                for (int n = ticks; n > 0; --n) stepSimulation();
            else
                handleTriggeredActions();  // Esc still closes the menu
            updateView(menu_->isOpen() ? 1.0 : clock.alpha());
        }
        renderFrame(frameMs);
        if (mRoot->endRenderingQueued()) quit_ = true;
        if (settings_.ticks > 0 && static_cast<long>(sim_->tick()) >= settings_.ticks) quit_ = true;
    }
    return 0;
}

namespace {
// CPU time of the whole process, all threads (llvmpipe rasterises on its own threads).
double processCpuMs() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}
}  // namespace

int GameApp::runReplay(bool timed) {
    std::cout << "renderer " << rendererDescription() << "\n";
    ReplayPlayer player(*script_);
    std::vector<double> frameMs;
    std::vector<TimedemoSegment> segments(1);
    const double fixedMs = 1000.0 / settings_.tickRate;
    double lastMs = fixedMs;
    bool diverged = false;
    for (std::int64_t t = 0; t <= player.lastTick() && !quit_; ++t) {
        const auto start = std::chrono::steady_clock::now();
        const double cpuStart = processCpuMs();
        const ReplayTick due = player.take(t);
        if (!due.settings.empty() && !segments.back().frameMs.empty()) segments.push_back({});
        for (const auto* c : due.settings) {
            applySetting(c->name, c->value, script_->fileName + ":" + std::to_string(c->line));
            segments.back().label += (segments.back().label.empty() ? "" : " ") + c->name + "=" + c->value;
        }
        for (const auto& in : due.inputs) injectInput(in);
        pollEvents();
        stepSimulation();
        updateView(1.0);
        // Captures show the fixed tick time, so the same replay gives the same pixels.
        renderFrame(timed ? lastMs : fixedMs);
        if (timed) finishFrame();
        for (const auto* c : due.captures) writeCapture(c->name);
        for (const auto* c : due.hashes) {
            const std::string hex = sim_->stateHashHex();
            std::cout << "hash " << t << " " << hex << "\n";
            if (!c->value.empty() && c->value != hex && !diverged) {
                diverged = true;
                std::cerr << script_->fileName << ":" << c->line << ": replay diverged at tick " << t << ": expected "
                          << c->value << ", got " << hex << "\n";
            }
        }
        lastMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        frameMs.push_back(lastMs);
        segments.back().frameMs.push_back(lastMs);
        segments.back().cpuMs.push_back(processCpuMs() - cpuStart);
    }
    for (auto& seg : segments)
        if (seg.label.empty()) seg.label = "start";
    // 10 frames: a new AO compositor compiles its shaders in its first two or three.
    if (timed) std::cout << formatFrameStats(computeFrameStats(frameMs), script_->fileName) << formatSegments(segments, 10);
    return diverged ? 3 : 0;
}

void GameApp::applySetting(const std::string& key, const std::string& value, const std::string& where) {
    parser_.apply(key, value, settings_, where);  // validated at load time, so this does not throw
    if (key == "fov") {
        const double aspect = camera_->getAspectRatio();
        camera_->setFOVy(Ogre::Radian(static_cast<Ogre::Real>(2.0 * std::atan(std::tan(degToRad(settings_.fov) * 0.5) / aspect))));
    } else if (key.rfind("ssao", 0) == 0 || key == "ao-only" || key == "exposure") {
        applyAoSettings();
    } else if (key == "smoke-at") {
        smoke_->spawn(parseVec3(settings_.smokeAt));
    } else if (key == "master-volume" || key == "effects-volume") {
        audio_->setVolumes(settings_.masterVolume, settings_.effectsVolume);
    } else if (key == "debug-panel") {
        hud_->setPanelVisible(settings_.showDebugPanel);
    }
}

void GameApp::injectInput(const ReplayInput& in) {
    // Real SDL events, addressed to our window: they reach keyPressed() etc. through OgreBites
    // exactly as a keyboard's would.
    SDL_Event e{};
    const Uint32 window = SDL_GetWindowID(mWindows.front().native);
    const bool down = in.kind == ReplayInput::Kind::KeyDown;
    if (in.kind == ReplayInput::Kind::MouseMotion) {
        e.type = SDL_MOUSEMOTION;
        e.motion.windowID = window;
        e.motion.xrel = in.dx;
        e.motion.yrel = in.dy;
    } else if (in.key.rfind("mouse", 0) == 0) {
        e.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
        e.button.windowID = window;
        e.button.state = down ? SDL_PRESSED : SDL_RELEASED;
        e.button.button = in.key == "mouse1" ? SDL_BUTTON_LEFT : in.key == "mouse2" ? SDL_BUTTON_RIGHT : SDL_BUTTON_MIDDLE;
    } else {
        e.type = down ? SDL_KEYDOWN : SDL_KEYUP;
        e.key.windowID = window;
        e.key.state = down ? SDL_PRESSED : SDL_RELEASED;
        e.key.keysym.sym = keycodeFromKeyName(in.key).value_or(0);
        e.key.keysym.scancode = static_cast<SDL_Scancode>(scancodeFromKeyName(in.key).value_or(0));
    }
    SDL_PushEvent(&e);
}

void GameApp::writeCapture(const std::string& name) {
    // Write beside, then rename: a capture is never left half-written.
    namespace fs = std::filesystem;
    const fs::path final = fs::path(settings_.captureDir) / (name + ".png");
    const fs::path partial = fs::path(settings_.captureDir) / (name + ".partial.png");
    writeScreenshot(partial.string());
    fs::rename(partial, final);
    std::cout << "capture " << name << " " << final.string() << "\n";
}

void GameApp::writeRecording() {
    // Expected hashes every second of game time let playback name the first diverging tick.
    recorder_->hash(static_cast<std::int64_t>(sim_->tick()) - 1, sim_->stateHashHex());
    recorder_->end(static_cast<std::int64_t>(sim_->tick()) - 1);
    const std::string tmp = settings_.record + ".partial";
    {
        std::ofstream out(tmp);
        out << replay::formatScript(recorder_->script());
        if (!out) throw std::runtime_error("cannot write recording '" + settings_.record + "'");
    }
    std::filesystem::rename(tmp, settings_.record);
    std::cout << "recorded " << settings_.record << "\n";
}

// One path for every key and mouse button: the input state, and the recording when there is one.
bool GameApp::menuTakesInput() const { return menu_ && menu_->isOpen() && !settings_.headless; }

void GameApp::onButton(const std::string& name, bool down) {
    if (name.empty()) return;
    if (menuTakesInput()) {
        // A binding waiting for its key takes it; otherwise only the menu key (to close) gets through.
        if (down && menu_->offerKey(name)) return;
        const auto menuKey = settings_.bindings.find(Action::Menu);
        if (menuKey == settings_.bindings.end() || menuKey->second != name) return;
    }
    if (down) input_.press(name);
    else input_.release(name);
    if (!recorder_) return;
    const auto tick = static_cast<std::int64_t>(sim_->tick());
    if (down) recorder_->keyDown(tick, name);
    else recorder_->keyUp(tick, name);
}

bool GameApp::keyPressed(const OgreBites::KeyboardEvent& evt) {
    if (menuTakesInput()) imguiInput_->keyPressed(evt);
    if (!evt.repeat) onButton(keyNameFromKeycode(evt.keysym.sym), true);
    return true;
}

bool GameApp::keyReleased(const OgreBites::KeyboardEvent& evt) {
    if (menuTakesInput()) imguiInput_->keyReleased(evt);
    onButton(keyNameFromKeycode(evt.keysym.sym), false);
    return true;
}

bool GameApp::mouseMoved(const OgreBites::MouseMotionEvent& evt) {
    if (menuTakesInput()) return imguiInput_->mouseMoved(evt);
    if (mouseGrabbed_ || settings_.headless) {
        input_.mouseMotion(evt.xrel, evt.yrel);
        if (recorder_) recorder_->mouse(static_cast<std::int64_t>(sim_->tick()), evt.xrel, evt.yrel);
    }
    return true;
}

bool GameApp::mousePressed(const OgreBites::MouseButtonEvent& evt) {
    if (menuTakesInput() && !menu_->offerKey(keyNameFromMouseButton(evt.button))) imguiInput_->mousePressed(evt);
    else onButton(keyNameFromMouseButton(evt.button), true);
    return true;
}

bool GameApp::mouseReleased(const OgreBites::MouseButtonEvent& evt) {
    if (menuTakesInput()) imguiInput_->mouseReleased(evt);
    onButton(keyNameFromMouseButton(evt.button), false);
    return true;
}

bool GameApp::mouseWheelRolled(const OgreBites::MouseWheelEvent& evt) {
    if (menuTakesInput()) imguiInput_->mouseWheelRolled(evt);
    return true;
}

}  // namespace obscura
