// See game_app.h: the window's keys and mouse into the game's input (and the recording), the
// menu's and the debug panel's ImGui when they are open; a replay's inputs as real SDL events.
#include "app/game_app.h"

#include "app/pause_menu.h"
#include "app/sdl_keys.h"
#include "replay/replay_recorder.h"
#include "session.h"

#include <OgreImGuiInputListener.h>
#include <SDL2/SDL.h>

namespace obscura {

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

// One path for every key and mouse button: the input state, and the recording when there is one.
void GameApp::onButton(const std::string& name, bool down) {
    if (name.empty()) return;
    if (routing().keysToUi()) {
        // A binding waiting for its key takes it; otherwise only the menu key (to close) gets through.
        if (down && menu_->offerKey(name)) return;
        const auto menuKey = settings_.bindings.find(Action::Menu);
        if (menuKey == settings_.bindings.end() || menuKey->second != name) return;
    }
    if (down) input_.press(name);
    else input_.release(name);
    if (!recorder_) return;
    const auto tick = static_cast<std::int64_t>(session_->tick());
    if (down) recorder_->keyDown(tick, name);
    else recorder_->keyUp(tick, name);
}

bool GameApp::keyPressed(const OgreBites::KeyboardEvent& evt) {
    if (routing().keysToUi()) imguiInput_->keyPressed(evt);
    if (!evt.repeat) onButton(keyNameFromKeycode(evt.keysym.sym), true);
    return true;
}

bool GameApp::keyReleased(const OgreBites::KeyboardEvent& evt) {
    if (routing().keysToUi()) imguiInput_->keyReleased(evt);
    onButton(keyNameFromKeycode(evt.keysym.sym), false);
    return true;
}

bool GameApp::mouseMoved(const OgreBites::MouseMotionEvent& evt) {
    if (routing().mouseToUi()) return imguiInput_->mouseMoved(evt);  // the menu's or the panel's pointer
    if (mouseGrabbed_ || settings_.headless) {
        input_.mouseMotion(evt.xrel, evt.yrel);
        if (recorder_) recorder_->mouse(static_cast<std::int64_t>(session_->tick()), evt.xrel, evt.yrel);
    }
    return true;
}

bool GameApp::mousePressed(const OgreBites::MouseButtonEvent& evt) {
    const std::string name = keyNameFromMouseButton(evt.button);
    if (routing().mouseToUi()) {
        // A menu binding waiting for its key may take a button; else the click is the UI's, never a shot.
        if (!(routing().keysToUi() && menu_->offerKey(name))) {
            imguiInput_->mousePressed(evt);
            uiPressedUnseen_.insert(evt.button);
        }
        return true;
    }
    onButton(name, true);
    return true;
}

bool GameApp::mouseReleased(const OgreBites::MouseButtonEvent& evt) {
    // ImGui 1.86 reads the buttons' state once a frame: a click whose press and release arrive
    // between two frames would never be seen down. Its release waits for the next frame.
    if (uiPressedUnseen_.count(evt.button)) uiReleasesDue_.push_back(evt);
    else if (routing().mouseToUi()) imguiInput_->mouseReleased(evt);
    onButton(keyNameFromMouseButton(evt.button), false);  // a button held before the UI opened lets go
    return true;
}

void GameApp::afterUiFrame() {
    uiPressedUnseen_.clear();  // the frame just built saw them down
    for (const auto& evt : uiReleasesDue_) imguiInput_->mouseReleased(evt);
    uiReleasesDue_.clear();
}

bool GameApp::mouseWheelRolled(const OgreBites::MouseWheelEvent& evt) {
    if (routing().mouseToUi()) imguiInput_->mouseWheelRolled(evt);
    return true;
}

}  // namespace obscura
