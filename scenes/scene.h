#pragma once
// The project's own scene model: what the loader fills, what the renderer uploads and what the
// shadow math reads bounds from. GL-free and tinygltf-free, so every layer can see it.
#include "math/aabb.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_precision.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace shadowlab {

// One morph target of a primitive (glTF 2.0 spec 3.7.2.2): displacements added to the base
// attributes, weighted by the node's (or the mesh's default) weights.
struct MorphTarget {
    std::vector<glm::vec3> positions;  // POSITION displacement per vertex (zeros when the file has none)
    std::vector<glm::vec3> normals;    // NORMAL displacement, empty when the file has none
    Aabb positionBounds;               // of the displacements: weighted, they bound the morphed shape
};

// One triangle list (strips and fans are converted by the loader), de-indexed attributes
// already decoded to float (sparse accessors applied, normalized integers scaled).
struct Primitive {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;    // always filled: computed (area-weighted) when the file has none
    std::vector<glm::vec2> texcoords;  // TEXCOORD_0, empty when the file has none
    std::vector<std::uint32_t> indices;  // triangle list, always indexed (non-indexed input gets 0..n-1)
    int material = -1;                   // index into Scene::materials; -1 = default material
    Aabb bounds;                         // object space (the bind pose / base shape)
    // Skinning (glTF 2.0 spec 3.7.3): JOINTS_0 (indices into the node's Skin::joints) and
    // WEIGHTS_0 (normalised to sum 1 by the loader), both empty when the primitive is not skinned.
    std::vector<glm::u16vec4> joints;
    std::vector<glm::vec4> skinWeights;
    // Per skin joint: bounds of the bind-pose positions the joint influences (weight > 0), empty
    // boxes for joints without vertices. Transformed by the joint matrices they bound the pose.
    std::vector<Aabb> jointBounds;
    std::vector<MorphTarget> targets;
    bool skinned() const { return !joints.empty(); }
    std::size_t triangleCount() const { return indices.size() / 3; }
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
    std::vector<float> weights{};  // default morph target weights (one per target), may be empty
    bool morphed() const;        // a primitive has morph targets
    bool skinned() const;        // a primitive has JOINTS_0 / WEIGHTS_0
};

// glTF 2.0 spec 3.7.3 "Skins": the joints (nodes) and the matrices that take the mesh from its
// bind pose into each joint's space.
struct Skin {
    std::string name;
    std::vector<int> joints;                      // node indices
    std::vector<glm::dmat4> inverseBindMatrices;  // one per joint (identity when the file has none)
    int skeleton = -1;                            // informative only: the joints' common root
};

// Values are the glTF / OpenGL enums (9728 NEAREST, 9729 LINEAR, 10497 REPEAT, ...).
struct Sampler {
    int magFilter = 9729;
    int minFilter = 9987;  // LINEAR_MIPMAP_LINEAR
    int wrapS = 10497;
    int wrapT = 10497;
    bool operator==(const Sampler&) const = default;
};

struct Texture {
    std::string name;
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba8;  // decoded, 4 channels, sRGB-encoded colour (empty until decoded)
    // The image file's PNG/JPEG bytes, kept only when loaded with TextureDecoding::Deferred (see
    // decodeTexture); shared by the textures that use the same image.
    std::shared_ptr<const std::vector<std::uint8_t>> encoded;
    Sampler sampler;
};

enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};  // linear
    int baseColorTexture = -1;        // index into Scene::textures
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
    glm::vec3 emissiveFactor{0.0f};
};

enum class LightType { Directional, Spot, Point };

// A KHR_lights_punctual light placed in the world by its node.
struct Light {
    std::string name;
    LightType type = LightType::Directional;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    float range = 0.0f;  // 0 = unlimited
    float innerConeAngle = 0.0f;               // radians (spot)
    float outerConeAngle = 0.7853981633974483f;  // radians (spot), glTF default pi/4
    glm::dvec3 position{0.0};                  // world
    glm::dvec3 direction{0.0, -1.0, 0.0};      // world, the way the light travels (node's -Z)
    int node = -1;                             // -1 for the default sun
};

// A perspective (or orthographic) glTF camera placed by its node.
struct Camera {
    std::string name;
    bool orthographic = false;
    float yfov = 0.8f;        // radians
    float aspectRatio = 0.0f;  // 0 = use the viewport's
    float znear = 0.1f;
    float zfar = 0.0f;  // 0 = infinite in glTF; the loader replaces it with a finite value from the bounds
    float xmag = 1.0f, ymag = 1.0f;  // orthographic half extents
    glm::dmat4 cameraToWorld{1.0};   // camera looks down its -Z
    int node = -1;                   // -1 for the framing camera
};

struct Node {
    std::string name;
    int parent = -1;
    std::vector<int> children;
    // Local transform: the glTF matrix if given, else T*R*S of the fields below (kept for animation).
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    bool hasMatrix = false;
    glm::dmat4 matrix{1.0};
    glm::dmat4 world{1.0};
    int mesh = -1;
    int skin = -1;               // index into Scene::skins (with a skinned mesh)
    std::vector<float> weights;  // morph weights: the node's, else the mesh's default (animated)
    int camera = -1;  // index into Scene::cameras
    int light = -1;   // index into Scene::lights
};

// One mesh drawn at one node (a mesh referenced by n nodes gives n instances).
struct MeshInstance {
    int node = -1;
    int mesh = -1;
    glm::dmat4 world{1.0};
    Aabb worldBounds;
    bool mirrored = false;  // det(world) < 0: winding flips (matters for culling in the shadow pass)
};

enum class AnimationPath { Translation, Rotation, Scale, Weights };
enum class Interpolation { Linear, Step, CubicSpline };

struct AnimationChannel {
    int node = -1;
    AnimationPath path = AnimationPath::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;
    std::vector<glm::vec4> values;  // vec3 in xyz for T/S, quaternion xyzw for R; 3 per key for cubic spline
    // Path Weights: `targets` floats per value (values above stay empty), 3 values per key for cubic spline.
    std::vector<float> weights;
    int targets = 0;
};

struct Animation {
    std::string name;
    std::vector<AnimationChannel> channels;
    float duration = 0.0f;
};

struct Scene {
    std::string source;  // file it came from
    std::vector<Node> nodes;
    std::vector<int> roots;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Light> lights;
    std::vector<Camera> cameras;
    std::vector<MeshInstance> instances;
    std::vector<Animation> animations;
    std::vector<Skin> skins;
    Aabb bounds;  // world, over all instances
    bool defaultLight = false;   // no light in the file: a sun was added
    bool defaultCamera = false;  // no camera in the file: a framing camera was added
    std::vector<std::string> warnings;
    // The glTF file's scenes (a name each, may be empty) and the one shown (LoadOptions::sceneIndex).
    std::vector<std::string> sceneNames;
    int shownScene = -1;  // -1: the file has no scenes array (every parentless node is a root)

    std::size_t triangleCount() const;  // drawn triangles, per instance
};

}  // namespace shadowlab
