// See game_app.h.
#include "cache_dir.h"
#include "app/game_app.h"

#include "app/debug_panel.h"
#include "app/game_audio.h"
#include "app/leak_check.h"
#include "app/pause_menu.h"
#include "app/render_view.h"
#include "app/sdl_keys.h"
#include "app/x_errors.h"
#include "map/entity_values.h"
#include "render/hud.h"
#include "render/level_lighting.h"
#include "render/pass_order.h"
#include "replay/replay_recorder.h"
#include "replay/replay_script.h"
#include "session.h"
#include "smoke/smoke_dump.h"
#include "ssao/ssao_modes.h"
#include "ao_truth/truth_compare.h"
#include "stop_signal.h"

#include <Ogre.h>
#include <OgreImGuiInputListener.h>
#include <OgreOverlaySystem.h>
#include <OgreRTShaderSystem.h>
#include <SDL2/SDL.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
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
// The hidden window only carries the GL context; frames go to an offscreen texture.
constexpr unsigned kHiddenWindowSize = 64;
constexpr double kPi = 3.14159265358979323846;

// What the view needs of a frame besides the state: its time, the HUD's and crosshair's visibility.
RenderView::Frame frameOf(const Settings& settings, bool menuOpen, double frameMs, std::string notice) {
    RenderView::Frame frame;
    frame.notice = std::move(notice);
    frame.frameMs = frameMs;
    frame.frameMsIsFixed = settings.headless;
    frame.hudVisible = settings.hud;
    frame.crosshair = !menuOpen;
    return frame;
}
}  // namespace

GameApp::GameApp(Settings settings, const SettingsParser& parser)
    : OgreBites::ApplicationContext("Obscura"), settings_(std::move(settings)), parser_(parser), input_(settings_) {
    if (settings_.dataDir.empty()) settings_.dataDir = OBSCURA_DATA_DIR;
    if (settings_.level.empty()) settings_.level = dataPath("media/levels/arena.map");
    if (settings_.headless && settings_.ticks == 0) settings_.ticks = TickDurations(settings_.tickRate).headlessTicks;
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
        const std::filesystem::path dir = cacheDir();
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        logFile = (dir / "obscura.log").string();
    }
    auto* logs = new Ogre::LogManager();
    logs->createLog(logFile, true, false, false);
    mRoot = OGRE_NEW Ogre::Root("", "", "");
    render::installNamedPassOrder();  // before any material: the draw order by names, not addresses
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
    // Our own resources (media/resources.cfg lists them relative to the data folder; "dir/*" is
    // every folder in dir, in name order, so a technique's media/<t>/ and shaders/<t>/ join alone).
    Ogre::ConfigFile cf;
    cf.load(dataPath("media/resources.cfg"));
    for (const auto& [section, settings] : cf.getSettingsBySection()) {
        for (const auto& [type, location] : settings) {
            std::string path = location;
            if (path.rfind("@generated/", 0) == 0)
                path = std::string(OBSCURA_GENERATED_DIR) + "/" + path.substr(11);
            else if (path.front() != '/')
                path = dataPath(path);
            if (path.size() < 2 || path.compare(path.size() - 2, 2, "/*") != 0) {
                rgm.addResourceLocation(path, type, section);
                continue;
            }
            std::vector<std::string> folders;
            for (const auto& entry : std::filesystem::directory_iterator(path.substr(0, path.size() - 2)))
                if (entry.is_directory()) folders.push_back(entry.path().string());
            std::sort(folders.begin(), folders.end());
            for (const auto& folder : folders) rgm.addResourceLocation(folder, type, section);
        }
    }
}

void GameApp::shutdown() {
    // Order matters (see shared/README): our OGRE objects first (the view destroys its scene),
    // then RTSS, overlays, root.
    imguiInput_.reset();
    panel_.reset();
    view_.reset();
    menu_.reset();
    audio_.reset();
    OgreBites::ApplicationContext::shutdown();
}

