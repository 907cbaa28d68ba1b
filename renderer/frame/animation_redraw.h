#pragma once
// Whether a step of the scene clock changes the picture: a playing animation whose moving nodes
// are neither in the view nor able to cast a shadow into it (outside B, thesis 4.2: a caster
// outside B shadows no visible point) changes nothing on screen, so the viewer need not draw.
// GL-free: the viewer keeps the volumes of the frame it drew last and asks after each pose step.
#include "culling/cull_volume.h"
#include "math/cascades.h"
#include "scenes/scene.h"
#include "settings/settings.h"

#include <vector>

namespace shadowlab {

// What a pose step can change, kept from before the step: node world matrices and morph weights
// (a skinned mesh follows its joints' nodes) and the instance bounds.
struct PoseSnapshot {
    std::vector<glm::dmat4> nodeWorld;
    std::vector<std::vector<float>> nodeWeights;
    std::vector<Aabb> instanceBounds;
};
PoseSnapshot snapshotPose(const Scene& scene);

// The volumes of the frame drawn last: the view frustum and the caster reach (B) of each shadow
// map. `everything`: a view shows the whole scene (observer inset, split or A/B compare, or no
// frame yet), so any pose change counts.
struct WatchedVolumes {
    std::vector<CullVolume> volumes;
    bool everything = true;
};
// The frustum of `camera` at this aspect, plus the caster reach of `oneMap` (shadows from one map)
// or of every split of `cascades` (when it has splits); `shadowed` false: no shadow volume.
WatchedVolumes watchedVolumes(const CameraSettings& camera, double aspect, bool shadowed, const ShadowSetup& oneMap,
                              const CascadeSetup& cascades);

// The instances whose world matrix, bounds, morph weights or skin joints differ between `before`
// and the scene's present pose, ascending.
std::vector<std::uint32_t> movedInstances(const PoseSnapshot& before, const Scene& scene);

// Does the step from `before` to the scene's present pose change what the watched frame shows?
// True when a moved instance may lie in a watched volume before or after the step, when a node
// carrying a scene light moved, or when the scene's structure changed (another instance count).
bool animationNeedsRedraw(const PoseSnapshot& before, const Scene& scene, const WatchedVolumes& watched);

}  // namespace shadowlab
