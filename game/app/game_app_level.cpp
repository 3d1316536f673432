// See game_app.h: trigger_changelevel. The next level is `<map>.map` beside the current one (a
// Quake episode's maps sit in one folder), found by the level's confined lookup; the game unloads
// the level and loads that one, as Quake's changelevel restarts the server. A replay or a timedemo
// plays one level, so it ends there; so does a level whose next map is not beside it, with a line
// that says why. A recording is written at the change (it holds one level) and stops.
#include "app/game_app.h"

#include "app/debug_panel.h"
#include "app/game_audio.h"
#include "app/pause_menu.h"
#include "app/render_view.h"
#include "map/asset_path.h"
#include "map/entity_values.h"
#include "replay/replay_recorder.h"
#include "session.h"

#include <OgreImGuiInputListener.h>

#include <filesystem>
#include <iostream>

namespace obscura {

void GameApp::changeLevel(const map::LevelEntity& trigger) {
    const std::string name = trigger.value("map");
    const std::string where = trigger.where(session_->level().sourcePath) + ": trigger_changelevel";
    std::cout << "changelevel " << (name.empty() ? "(none)" : name) << " at tick " << session_->tick() << "\n";
    const auto endRun = [&](const std::string& why) {
        std::cerr << "obscura: " << where << ": " << why << "; the run ends here\n";
        quit_ = true;
    };
    if (script_) {
        quit_ = true;  // the replay reached its level's exit: nothing to say
        return;
    }
    if (name.empty()) return endRun("no 'map' names the next level");
    if (!map::isBareName(name)) return endRun("'map' " + map::quotedValue(name) + " is not a bare map name (the next map is looked for beside this one)");
    const std::string dir = std::filesystem::path(settings_.level).parent_path().string();
    const map::AssetPath next = map::resolveAsset(name + ".map", {dir}, {dir}, "the level's folder");
    if (!next.error.empty()) return endRun("'" + name + ".map' " + next.error);
    if (next.file.empty()) return endRun("no '" + name + ".map' beside " + settings_.level);

    if (recorder_) {
        try {
            writeRecording();
        } catch (const std::exception& e) {
            std::cerr << "obscura: " << e.what() << "\n";
        }
        recorder_.reset();
    }
    // The level's objects go in the reverse of load()'s order; a load failure of the next map is a
    // load-time error like the first map's (it names the file and line).
    imguiInput_.reset();
    panel_.reset();
    menu_.reset();
    view_.reset();
    audio_.reset();
    session_.reset();
    settings_.level = next.file;
    settings_.startPose.clear();  // both named places in the old level
    settings_.smokeAt.clear();
    load();
    if (!settings_.headless) updatePointerGrab();
}

}  // namespace obscura
