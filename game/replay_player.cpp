// See replay_player.h.
#include "replay_player.h"

namespace obscura {

ReplayPlayer::ReplayPlayer(const replay::Script& script) : script_(script), lastTick_(script.endTick()) {}

ReplayTick ReplayPlayer::take(std::int64_t tick) {
    ReplayTick out;
    for (auto it = pending_.begin(); it != pending_.end() && it->first <= tick;) {
        out.inputs.push_back(it->second);
        it = pending_.erase(it);
    }
    // The `setting` headers: before anything of the first tick.
    if (tick == 0)
        for (const replay::Command& c : script_.settings) out.settings.push_back(&c);
    using T = replay::Command::Type;
    using A = replay::Command::Action;
    for (; next_ < script_.commands.size() && script_.commands[next_].tick <= tick; ++next_) {
        const replay::Command& c = script_.commands[next_];
        switch (c.type) {
            case T::Key:
            case T::Button: {
                const std::string key = c.type == T::Key ? c.name : replay::buttonKeyName(c.name);
                if (c.action == A::Up) {
                    out.inputs.push_back({ReplayInput::Kind::KeyUp, key, 0, 0});
                } else {
                    out.inputs.push_back({ReplayInput::Kind::KeyDown, key, 0, 0});
                    if (c.action == A::Tap) pending_.insert({tick + 1, {ReplayInput::Kind::KeyUp, key, 0, 0}});
                }
                break;
            }
            case T::Mouse: out.inputs.push_back({ReplayInput::Kind::MouseMotion, {}, c.dx, c.dy}); break;
            case T::Set: out.settings.push_back(&c); break;
            case T::Capture: out.captures.push_back(&c); break;
            case T::Hash: out.hashes.push_back(&c); break;
            case T::End: break;
        }
    }
    return out;
}

}  // namespace obscura
