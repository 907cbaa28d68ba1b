#pragma once
// The viewer's input as events, not as state polled once per frame (GLFW-free, testable).
//
// At 3-5 fps a key tap shorter than a frame would be lost to polling: the press and the release both
// arrive in one glfwPollEvents(), and polling the key state afterwards sees it released. Here the
// GLFW callbacks push every event into an InputQueue; each frame drains it in order, so a tap is a
// press event whatever the frame rate. Drags are measured from where the button went down, never
// from the cursor position of the previous frame (else a click after entering the window would swing
// the view by the distance the cursor travelled outside it).
#include "settings/settings.h"

#include <glm/glm.hpp>

#include <set>
#include <utility>
#include <vector>

namespace shadowlab::app {

enum class InputKind { Key, MouseButton, CursorMove, Scroll };

struct InputEvent {
    InputKind kind = InputKind::Key;
    int code = 0;        // GLFW key or mouse button
    int action = 0;      // GLFW_PRESS (1), GLFW_RELEASE (0), GLFW_REPEAT (2)
    int mods = 0;        // GLFW_MOD_* bits
    glm::dvec2 position{0.0};  // CursorMove: window coordinates
    double scroll = 0.0;       // Scroll: wheel notches (y)
};

// Filled by the window callbacks, drained once per frame (single-threaded: GLFW calls back from
// glfwPollEvents / glfwWaitEvents on the main thread).
class InputQueue {
public:
    void push(const InputEvent& event) { events_.push_back(event); }
    std::vector<InputEvent> drain() { return std::exchange(events_, {}); }
    bool empty() const { return events_.empty(); }

private:
    std::vector<InputEvent> events_;
};

// What a key press does in the viewer.
enum class ViewerAction {
    None,
    SelectSsm,
    SelectSsmUnfocused,
    SelectPsm,
    SelectLispsm,
    TogglePlay,
    ToggleUi,
    Screenshot,
    FrameScene,   // Home / F: fit the scene bounds into the view
    ResetCamera,  // R: back to the scene's first camera
};

// The binding of keys to actions (GLFW key codes). Keys that act while a text field has the
// keyboard are the function keys only.
ViewerAction actionForKey(int key, int mods);
bool actsWhileTyping(ViewerAction action);
// Settings change of a method action; false for the others.
bool applyMethodAction(ViewerAction action, Settings& settings);

// Which fly keys are down. A key pressed and released within one frame still counts as held for
// that frame, so a short tap moves a little instead of nothing.
class FlyKeys {
public:
    void onKey(int key, int action);
    // x right (D - A), y up (E - Q), z forward (W - S); then forgets the taps.
    glm::dvec3 takeMove();
    bool fast() const { return shift_; }
    bool anyHeld() const { return !held_.empty(); }
    void clear();

private:
    std::set<int> held_, tapped_;
    bool shift_ = false;
};

// What a drag moves, chosen when the button goes down.
enum class DragTarget { None, Look, Orbit, Observer };

// Movement per drag target since the last frame, window coordinates.
struct DragDeltas {
    glm::dvec2 look{0.0}, orbit{0.0}, observer{0.0};
};

// Accumulates drag deltas from cursor events, measured from the press position. The first cursor
// event after a press only re-anchors (the press itself may carry a stale position: GLFW reports
// the cursor where it left the window). A whole drag within one frame (press, moves, release) is
// kept until the frame takes it.
class DragTracker {
public:
    void onCursor(const glm::dvec2& position);
    void onPress(DragTarget target);
    // True when the press was a click: the cursor moved less than kClickSlop pixels in all between
    // press and release (the click that enlarges an inset, not a drag that turns the observer).
    bool onRelease();
    static constexpr double kClickSlop = 4.0;
    DragTarget target() const { return target_; }
    const glm::dvec2& cursor() const { return cursor_; }
    // The movement since the last call.
    DragDeltas takeDeltas() { return std::exchange(deltas_, {}); }

private:
    glm::dvec2 cursor_{0.0};
    glm::dvec2 anchor_{0.0};
    DragDeltas deltas_;
    DragTarget target_ = DragTarget::None;
    bool reanchor_ = false;
    bool pressed_ = false;  // a button is down (also with DragTarget::None: over a panel)
    double travel_ = 0.0;   // cursor path length since the press
};

}  // namespace shadowlab::app
