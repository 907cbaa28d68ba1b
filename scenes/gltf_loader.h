#pragma once
// glTF 2.0 (.gltf with external or data-URI resources, .glb) into the project's scene model.
// tinygltf parses; everything it does not check (accessor ranges, sparse substitution, index
// ranges, non-finite numbers, required extensions, node cycles) is validated here before use.
#include "scenes/scene.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

struct LoadResult {
    std::optional<Scene> scene;         // empty on failure: never a half-loaded scene
    std::string error;                  // "<file>: <reason>" when scene is empty
    std::vector<std::string> warnings;  // also kept in Scene::warnings
    bool ok() const { return scene.has_value(); }
};

// Loads a .gltf or .glb (the container is told by the file's magic, not its name).
// Never throws and never crashes on bad input; adds the default sun / framing camera.
LoadResult loadScene(const std::filesystem::path& file);

// Adds a default sun (directional, from above and slightly sideways, "Default Sun",
// Scene::defaultLight) when the scene has no light, and a framing perspective camera
// (yfov 60 degrees, looking at the bounds from a diagonal, near/far from the bounds,
// Scene::defaultCamera) when it has no camera. Needs up-to-date bounds (updateWorldTransforms).
void addDefaultsIfMissing(Scene& scene);

// Recomputes Node::world from the local TRS/matrix down from the roots, rebuilds the mesh
// instances (world matrix, world bounds, mirroring) of the nodes reachable from the roots,
// places the node lights and cameras, and recomputes Scene::bounds. Animation calls it per frame.
// A scene without roots treats every parentless node as a root.
void updateWorldTransforms(Scene& scene);

// Local transform of a node: its matrix, or T * R * S.
glm::dmat4 localTransform(const Node& node);

// The multi-line text `shadowlab info` prints.
std::string describeScene(const Scene& scene);

}  // namespace shadowlab
