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

TEST(FlyKeys, ATapWithinOneFrameStillMovesOnce) {
    FlyKeys keys;
    keys.onKey(GLFW_KEY_W, GLFW_PRESS);
    keys.onKey(GLFW_KEY_W, GLFW_RELEASE);
    EXPECT_EQ(keys.takeMove(), glm::dvec3(0, 0, 1));
    EXPECT_EQ(keys.takeMove(), glm::dvec3(0.0));  // released: the next frame stands still
    keys.onKey(GLFW_KEY_D, GLFW_PRESS);
    keys.onKey(GLFW_KEY_LEFT_SHIFT, GLFW_PRESS);
    EXPECT_EQ(keys.takeMove(), glm::dvec3(1, 0, 0));
    EXPECT_EQ(keys.takeMove(), glm::dvec3(1, 0, 0));  // held
    EXPECT_TRUE(keys.fast());
    EXPECT_TRUE(keys.anyHeld());
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