void GameApp::load() {
    std::vector<std::string> warnings;
    map::LoadTimes times;
    map::Level level = Session::loadLevel(settings_, &warnings, &times);
    checkInLevel(settings_, level);  // the start pose and smoke position inside the level's box
    // Every warning to the log; the first kMaxWarningLines on stderr, as file:line: text.
    for (const auto& w : warnings) Ogre::LogManager::getSingleton().logWarning(w);
    for (const auto& line : map::warningLines(warnings)) std::cerr << line << "\n";
    const Vec3 towardSun = render::computeLevelLighting(level).sunDirection;
    const auto t0 = std::chrono::steady_clock::now();
    session_ = std::make_unique<Session>(settings_, std::move(level), towardSun);
    const auto t1 = std::chrono::steady_clock::now();
    // The movers' and triggers' problems (a target naming nothing, a bad speed), file:line like the
    // map's: the level still plays.
    const std::vector<std::string>& simWarnings = session_->sim().warnings();
    for (const auto& w : simWarnings) Ogre::LogManager::getSingleton().logWarning(w);
    for (const auto& line : map::warningLines(simWarnings)) std::cerr << line << "\n";

    view_ = std::make_unique<RenderView>(RenderView::Context{*mRoot, *getRenderWindow(), *mOverlaySystem, *mShaderGenerator},
                                         settings_, *session_);
    times.sessionMs = std::chrono::duration<double, std::milli>(t1 - t0).count();
    times.sceneMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count();
    const std::string summary = map::summaryLine(session_->level(), warnings.size() + simWarnings.size(), times);
    Ogre::LogManager::getSingleton().logMessage(summary);
    std::cerr << summary << "\n";
    // The level's title (worldspawn's `message`), where Quake prints it on load: the console (here
    // stderr) and, in a window, its title bar.
    const auto& entities = session_->level().entities;
    if (const std::string title = entities.empty() ? "" : map::messageText(entities.front().value("message")); !title.empty()) {
        std::cerr << "obscura: level title: " << title << "\n";
        if (!settings_.headless) SDL_SetWindowTitle(mWindows.front().native, ("Obscura - " + title).c_str());
    }
    // Sounds load once, here (a malformed WAV stops the game at load time, naming the file); with
    // no audio device the game runs silent after one warning line.
    audio_ = std::make_unique<GameAudio>(settings_, dataPath("media/sounds"), session_->smoke().settings().emitTime);

    PauseMenu::Hooks hooks;
    hooks.set = [this](const std::string& key, const std::string& value) { applySetting(key, value, "menu"); };
    hooks.resize = [this](int w, int h) { resizeWindow(w, h); };
    hooks.resume = [this] { setMenuOpen(false); };
    hooks.quit = [this] { quit_ = true; };
    hooks.click = [this] { audio_->uiClick(); };
    menu_ = std::make_unique<PauseMenu>(settings_, hooks);
    imguiInput_ = std::make_unique<OgreBites::ImGuiInputListener>();  // after the HUD made ImGui's context
    view_->hud().setMenu([this] { menu_->draw(); });
    panel_ = std::make_unique<DebugPanel>(*view_, *session_, settings_, [this] { applyAoSettings(); });
}

void GameApp::applyAoSettings() { view_->applyAo(RenderView::aoSettings(settings_)); }

