#pragma once
// Generated glTF test worlds (scenes/README.md describes each): deterministic, Blender-free,
// written as .glb through tinygltf. The same name, seed and scale give a byte-identical file.
#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace shadowlab::scenegen {

struct GenerateOptions {
    std::uint64_t seed = 1;
    // Amount of content: object count and ground area grow with it at constant density
    // (forest, cubes, street). Scenes with a fixed layout (plane-box, chessboard) accept only 1.
    double scale = 1.0;
    // Wrap the scene in a closed, textured, single-sided sky box facing inwards (node "SkyBox"),
    // large enough to enclose everything drawn, every camera and every positioned light.
    bool skyBox = false;
};

// What the written file contains, counted by the generator while building it.
struct SceneStats {
    std::size_t nodes = 0;          // all glTF nodes (mesh, group, camera and light nodes)
    std::size_t meshInstances = 0;  // nodes that draw a mesh
    std::size_t meshes = 0;
    std::size_t materials = 0;
    std::size_t cameras = 0;
    std::size_t lights = 0;
    std::size_t triangles = 0;  // drawn: each mesh's triangles once per node that draws it
    std::size_t vertices = 0;   // stored (each mesh once)
    glm::dvec3 boundsMin{0.0};  // world-space bounds of all drawn vertices
    glm::dvec3 boundsMax{0.0};
    std::uintmax_t fileBytes = 0;
};

struct GenerateResult {
    bool ok = false;
    std::string error;  // set when !ok: unknown name, bad option, write failure
    SceneStats stats;
};

struct GeneratorInfo {
    std::string name;
    std::string summary;  // one line: what the scene stresses
    bool scalable = true;
};

// The generators, in a fixed order: forest, cubes, chessboard, street, plane-box, interior.
const std::vector<GeneratorInfo>& generators();
std::vector<std::string> generatorNames();
// "forest, cubes, chessboard, street, plane-box, interior" for messages.
std::string generatorNameList();

// Builds scene `name` and writes it as binary glTF (.glb, one embedded buffer) to `out`
// (parent folders are created). Never throws; problems come back in GenerateResult::error.
GenerateResult generateScene(const std::string& name, const GenerateOptions& options, const std::filesystem::path& out);

}  // namespace shadowlab::scenegen
