// The viewer's event-driven input (GLFW-free): a key tap shorter than a frame is still a press in
// the queue, drags are measured from the press position, fly keys count taps.
#include "viewer/viewer_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <gtest/gtest.h>

namespace shadowlab::app {
namespace {

InputEvent key(int code, int action, int mods = 0) {
    InputEvent e;
    e.kind = InputKind::Key;
    e.code = code;
    e.action = action;
    e.mods = mods;
    return e;
}

// What the viewer does with one frame's events: the actions of the key presses, in order.
std::vector<ViewerAction> pressActions(const std::vector<InputEvent>& events) {
    std::vector<ViewerAction> actions;
    for (const InputEvent& e : events)
        if (e.kind == InputKind::Key && e.action == GLFW_PRESS) actions.push_back(actionForKey(e.code, e.mods));
    return actions;
}

TEST(InputQueue, TapsShorterThanAFrameAreAllDeliveredInOrder) {
    // At 3-5 fps six taps can fall into one frame: press and release both arrive before the frame
    // looks. Polling the key state would see six released keys; the queue keeps every press.
    InputQueue queue;
    for (int code : {GLFW_KEY_3, GLFW_KEY_SPACE, GLFW_KEY_1, GLFW_KEY_4, GLFW_KEY_F1, GLFW_KEY_F12}) {
        queue.push(key(code, GLFW_PRESS));
        queue.push(key(code, GLFW_RELEASE));
    }
    const std::vector<ViewerAction> actions = pressActions(queue.drain());
    const std::vector<ViewerAction> expected{ViewerAction::SelectPsm,    ViewerAction::TogglePlay,
                                             ViewerAction::SelectSsm,    ViewerAction::SelectLispsm,
                                             ViewerAction::ToggleUi,     ViewerAction::Screenshot};
    EXPECT_EQ(actions, expected);
    EXPECT_TRUE(queue.empty());  // drained: the next frame does not repeat them
    EXPECT_TRUE(queue.drain().empty());
}

TEST(InputQueue, MethodKeysSetTheMethodAndModifiersDisableThem) {
    Settings s;
    s.method = ShadowMethod::Lispsm;
    EXPECT_TRUE(applyMethodAction(actionForKey(GLFW_KEY_3, 0), s));
    EXPECT_EQ(s.method, ShadowMethod::Psm);
    EXPECT_TRUE(applyMethodAction(actionForKey(GLFW_KEY_2, 0), s));
    EXPECT_EQ(s.method, ShadowMethod::SsmUnfocused);
    EXPECT_FALSE(applyMethodAction(actionForKey(GLFW_KEY_SPACE, 0), s));
    EXPECT_EQ(actionForKey(GLFW_KEY_3, GLFW_MOD_CONTROL), ViewerAction::None);
    EXPECT_EQ(actionForKey(GLFW_KEY_HOME, 0), ViewerAction::FrameScene);
    EXPECT_EQ(actionForKey(GLFW_KEY_F, 0), ViewerAction::FrameScene);
    EXPECT_EQ(actionForKey(GLFW_KEY_R, 0), ViewerAction::ResetCamera);
    EXPECT_TRUE(actsWhileTyping(ViewerAction::ToggleUi));
    EXPECT_FALSE(actsWhileTyping(ViewerAction::SelectPsm));
}

// The forward flight of a W tap pressed at a frame's poll and released `tapSeconds` later, with
// frames `frameSeconds` apart: the viewer sees events only when a frame polls them.
double tapFlight(double frameSeconds, double tapSeconds) {
    FlyKeys keys;
    const double press = 10.0, release = press + tapSeconds;
    keys.onKey(GLFW_KEY_W, GLFW_PRESS, 0, press);
    double flown = keys.takeFlight(press).z;
    for (double t = press + frameSeconds; t < press + 8.0; t += frameSeconds) {
        if (t >= release && keys.anyHeld()) keys.onKey(GLFW_KEY_W, GLFW_RELEASE, 0, t);
        flown += keys.takeFlight(t).z;
    }
    return flown;
}

TEST(FlyKeys, ATapFliesTheSameAt10FpsAsAt1Fps) {
    // A 60 ms tap whose release reaches the next frame: flown for a whole frame before (speed x
    // 1.6 s at overlay frame times).
    const double at10 = tapFlight(0.1, 0.06), at1 = tapFlight(1.0, 0.06);
    EXPECT_NEAR(at10, FlyKeys::kTapSeconds, 0.1 * FlyKeys::kTapSeconds);
    EXPECT_NEAR(at1, at10, 0.1 * at10);
    // Press and release within one poll: exactly one tap.
    FlyKeys keys;
    keys.onKey(GLFW_KEY_W, GLFW_PRESS, 0, 5.0);
    keys.onKey(GLFW_KEY_W, GLFW_RELEASE, 0, 5.0);
    EXPECT_EQ(keys.takeFlight(5.0), glm::dvec3(0, 0, FlyKeys::kTapSeconds));
    EXPECT_EQ(keys.takeFlight(9.0), glm::dvec3(0.0));  // released: nothing flies on
}

TEST(FlyKeys, AHeldKeyFliesWhileHeldAndStopsWithTheFrameThatSeesTheRelease) {
    // Held 3 s: about 3 s of flight whether frames take 0.1 s or 1 s, never more than held.
    const double at10 = tapFlight(0.1, 3.0), at1 = tapFlight(1.0, 3.0);
    EXPECT_GT(at10, 2.8);
    EXPECT_LE(at10, 3.0 + 1e-9);
    EXPECT_GT(at1, 1.9);  // at most one frame short: the release lands somewhere in the last frame
    EXPECT_LE(at1, 3.0 + 1e-9);
    FlyKeys keys;
    keys.onKey(GLFW_KEY_D, GLFW_PRESS, 0, 1.0);
    keys.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_PRESS, 0, 1.0);
    EXPECT_TRUE(keys.anyHeld());
    EXPECT_TRUE(keys.fast());
    EXPECT_NEAR(keys.takeFlight(1.0).x, FlyKeys::kTapSeconds, 1e-12);
    // Slow frames (1.6 s): each frame that sees the key still down flies the time since the last.
    EXPECT_NEAR(keys.takeFlight(2.6).x, 1.5, 1e-12);
    keys.onKey(GLFW_KEY_D, GLFW_RELEASE, 0, 4.2);
    EXPECT_EQ(keys.takeFlight(4.2), glm::dvec3(0.0));
    EXPECT_FALSE(keys.anyHeld());
}

TEST(FlyKeys, ShortcutsWithCtrlDoNotFly) {
    FlyKeys keys;
    keys.onKey(GLFW_KEY_A, GLFW_PRESS, GLFW_MOD_CONTROL, 1.0);  // Ctrl+A: select all, not "fly left"
    keys.onKey(GLFW_KEY_A, GLFW_RELEASE, GLFW_MOD_CONTROL, 1.5);
    EXPECT_EQ(keys.takeFlight(2.0), glm::dvec3(0.0));
    EXPECT_FALSE(keys.anyHeld());
    EXPECT_EQ(actionForKey(GLFW_KEY_EQUAL, GLFW_MOD_SHIFT), ViewerAction::FlyFaster);  // '+'
    EXPECT_EQ(actionForKey(GLFW_KEY_KP_SUBTRACT, 0), ViewerAction::FlySlower);
    EXPECT_EQ(actionForKey(GLFW_KEY_G, 0), ViewerAction::ToggleWalk);
}

TEST(DragTracker, AClickAfterEnteringTheWindowDoesNotMoveTheView) {
    DragTracker drag;
    drag.onCursor({5.0, 5.0});  // last seen near the edge
    // The cursor re-enters far away; the first report comes with the press.
    drag.onPress(DragTarget::Look);
    drag.onCursor({600.0, 300.0});
    EXPECT_EQ(drag.takeDeltas().look, glm::dvec2(0.0));
    drag.onCursor({610.0, 296.0});
    drag.onCursor({615.0, 290.0});
    EXPECT_EQ(drag.takeDeltas().look, glm::dvec2(15.0, -10.0));
    EXPECT_EQ(drag.takeDeltas().look, glm::dvec2(0.0));
    EXPECT_EQ(drag.target(), DragTarget::Look);
    drag.onRelease();
    drag.onCursor({700.0, 300.0});  // moving without a button drags nothing
    const DragDeltas none = drag.takeDeltas();
    EXPECT_EQ(none.look + none.orbit + none.observer, glm::dvec2(0.0));
    EXPECT_EQ(drag.target(), DragTarget::None);
    EXPECT_EQ(drag.cursor(), glm::dvec2(700.0, 300.0));
}

TEST(DragTracker, AWholeDragWithinOneFrameIsKeptForThatFrame) {
    DragTracker drag;
    drag.onCursor({100.0, 100.0});
    drag.onPress(DragTarget::Orbit);
    drag.onCursor({100.0, 100.0});
    drag.onCursor({130.0, 90.0});
    drag.onRelease();
    const DragDeltas d = drag.takeDeltas();
    EXPECT_EQ(d.orbit, glm::dvec2(30.0, -10.0));
    EXPECT_EQ(d.look, glm::dvec2(0.0));
}

TEST(DragTracker, AReleaseIsAClickOnlyWhenTheCursorStayedPut) {
    DragTracker drag;
    drag.onCursor({200.0, 200.0});
    drag.onPress(DragTarget::Observer);
    drag.onCursor({200.0, 200.0});  // the re-anchoring report
    drag.onCursor({201.0, 202.0});  // hand jitter: under the slop
    EXPECT_TRUE(drag.onRelease());

    drag.onPress(DragTarget::Observer);
    drag.onCursor({201.0, 202.0});
    drag.onCursor({230.0, 202.0});  // a drag that turns the observer
    drag.onCursor({201.0, 202.0});  // and back: the path counts, not the end point
    EXPECT_FALSE(drag.onRelease());
    EXPECT_FALSE(drag.onRelease());  // a release without a press is no click

    drag.onPress(DragTarget::None);  // over a panel: still a click (the viewer decides what is under it)
    EXPECT_TRUE(drag.onRelease());
}

}  // namespace
}  // namespace shadowlab::app
