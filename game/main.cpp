// obscura: the game executable. Parses settings, runs the game, and turns every load-time error
// into one clear line on stderr and a non-zero exit.
#include "app/game_app.h"
#include "replay/replay_script.h"
#include "settings.h"

#include <OgreException.h>

#include <filesystem>
#include <iostream>
#include <vector>

int main(int argc, char** argv) {
    try {
        obscura::SettingsParser parser;
        obscura::Settings settings;
        if (!parser.parse(argc, argv, settings)) return 0;  // --help
        // A live game with no --config reads the user's (the pause menu saves there); headless runs,
        // replays and timedemos never do, so their results do not depend on who runs them.
        const bool live = !settings.headless && settings.replay.empty() && settings.timedemo.empty();
        if (live && settings.configFile.empty()) {
            const std::string user = obscura::defaultConfigPath();
            if (std::filesystem::exists(user)) {
                std::vector<const char*> args(argv, argv + argc);
                args.push_back("--config");
                args.push_back(user.c_str());
                settings = obscura::Settings();
                parser.parse(static_cast<int>(args.size()), args.data(), settings);
            }
            settings.configFile = user;
        }
        // Outputs are checked before anything runs: a run must not end by failing to write.
        obscura::checkOutputsWritable(settings);
        obscura::GameApp app(std::move(settings), parser);
        return app.run();
    } catch (const obscura::replay::ScriptError& e) {
        std::cerr << "obscura: replay script error: " << e.what() << "\n";
        return 2;
    } catch (const obscura::SettingsError& e) {
        std::cerr << "obscura: " << e.what() << "\n";
        return 2;
    } catch (const Ogre::Exception& e) {
        std::cerr << "obscura: OGRE error: " << e.getFullDescription() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "obscura: " << e.what() << "\n";
        return 1;
    }
}