void GameApp::handleActions() {
    for (const TriggeredAction& t : input_.takeTriggered()) {
        switch (t.action) {
            case Action::ToggleDebug: setPanelVisible(!panel_->visible()); break;
            case Action::Menu: setMenuOpen(!menu_->isOpen()); break;
            case Action::Screenshot: {
                // F12 inside the frame: a folder that cannot be written costs the picture, not the game.
                // Where it went (or why not) shows on the HUD for a while, in game ticks (replays repeat).
                std::error_code ec;
                const std::string path = std::filesystem::absolute("obscura-" + std::to_string(session_->tick()) + ".png", ec).string();
                const std::string problem = view_->saveScreenshot(path);
                if (problem.empty()) std::cout << "screenshot " << path << "\n";
                else std::cerr << "obscura: F12 screenshot: " << problem << "; playing on\n";
                notice_ = problem.empty() ? "F12: wrote " + path : "F12: no screenshot: " + problem;
                noticeUntilTick_ = session_->tick() + static_cast<std::uint64_t>(session_->durations().centrePrintTicks);
                break;
            }
            case Action::CycleAo:
                // Shift+O steps backwards (Shift as it was when O went down).
                settings_.ssao = ssao::cycleMode(settings_.ssao, t.shift ? -1 : 1);
                applyAoSettings();
                break;
            case Action::CycleView: {
                // The frame's debug views; the AO-only view follows P's setting.
                const std::string v = view_->cycleView();
                settings_.aoOnly = v == "ao";
                break;
            }
            case Action::CycleTruth:
                // off -> reference -> the mode's AO -> heat map -> off (app/truth_key.h).
                settings_.truth = ao_truth::showName(ao_truth::nextShow(*ao_truth::showFromName(settings_.truth)));
                view_->setTruth(settings_.truth, settings_.truthRays);
                break;
            case Action::AoOnlyView:
                settings_.aoOnly = !settings_.aoOnly;
                applyAoSettings();
                break;
            default: break;  // movement actions are read as held states
        }
    }
}

void GameApp::tick() {
    // A recording carries expected hashes once a second of game time, so a diverging playback
    // names the tick where it first went wrong.
    if (recorder_ && session_->tick() > 0 && session_->tick() % static_cast<std::uint64_t>(settings_.tickRate) == 0)
        recorder_->hash(static_cast<std::int64_t>(session_->tick()) - 1, session_->sim().stateHashHex());
    session_->step(input_.takeCommand());
    for (const sim::SimEvent& e : session_->events()) {
        switch (e.type) {
            case sim::SimEventType::Shot: ++tally_[0]; break;
            case sim::SimEventType::Jump: ++tally_[1]; break;
            case sim::SimEventType::ReloadStart: ++tally_[2]; break;
            case sim::SimEventType::GrenadeThrow: ++tally_[3]; break;
            default: break;
        }
    }
    // One way: what happened this tick goes to sound, effects and the HUD.
    audio_->onEvents(session_->events());
    view_->onTick(session_->events());
    if (const map::LevelEntity* trigger = session_->changeLevel()) changeLevel(*trigger);
}

void GameApp::followState(double alpha) {
    view_->update(*session_, alpha);
    const RenderView::Listener ear = view_->listener();
    audio_->update(ear.position, ear.forward, ear.up, session_->sim().player().velocity);
}

void GameApp::present(double alpha, double frameMs) {
    followState(alpha);
    view_->draw(*session_, frameOf(settings_, menu_->isOpen(), frameMs, notice()));
    afterUiFrame();
}

void GameApp::skipDraw(double alpha, double frameMs) {
    followState(alpha);
    view_->skipDraw(frameOf(settings_, menu_->isOpen(), frameMs, notice()));
}

bool GameApp::paused() const { return menu_->isOpen(); }
bool GameApp::interfaceOpen() const { return menu_->isOpen() || panel_->visible(); }
bool GameApp::quitRequested() const { return quit_ || mRoot->endRenderingQueued(); }
std::uint64_t GameApp::simTick() const { return session_->tick(); }
std::string GameApp::stateHashHex() const { return session_->sim().stateHashHex(); }
double GameApp::smokeRenderThreadMs() const { return session_->smoke().lastTickMs() + view_->smokeUploadMs(); }
void GameApp::writeScreenshot(const std::string& path) {
    if (settings_.headless && view_->truthShown()) {
        // A headless capture of the truth is the finished reference's, scored: wait for the
        // tracer, then one frame takes the reference and scores the mode, the next shows both.
        // The live game never waits (app/truth_key.h); rendering drives nothing in the simulation.
        view_->waitTruth();
        for (int frame = 0; frame < 2; ++frame) present(1.0, 1000.0 / settings_.tickRate);
    }
    // The volumetrics march a quarter of their pixels a frame and reuse the rest: a capture rewinds
    // their phase and draws the unchanged scene until each was marched on it, in one order, so it
    // shows the same image whatever frames a window or a headless run drew before, or how many
    // (no tick runs meanwhile; --replay-draw captures draws only the frames captured).
    for (int frame = view_->settleVolumes(); frame > 0; --frame) present(1.0, 1000.0 / settings_.tickRate);
    view_->writeScreenshot(path);
}
void GameApp::finishFrame() { view_->finishFrame(); }

