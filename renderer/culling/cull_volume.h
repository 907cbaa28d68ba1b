#pragma once
// What a pass culls against, as inward half-spaces: the view frustum for the camera's passes, or
// the intersection body B (its face planes and its bounds) for a shadow pass, as casterCanReach
// (math/shadow_setup.h). Kept beside a pass's culled instance list so the draw can cull the
// clusters of large meshes (mesh_clusters.h) by the same logic one level finer. GL-free.
#include "frame/frame_setup.h"
#include "math/shadow_setup.h"

#include <vector>

namespace shadowlab {

class CullVolume {
public:
    CullVolume() = default;  // keeps everything
    static CullVolume viewFrustum(const ClipPlanes& planes);
    // Nothing when !setup.valid (casterCanReach keeps nothing then either).
    static CullVolume casterReach(const ShadowSetup& setup);

    bool keepsEverything() const { return !empty_ && planes_.empty(); }
    // The same volume in the object space of an instance with this world matrix (plane' = M^T
    // plane): testing the object-space box there is exact where the world box of the transformed
    // box would be loose for rotated instances.
    CullVolume inObjectSpace(const glm::dmat4& world) const;
    // May part of the box lie inside? Conservative (a relative tolerance keeps touching boxes) and
    // monotone (a box inside a rejected box is rejected), as InstanceBvh::query needs.
    bool mayContain(const Aabb& box) const;

private:
    std::vector<glm::dvec4> planes_;  // inside where dot(plane, (p, 1)) >= 0
    bool empty_ = false;              // contains nothing at all
};

}  // namespace shadowlab
