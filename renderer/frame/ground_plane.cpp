#include "frame/ground_plane.h"

#include <algorithm>

namespace shadowlab {

GroundPlaneUndo addGroundPlane(Scene& scene) {
    GroundPlaneUndo undo{scene.materials.size(), scene.meshes.size(), scene.nodes.size(), scene.roots.size(),
                         scene.instances.size(), scene.bounds};
    if (scene.bounds.empty()) return undo;
    const glm::dvec3 extent = scene.bounds.extent(), centre = scene.bounds.center();
    const double half = 1.5 * std::max({extent.x, extent.z, 1e-3});
    // Just below the lowest point, so feet standing on y = min do not fight it for depth.
    const double y = scene.bounds.min.y - 1e-3 * std::max(glm::length(extent), 1e-3);

    Material ground;
    ground.name = "shadowlab ground plane";
    ground.baseColorFactor = {0.6f, 0.6f, 0.6f, 1.0f};
    ground.doubleSided = true;
    scene.materials.push_back(ground);

    Primitive quad;
    quad.material = int(scene.materials.size()) - 1;
    for (auto [sx, sz] : {std::pair{-1.0, -1.0}, {-1.0, 1.0}, {1.0, 1.0}, {1.0, -1.0}}) {
        const glm::dvec3 p{centre.x + sx * half, y, centre.z + sz * half};
        quad.positions.push_back(glm::vec3(p));
        quad.normals.push_back({0.0f, 1.0f, 0.0f});
        quad.texcoords.push_back({float(sx * 0.5 + 0.5), float(sz * 0.5 + 0.5)});
        quad.bounds.extend(p);
    }
    quad.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise seen from above
    scene.meshes.push_back({"shadowlab ground plane", {quad}});

    Node node;
    node.name = "shadowlab ground plane";
    node.mesh = int(scene.meshes.size()) - 1;
    scene.nodes.push_back(node);
    scene.roots.push_back(int(scene.nodes.size()) - 1);
    MeshInstance instance;
    instance.node = int(scene.nodes.size()) - 1;
    instance.mesh = node.mesh;
    instance.worldBounds = quad.bounds;
    scene.instances.push_back(instance);
    scene.bounds.extend(quad.bounds);
    return undo;
}

void removeGroundPlane(Scene& scene, const GroundPlaneUndo& undo) {
    scene.materials.resize(std::min(scene.materials.size(), undo.materials));
    scene.meshes.resize(std::min(scene.meshes.size(), undo.meshes));
    scene.nodes.resize(std::min(scene.nodes.size(), undo.nodes));
    scene.roots.resize(std::min(scene.roots.size(), undo.roots));
    scene.instances.resize(std::min(scene.instances.size(), undo.instances));
    scene.bounds = undo.bounds;
}

}  // namespace shadowlab
