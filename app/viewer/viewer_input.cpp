#include "viewer/viewer_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace shadowlab::app {

ViewerAction actionForKey(int key, int mods) {
    if (mods & (GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER)) return ViewerAction::None;
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
bool isFlyKey(int key) {
    switch (key) {
        case GLFW_KEY_W: case GLFW_KEY_A: case GLFW_KEY_S: case GLFW_KEY_D: case GLFW_KEY_Q: case GLFW_KEY_E:
            return true;
        default:
            return false;
    }
}
}  // namespace

void FlyKeys::onKey(int key, int action) {
    if (key == GLFW_KEY_LEFT_SHIFT || key == GLFW_KEY_RIGHT_SHIFT) {
        shift_ = action != GLFW_RELEASE;
        return;
    }
    if (!isFlyKey(key)) return;
    if (action == GLFW_PRESS) {
        held_.insert(key);
        tapped_.insert(key);
    } else if (action == GLFW_RELEASE) {
        held_.erase(key);
    }
}

glm::dvec3 FlyKeys::takeMove() {
    auto down = [&](int k) { return held_.count(k) || tapped_.count(k) ? 1.0 : 0.0; };
    const glm::dvec3 move{down(GLFW_KEY_D) - down(GLFW_KEY_A), down(GLFW_KEY_E) - down(GLFW_KEY_Q),
                          down(GLFW_KEY_W) - down(GLFW_KEY_S)};
    tapped_.clear();
    return move;
}

void FlyKeys::clear() {
    held_.clear();
    tapped_.clear();
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
