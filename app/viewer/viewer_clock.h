#pragma once
// The viewer's scene clock: glTF animations and the animated sun advance with the frame time, and a
// playing animation whose moving nodes are neither seen nor able to shadow what is seen is stepped
// on the CPU only (frame/animation_redraw.h): the window then waits instead of drawing.
#include "viewer/viewer_state.h"

namespace shadowlab {
class Renderer;
}

namespace shadowlab::app {

// How often a playing animation off screen is posed to see whether it comes into view (or into
// B): the longest a node entering the view is drawn late. A pose costs microseconds (CesiumMan's
// 19 joints: 3.9 us, docs/animation.md), so 30 wake-ups a second stay far below 1% of a core.
constexpr double kOffscreenAnimationPollSeconds = 1.0 / 30.0;

// Something on screen changes without input: the animation plays (or the sun moves).
bool animating(const ViewerState& state);

// Advances the clock by `dt` seconds of frame time and poses the scene; with `upload`, the
// renderer gets the new instance matrices (also those of poses stepped off screen since the last
// upload). A clock that moves nothing stands still, so an idle window stays idle.
void advanceClock(ViewerState& state, Renderer& renderer, double dt, bool upload = true);

// Advances the clock by `dt` and poses the scene on the CPU only. True when the step changes what
// the last drawn frame shows (a moved node may lie in its view or its B, a scene light moved, the
// sun moves): then draw, and advanceClock(state, renderer, 0) uploads the pose.
bool stepClockShows(ViewerState& state, double dt);

// After a drawn frame: the volumes the next pose steps are checked against (the view's frustum
// and B; everything when a second view, the observer or the light-view inset shows the scene).
void watchFrame(ViewerState& state, const Settings& shown, int panes, double aspect, const Renderer& renderer);

}  // namespace shadowlab::app
