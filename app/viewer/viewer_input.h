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

#include <map>
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
    double time = 0.0;         // seconds (glfwGetTime) when the window system handed it over
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
    FlyFaster,    // + (also keypad): fly speed x 1.25
    FlySlower,    // -: fly speed / 1.25
    ToggleWalk,   // G: walk mode (the eye kept at its height above the ground)
};

// The binding of keys to actions (GLFW key codes). Keys that act while a text field has the
// keyboard are the function keys only.
ViewerAction actionForKey(int key, int mods);
bool actsWhileTyping(ViewerAction action);
// Settings change of a method action; false for the others.
bool applyMethodAction(ViewerAction action, Settings& settings);

// The fly keys, integrated on real elapsed time between the frames that saw them held, not on
// frame times. A press flies kTapSeconds at once; a key still down at the next frame's events has
// been held for that whole frame, so from then on each frame flies the time since the last one.
// A release flies nothing more: the camera stops with the frame that learns of it. Events are
// only seen when a frame polls them, so a release in the first poll after the press cannot be
// told from a tap of any length: it is a tap. A tap therefore moves speed x kTapSeconds at 10 fps
// as at 1 fps (it moved speed x the last frame's time: 54 m at 1.6 s a frame in the forest).
// Presses with Ctrl, Alt or Super are shortcuts (Ctrl+A), not flight.
class FlyKeys {
public:
    // The flight of one tap: at 5 m/s, 0.5 m.
    static constexpr double kTapSeconds = 0.1;
    // `time`: when the frame polled the event, on the clock later given to takeFlight.
    void onKey(int key, int action, int mods, double time);
    // Seconds flown since the last call (once per frame, after the events) along x right (D - A),
    // y up (E - Q), z forward (W - S).
    glm::dvec3 takeFlight(double now);
    bool fast() const { return shift_; }
    bool anyHeld() const { return !held_.empty(); }
    void clear();

private:
    struct Hold {
        double counted = 0.0;  // flown up to this time
        int frames = 0;        // takeFlight calls that saw the key down
    };
    std::map<int, Hold> held_;
    glm::dvec3 flight_{0.0};
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
