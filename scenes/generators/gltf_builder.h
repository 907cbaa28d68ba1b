#pragma once
// Assembles a tinygltf::Model for the generators: one binary buffer, named meshes, materials,
// nodes, cameras and KHR_lights_punctual lights, and counts what it built (SceneStats).
#include "geometry.h"
#include "scene_generators.h"

#include <tiny_gltf.h>

#include <glm/gtc/quaternion.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace shadowlab::scenegen {

// Rotation taking the glTF camera/light forward axis (-Z) to `direction`, keeping +Y as close
// to `up` as possible; a direction parallel to `up` falls back to -Z as the up hint.
glm::dquat lookRotation(glm::dvec3 direction, glm::dvec3 up = {0.0, 1.0, 0.0});

struct Transform {
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 scale{1.0};
};

class GltfBuilder {
public:
    explicit GltfBuilder(const std::string& generatorDescription);

    // baseColor is linear RGBA; metallic 0, roughness as given; single-sided (the glTF default).
    int addMaterial(const std::string& name, glm::vec4 baseColor, float roughness = 0.9f);
    // A PNG stored in the binary buffer (image/png bufferView), sampled linearly, clamped at the edges.
    int addPngTexture(const std::string& name, const std::vector<std::uint8_t>& png);
    // Uses `texture` as the base colour texture of `material` (TEXCOORD_0).
    void setBaseColorTexture(int material, int texture);
    struct Part {
        const MeshData* data;
        int material;
    };
    int addMesh(const std::string& name, const std::vector<Part>& parts);
    int addPerspectiveCamera(const std::string& name, double yfov, double znear, double zfar);
    int addDirectionalLight(const std::string& name, glm::dvec3 color, double intensity);
    int addSpotLight(const std::string& name, glm::dvec3 color, double intensity, double range, double innerCone,
                     double outerCone);

    // A node under `parent` (-1: a root of the scene). Translations and scales are rounded to 0.1 mm,
    // rotations to 1e-7, so the JSON stays short; the rounded values are what the stats use.
    int addNode(const std::string& name, const Transform& transform, int parent = -1);
    void setMesh(int node, int mesh) { model_.nodes[std::size_t(node)].mesh = mesh; }
    void setCamera(int node, int camera) { model_.nodes[std::size_t(node)].camera = camera; }
    void setLight(int node, int light);
    // A camera/light node at `position` looking along `direction`.
    int addCameraNode(const std::string& name, int camera, glm::dvec3 position, glm::dvec3 direction, int parent = -1);
    int addLightNode(const std::string& name, int light, glm::dvec3 position, glm::dvec3 direction, int parent = -1);

    // Calls `visit` for every node reachable from the scene with its world matrix (parents first).
    void forEachNode(const std::function<void(const tinygltf::Node&, const glm::dmat4& world)>& visit) const;
    // World-space bounds of the vertices drawn so far; false when nothing is drawn yet.
    bool drawnBounds(glm::dvec3& lo, glm::dvec3& hi) const;

    // Counts the model (world transforms, drawn triangles, bounds) and writes it as .glb.
    bool write(const std::filesystem::path& out, SceneStats& stats, std::string& error);

    const tinygltf::Model& model() const { return model_; }

private:
    int addAccessor(const void* data, std::size_t bytes, int componentType, int type, std::size_t count, int target);

    tinygltf::Model model_;
    std::vector<MeshData> meshGeometry_;  // per mesh, all parts merged, for bounds
    std::vector<std::size_t> meshTriangles_;
};

}  // namespace shadowlab::scenegen
