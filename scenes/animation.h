#pragma once
// glTF animation sampling (glTF 2.0 spec, "Animations"; the papers' dynamic scenes): channels
// animate a node's translation, rotation, scale or morph weights with LINEAR (quaternion slerp for rotations),
// STEP or CUBICSPLINE (Hermite with in/out tangents) interpolation. GL-free: the sampler writes
// Node TRS, updateWorldTransforms (loader) then refreshes world matrices, instances and bounds.
#include "scenes/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace shadowlab {

// The channel's value at time `t` (seconds, in the animation's own time line). Before the first
// key the first value holds, after the last key the last value (the spec's clamping). xyz for
// translation/scale, a unit quaternion (x, y, z, w) for rotation. A channel with no keys, or with
// fewer values than its interpolation needs, returns nullopt-like `valid = false`.
struct ChannelSample {
    bool valid = false;
    glm::vec4 value{0.0f};
};
ChannelSample sampleChannel(const AnimationChannel& channel, double t);
// A "weights" channel (morph target weights, glTF 2.0 spec "Animations"): every target's weight at
// `t`, interpolated per component (LINEAR is a plain lerp). False when the channel is unusable.
bool sampleWeights(const AnimationChannel& channel, double t, std::vector<float>& weights);

// Length of an animation: its last key time over all channels (Animation::duration when larger).
double animationDuration(const Animation& animation);
// Which of the scene's animations play (settings key animation.clip): kAllClips plays every one
// at once, each looped over its own length; an index plays that one alone. An index past the last
// animation plays the first (sceneNotices says so).
constexpr int kAllClips = -1;
// The animation index `clip` selects in this scene: kAllClips, or a valid index.
int resolveClip(const Scene& scene, int clip);

// Longest animation of the scene (of the chosen clip); 0 when it has none.
double sceneAnimationDuration(const Scene& scene, int clip = kAllClips);

// The time inside one loop of a `duration` long animation played since 0 (t mod duration,
// non-negative); 0 for a zero duration.
double loopTime(double t, double duration);

// Writes every channel of the chosen animations at scene time `t` (each animation looped over its
// own duration) into the nodes' translation/rotation/scale and morph weights. Channels that target a
// missing node or a node given by a matrix (the spec forbids animating those) are skipped. Returns
// the number of channels applied. Does not update world matrices: see animateScene.
int applyAnimations(Scene& scene, double t, int clip = kAllClips);

// The nodes' local transforms and morph weights as loaded: a node that the next clip does not
// animate must go back to them rather than keep the last clip's pose.
struct RestPose {
    std::vector<glm::vec3> translation, scale;
    std::vector<glm::quat> rotation;
    std::vector<std::vector<float>> weights;
};
RestPose captureRestPose(const Scene& scene);
// Puts the captured values back (no world matrices: animateScene follows) into the nodes captured;
// nodes added since (the ground plane's) are left alone.
void restorePose(Scene& scene, const RestPose& rest);

// applyAnimations + updateWorldTransforms (world matrices, instances, lights, cameras, bounds).
// Returns false (scene untouched) when the scene has no animation.
bool animateScene(Scene& scene, double t, int clip = kAllClips);

}  // namespace shadowlab
