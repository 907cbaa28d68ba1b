#include "frame/animation_redraw.h"

#include "frame/frame_setup.h"

namespace shadowlab {

PoseSnapshot snapshotPose(const Scene& scene) {
    PoseSnapshot s;
    s.nodeWorld.reserve(scene.nodes.size());
    s.nodeWeights.reserve(scene.nodes.size());
    for (const Node& node : scene.nodes) {
        s.nodeWorld.push_back(node.world);
        s.nodeWeights.push_back(node.weights);
    }
    s.instanceBounds.reserve(scene.instances.size());
    for (const MeshInstance& inst : scene.instances) s.instanceBounds.push_back(inst.worldBounds);
    return s;
}

WatchedVolumes watchedVolumes(const CameraSettings& camera, double aspect, bool shadowed, const ShadowSetup& oneMap,
                              const CascadeSetup& cascades) {
    WatchedVolumes w;
    w.everything = false;
    const ViewFrustum view = viewFrustum(camera, aspect);
    w.volumes.push_back(CullVolume::viewFrustum(clipPlanes(view.projectionMatrix() * view.viewMatrix())));
    if (!shadowed) return w;
    if (cascades.splits.empty()) w.volumes.push_back(CullVolume::casterReach(oneMap));
    for (const CascadeSplit& split : cascades.splits) w.volumes.push_back(CullVolume::casterReach(split.setup));
    return w;
}

namespace {

bool nodeMoved(const PoseSnapshot& before, const Scene& scene, int node) {
    if (node < 0 || std::size_t(node) >= scene.nodes.size()) return false;
    const std::size_t n = std::size_t(node);
    return before.nodeWorld[n] != scene.nodes[n].world || before.nodeWeights[n] != scene.nodes[n].weights;
}

bool instanceMoved(const PoseSnapshot& before, const Scene& scene, std::size_t i) {
    const MeshInstance& inst = scene.instances[i];
    const Aabb& was = before.instanceBounds[i];
    if (was.min != inst.worldBounds.min || was.max != inst.worldBounds.max) return true;
    if (nodeMoved(before, scene, inst.node)) return true;
    if (inst.node < 0 || std::size_t(inst.node) >= scene.nodes.size()) return false;
    // A skinned mesh deforms when one of its joints moves, whatever its own node does.
    const int skin = scene.nodes[std::size_t(inst.node)].skin;
    if (skin < 0 || std::size_t(skin) >= scene.skins.size()) return false;
    for (int joint : scene.skins[std::size_t(skin)].joints)
        if (nodeMoved(before, scene, joint)) return true;
    return false;
}

}  // namespace

std::vector<std::uint32_t> movedInstances(const PoseSnapshot& before, const Scene& scene) {
    std::vector<std::uint32_t> moved;
    if (before.instanceBounds.size() != scene.instances.size() || before.nodeWorld.size() != scene.nodes.size()) {
        for (std::size_t i = 0; i < scene.instances.size(); ++i) moved.push_back(std::uint32_t(i));
        return moved;
    }
    for (std::size_t i = 0; i < scene.instances.size(); ++i)
        if (instanceMoved(before, scene, i)) moved.push_back(std::uint32_t(i));
    return moved;
}

bool animationNeedsRedraw(const PoseSnapshot& before, const Scene& scene, const WatchedVolumes& watched) {
    if (before.instanceBounds.size() != scene.instances.size() || before.nodeWorld.size() != scene.nodes.size())
        return true;
    // A moving light changes the shading and every shadow.
    for (const Light& light : scene.lights)
        if (nodeMoved(before, scene, light.node)) return true;
    const std::vector<std::uint32_t> moved = movedInstances(before, scene);
    if (moved.empty()) return false;
    if (watched.everything) return true;
    for (std::uint32_t i : moved) {
        // The box before the step (what the picture shows now) and after it (what it would show).
        for (const Aabb* box : {&before.instanceBounds[i], &scene.instances[i].worldBounds}) {
            if (box->empty()) continue;
            for (const CullVolume& volume : watched.volumes)
                if (volume.mayContain(*box)) return true;
        }
    }
    return false;
}

}  // namespace shadowlab
