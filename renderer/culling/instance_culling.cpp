#include "culling/instance_culling.h"

namespace shadowlab {

namespace {

void collectBoxes(const Scene& scene, std::vector<Aabb>& boxes) {
    boxes.resize(scene.instances.size());
    for (std::size_t i = 0; i < scene.instances.size(); ++i) boxes[i] = scene.instances[i].worldBounds;
}

template <class BoxTest>
void linearCull(const Scene& scene, BoxTest&& test, InstanceList& out) {
    for (std::size_t i = 0; i < scene.instances.size(); ++i)
        if (test(scene.instances[i].worldBounds)) out.push_back(std::uint32_t(i));
}

}  // namespace

void InstanceCuller::setScene(const Scene& scene) {
    collectBoxes(scene, boxes_);
    bvh_.build(boxes_);
}

void InstanceCuller::updateInstances(const Scene& scene) {
    collectBoxes(scene, boxes_);
    bvh_.refit(boxes_);
}

void InstanceCuller::visible(const Scene& scene, const ClipPlanes& planes, bool hierarchical, InstanceList& out) const {
    out.clear();
    out.volume = CullVolume::viewFrustum(planes);
    auto test = [&](const Aabb& box) { return boxMayBeVisible(planes, box); };
    if (hierarchical && bvh_.instanceCount() == scene.instances.size()) bvh_.query(test, out);
    else linearCull(scene, test, out);
}

void InstanceCuller::casters(const Scene& scene, const ShadowSetup& setup, bool hierarchical, InstanceList& out) const {
    out.clear();
    out.volume = CullVolume::casterReach(setup);
    if (!setup.valid) return;
    auto test = [&](const Aabb& box) { return casterCanReach(setup, box); };
    if (hierarchical && bvh_.instanceCount() == scene.instances.size()) bvh_.query(test, out);
    else linearCull(scene, test, out);
}

}  // namespace shadowlab
