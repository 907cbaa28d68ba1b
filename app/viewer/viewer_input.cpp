#include "viewer/viewer_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>

namespace shadowlab::app {

namespace {
constexpr int kShortcutMods = GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER;
}  // namespace

ViewerAction actionForKey(int key, int mods) {
    if (mods & kShortcutMods) return ViewerAction::None;
    switch (key) {
        case GLFW_KEY_1: return ViewerAction::SelectSsm;
        case GLFW_KEY_2: return ViewerAction::SelectSsmUnfocused;
        case GLFW_KEY_3: return ViewerAction::SelectPsm;
        case GLFW_KEY_4: return ViewerAction::SelectLispsm;
        case GLFW_KEY_SPACE: return ViewerAction::TogglePlay;
        case GLFW_KEY_F1: return ViewerAction::ToggleUi;
        case GLFW_KEY_F12: return ViewerAction::Screenshot;
        case GLFW_KEY_HOME:
        case GLFW_KEY_F: return ViewerAction::FrameScene;
        case GLFW_KEY_R: return ViewerAction::ResetCamera;
        case GLFW_KEY_EQUAL:  // '+' on US layouts is shift + '='
        case GLFW_KEY_KP_ADD: return ViewerAction::FlyFaster;
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT: return ViewerAction::FlySlower;
        case GLFW_KEY_G: return ViewerAction::ToggleWalk;
        default: return ViewerAction::None;
    }
}

bool actsWhileTyping(ViewerAction action) {
    return action == ViewerAction::ToggleUi || action == ViewerAction::Screenshot;
}

bool applyMethodAction(ViewerAction action, Settings& settings) {
    switch (action) {
        case ViewerAction::SelectSsm: settings.method = ShadowMethod::SsmFocused; return true;
        case ViewerAction::SelectSsmUnfocused: settings.method = ShadowMethod::SsmUnfocused; return true;
        case ViewerAction::SelectPsm: settings.method = ShadowMethod::Psm; return true;
        case ViewerAction::SelectLispsm: settings.method = ShadowMethod::Lispsm; return true;
        default: return false;
    }
}

namespace {
// The axis a fly key moves along, zero for other keys.
glm::dvec3 flyAxis(int key) {
    switch (key) {
        case GLFW_KEY_D: return {1, 0, 0};
        case GLFW_KEY_A: return {-1, 0, 0};
        case GLFW_KEY_E: return {0, 1, 0};
        case GLFW_KEY_Q: return {0, -1, 0};
        case GLFW_KEY_W: return {0, 0, 1};
        case GLFW_KEY_S: return {0, 0, -1};
        default: return {0, 0, 0};
    }
}
}  // namespace

void FlyKeys::onKey(int key, int action, int mods, double time) {
    if (key == GLFW_KEY_LEFT_SHIFT || key == GLFW_KEY_RIGHT_SHIFT) {
        shift_ = action != GLFW_RELEASE;
        return;
    }
    const glm::dvec3 axis = flyAxis(key);
    if (axis == glm::dvec3(0.0)) return;
    if (action == GLFW_PRESS && !held_.count(key) && !(mods & kShortcutMods)) {
        flight_ += axis * kTapSeconds;  // the tap's flight at once; a hold counts after it
        held_[key] = {time + kTapSeconds, 0};
    } else if (action == GLFW_RELEASE) {
        held_.erase(key);
    }
}

glm::dvec3 FlyKeys::takeFlight(double now) {
    for (auto& [key, hold] : held_)
        if (++hold.frames >= 2 && now > hold.counted) {
            flight_ += flyAxis(key) * (now - hold.counted);
            hold.counted = now;
        }
    return std::exchange(flight_, glm::dvec3(0.0));
}

void FlyKeys::clear() {
    held_.clear();
    flight_ = glm::dvec3(0.0);
    shift_ = false;
}

void DragTracker::onCursor(const glm::dvec2& position) {
    cursor_ = position;
    if (!pressed_) return;
    if (reanchor_) {
        reanchor_ = false;
        anchor_ = position;
        return;
    }
    const glm::dvec2 delta = position - anchor_;
    anchor_ = position;
    travel_ += glm::length(delta);
    switch (target_) {
        case DragTarget::Look: deltas_.look += delta; break;
        case DragTarget::Orbit: deltas_.orbit += delta; break;
        case DragTarget::Observer: deltas_.observer += delta; break;
        case DragTarget::None: break;
    }
}

void DragTracker::onPress(DragTarget target) {
    target_ = target;
    anchor_ = cursor_;
    reanchor_ = true;
    pressed_ = true;
    travel_ = 0.0;
}

bool DragTracker::onRelease() {
    const bool click = pressed_ && travel_ < kClickSlop;
    target_ = DragTarget::None;
    pressed_ = false;
    return click;
}

}  // namespace shadowlab::app
