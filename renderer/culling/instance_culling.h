#pragma once
// Which instances a pass draws: view-frustum culling for the camera's passes and caster culling
// against the intersection body B for the shadow pass (thesis 4.2, 9.2.2), either through the
// instance BVH or by the linear loop over every instance (skip.hierarchicalCulling = false).
// Both give the same ascending index lists. GL-free.
#include "culling/cull_volume.h"
#include "culling/instance_bvh.h"
#include "frame/frame_setup.h"

#include <cstdint>
#include <vector>

namespace shadowlab {

// Indices into Scene::instances, ascending, and the volume they were culled against (what the
// draw culls clustered meshes' clusters against; everything for a list built by hand).
struct InstanceList : std::vector<std::uint32_t> {
    using std::vector<std::uint32_t>::vector;
    CullVolume volume;
};

class InstanceCuller {
public:
    // Builds the hierarchy over the scene's instance bounds.
    void setScene(const Scene& scene);
    // After animation moved instances: refits the hierarchy (cost linear in the instances).
    void updateInstances(const Scene& scene);

    void visible(const Scene& scene, const ClipPlanes& planes, bool hierarchical, InstanceList& out) const;
    void casters(const Scene& scene, const ShadowSetup& setup, bool hierarchical, InstanceList& out) const;

    const InstanceBvh& hierarchy() const { return bvh_; }

private:
    InstanceBvh bvh_;
    std::vector<Aabb> boxes_;  // scratch for build / refit
};

}  // namespace shadowlab