InputRouting GameApp::routing() const {
    return {menu_ && menu_->isOpen(), panel_ && panel_->visible(), settings_.headless};
}

void GameApp::setMenuOpen(bool open) {
    menu_->setOpen(open);
    input_.releaseAll();  // keys held when the menu opened must not stay held behind it
    updatePointerGrab();
}

void GameApp::setPanelVisible(bool visible) {
    panel_->setVisible(visible);
    updatePointerGrab();
}

void GameApp::updatePointerGrab() {
    if (settings_.headless) return;  // nothing to grab; replays never pause
    mouseGrabbed_ = routing().grabPointer();
    setWindowGrab(mouseGrabbed_);
}

void GameApp::resizeWindow(int width, int height) {
    if (settings_.headless) return;  // the offscreen target keeps the size the run was started with
    settings_.width = width;
    settings_.height = height;
    SDL_SetWindowSize(mWindows.front().native, width, height);
    getRenderWindow()->resize(static_cast<unsigned>(width), static_cast<unsigned>(height));
    view_->resized(width, height, settings_.fov);
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
    script_ = prepareReplay(settings_, parser_);
    // OGRE's GL3Plus is GLX-only: SDL must use X11 (not Wayland or a dummy driver), and even a
    // headless run needs an X display for the GL context. Say so before OGRE trips over it.
    // SDL would turn SIGINT/SIGTERM into a quit event that only the live loop reads; StopSignal
    // takes them instead, for every run mode.
    SDL_SetHint(SDL_HINT_VIDEODRIVER, "x11");
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
        const char* display = std::getenv("DISPLAY");
        throw std::runtime_error(std::string("cannot open an X display (DISPLAY=") + (display ? display : "unset") +
                                 "): " + SDL_GetError() +
                                 ". Run under Xvfb, e.g. `xvfb-run -a obscura --headless`, or use scripts/play.sh");
    }
    const StopSignal stop;
    if (!settings_.record.empty())
        recorder_ = std::make_unique<replay::Recorder>(settings_.level, settings_.seed, settings_.width,
                                                       settings_.height, settings_.tickRate);
    // A recording carries the settings that change input, so it plays back the same anywhere.
    if (recorder_)
        for (const auto& [k, v] : inputSettingValues(settings_)) recorder_->setting(k, v);
    initApp();
    if (!mRoot || getRenderWindow() == nullptr) throw std::runtime_error("OGRE failed to initialise (see the log)");
    installXErrorHandlers();
    load();

    int code = 0;
    if (script_) {
        std::cout << "renderer " << rendererDescription() << "\n";
        ReplayDriver driver(*script_, *this, !settings_.timedemo.empty(), settings_.tickRate, settings_.captureDir,
                            settings_.replayDraw == "every-frame");
        code = runFrames(*this, driver);
        std::cout << driver.report();
    } else if (settings_.headless) {
        HeadlessDriver driver(settings_.tickRate, settings_.ticks);
        code = runFrames(*this, driver);
    } else {
        updatePointerGrab();
        LiveDriver driver(settings_.tickRate, settings_.ticks);
        code = runFrames(*this, driver);
    }
    if (StopSignal::requested())
        std::cerr << "obscura: stopped by " << (StopSignal::pending() == SIGINT ? "SIGINT" : "SIGTERM") << " at tick "
                  << session_->tick() << "\n";

    if (!settings_.screenshot.empty()) {
        writeScreenshot(settings_.screenshot);
        std::cout << "screenshot " << settings_.screenshot << "\n";
    }
    // Where the camera ended, in --start-pose's form, for every run (a replay's captures print
    // theirs too): the player may have been moved by physics from the pose asked for, and
    // tools/aoref traces its reference from this one.
    std::cout << "camera-pose " << cameraPose() << "\n";
    if (!settings_.volumeDump.empty()) view_->writeBufferDump("volumeMap", settings_.volumeDump);
    if (!settings_.lightDump.empty()) view_->writeBufferDump("litMap", settings_.lightDump);
    if (!settings_.irradianceDump.empty()) view_->writeIrradianceDump(settings_.irradianceDump);
    if (!settings_.smokeDump.empty()) smoke::writeSmokeDump(session_->smoke().dump(), settings_.smokeDump);
    if (recorder_) writeRecording();
    std::cout << summaryLine() << "\n";
    if (xErrorCount() > 0) std::cerr << "obscura: " << xErrorCount() << " X error(s) in this run\n";
    std::cout << "state-hash " << session_->sim().stateHashHex() << "\n";
    if (runLeakedMemory()) {
        std::cerr << "obscura: LeakSanitizer found memory lost during the run (report above)\n";
        code = 1;
    }
    closeApp();
    return code;
}

