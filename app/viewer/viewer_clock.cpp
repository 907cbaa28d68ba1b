#include "viewer/viewer_clock.h"

#include "renderer.h"
#include "scenes/animation.h"

#include <algorithm>
#include <utility>

namespace shadowlab::app {

namespace {

bool sunMoves(const Settings& s) { return s.light.animateSun && s.light.source == LightSource::Sun; }

// The scene at the clock's time and clip; another clip starts from the rest pose (a node it does
// not animate must not keep the last clip's pose).
void poseScene(ViewerState& state) {
    const AnimationSettings& a = state.settings.animation;
    if (a.time == state.posedTime && a.clip == state.posedClip) return;
    if (a.clip != state.posedClip) restorePose(*state.scene, state.restPose);
    if (animateScene(*state.scene, a.time, a.clip)) state.poseUploadPending = true;
    state.posedTime = a.time;
    state.posedClip = a.clip;
}

}  // namespace

bool animating(const ViewerState& state) {
    const Settings& s = state.settings;
    if (!state.scene || !s.animation.playing) return false;
    return !state.scene->animations.empty() || sunMoves(s);
}

void advanceClock(ViewerState& state, Renderer& renderer, double dt, bool upload) {
    Settings& s = state.settings;
    if (animating(state)) s.animation.time = std::max(0.0, s.animation.time + dt * s.animation.speed);
    poseScene(state);
    // Moving casters: new instance matrices (the renderer compares them with what it has).
    if (upload && std::exchange(state.poseUploadPending, false)) renderer.updateInstances(*state.scene);
}

bool stepClockShows(ViewerState& state, double dt) {
    Settings& s = state.settings;
    s.animation.time = std::max(0.0, s.animation.time + dt * s.animation.speed);
    if (sunMoves(s)) return true;
    if (s.animation.time == state.posedTime && s.animation.clip == state.posedClip) return false;
    const PoseSnapshot before = snapshotPose(*state.scene);
    poseScene(state);
    return animationNeedsRedraw(before, *state.scene, state.watched);
}

void watchFrame(ViewerState& state, const Settings& shown, int panes, double aspect, const Renderer& renderer) {
    const OverlaySettings& o = shown.overlays;
    if (panes != 1 || state.ab.active || o.observerInset || o.lightViewInset) {
        state.watched = WatchedVolumes{};
        return;
    }
    state.watched = watchedVolumes(shown.camera, aspect, shown.shadows, renderer.lastShadowSetup(),
                                   renderer.lastCascadeSetup());
}

}  // namespace shadowlab::app
