// See input.h.
#include "input.h"

namespace obscura {

namespace {
// Quake's m_yaw / m_pitch: 0.022 degrees per mouse count at sensitivity 1.
constexpr double kRadiansPerCount = 0.022 * 3.14159265358979323846 / 180.0;
}  // namespace

void InputState::press(const std::string& key) {
    if (!down_.insert(key).second) return;  // auto-repeat: only the first press triggers
    latched_.insert(key);
    const bool shift = isKeyDown("lshift") || isKeyDown("rshift");
    for (const auto& [action, bound] : settings_.bindings)
        if (bound == key) triggered_.push_back({action, shift});
}

void InputState::release(const std::string& key) { down_.erase(key); }

void InputState::releaseAll() {
    down_.clear();
    latched_.clear();
}

bool InputState::isDown(Action a) const {
    const auto it = settings_.bindings.find(a);
    return it != settings_.bindings.end() && (down_.count(it->second) != 0 || latched_.count(it->second) != 0);
}

std::vector<TriggeredAction> InputState::takeTriggered() {
    std::vector<TriggeredAction> t;
    t.swap(triggered_);
    return t;
}

sim::PlayerCommand InputState::takeCommand() {
    sim::PlayerCommand c;
    c.forward = static_cast<float>(isDown(Action::Forward)) - static_cast<float>(isDown(Action::Back));
    c.right = static_cast<float>(isDown(Action::Right)) - static_cast<float>(isDown(Action::Left));
    c.jump = isDown(Action::Jump);
    c.crouch = isDown(Action::Crouch);
    c.sprint = isDown(Action::Sprint);
    c.fire = isDown(Action::Fire);
    c.reload = isDown(Action::Reload);
    c.throwHeld = isDown(Action::Throw);
    const double k = kRadiansPerCount * settings_.mouseSensitivity;
    // Mouse right turns right (negative yaw about +Y); mouse down looks down unless inverted.
    c.yawDelta = static_cast<float>(-static_cast<double>(mouseDx_) * k);
    c.pitchDelta = static_cast<float>(static_cast<double>(settings_.invertMouse ? mouseDy_ : -mouseDy_) * k);
    mouseDx_ = mouseDy_ = 0;
    latched_.clear();
    return c;
}

}  // namespace obscura