// Bullet holes in the level's signs' plates now (each sign keeps at most SIGN_MAX_HOLES).
std::size_t GameApp::signHoles() const {
    std::size_t n = 0;
    for (const auto& h : session_->signs().holes()) n += h.holes().size();
    return n;
}

std::string GameApp::cameraPose() const {
    const auto& p = session_->sim().player();
    const Vec3 eye = p.eye();
    char line[160];
    std::snprintf(line, sizeof line, "%.4f %.4f %.4f %.4f %.4f", eye.x, eye.y, eye.z, p.yaw * 180.0 / kPi, p.pitch * 180.0 / kPi);
    return line;
}

std::string GameApp::notice() const { return session_ && session_->tick() < noticeUntilTick_ ? notice_ : std::string(); }

std::string GameApp::summaryLine() const {
    const auto& p = session_->sim().player();
    char pose[96];
    std::snprintf(pose, sizeof pose, "yaw %.2f pitch %.2f", p.yaw * 180.0 / kPi + 0.0, p.pitch * 180.0 / kPi + 0.0);
    return "summary tick " + std::to_string(session_->tick()) + " shots " + std::to_string(tally_[0]) + " jumps " +
           std::to_string(tally_[1]) + " reloads " + std::to_string(tally_[2]) + " grenades " +
           std::to_string(tally_[3]) + " ao " + settings_.ssao + " sign-holes " + std::to_string(signHoles()) + " " + pose;
}

void GameApp::applySetting(const std::string& key, const std::string& value, const std::string& where) {
    parser_.apply(key, value, settings_, where);  // validated at load time, so this does not throw
    if (recorder_ && where == "menu") recorder_->set(static_cast<std::int64_t>(session_->tick()), key, value);
    if (key == "fov") {
        view_->setFov(settings_.fov);
    } else if (key.rfind("ssao", 0) == 0 || key == "ao-only" || key == "exposure") {
        applyAoSettings();
    } else if (key == "truth" || key == "truth-rays") {
        view_->setTruth(settings_.truth, settings_.truthRays);
    } else if (key == "sign-mode" || key == signs::kHaze.name) {
        view_->setSigns(settings_.signMode, settings_.signHaze);
    } else if (key == "smoke-at") {
        session_->spawnSmoke(parseVec3(settings_.smokeAt));
    } else if (key == "master-volume" || key == "effects-volume") {
        audio_->setVolumes(settings_.masterVolume, settings_.effectsVolume);
    } else if (key == "debug-panel") {
        setPanelVisible(settings_.showDebugPanel);
    }
}

void GameApp::writeRecording() {
    // Expected hashes every second of game time let playback name the first diverging tick.
    recorder_->hash(static_cast<std::int64_t>(session_->tick()) - 1, session_->sim().stateHashHex());
    recorder_->end(static_cast<std::int64_t>(session_->tick()) - 1);
    const std::string tmp = settings_.record + ".partial";
    {
        std::ofstream out(tmp);
        out << replay::formatScript(recorder_->script());
        if (!out) throw std::runtime_error("cannot write recording '" + settings_.record + "'");
    }
    std::filesystem::rename(tmp, settings_.record);
    std::cout << "recorded " << settings_.record << "\n";
}

}  // namespace obscura
