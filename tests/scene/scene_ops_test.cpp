// Scene-model operations without files: world transforms, instances, bounds, default light and
// camera, and the text of `shadowlab info` (describeScene).
#include "scenes/gltf_loader.h"
#include "shared_scenes.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace shadowlab {
namespace {

using scene_test::expectVec;
using scene_test::kScenes;

Primitive unitCube() {
    Primitive p;
    for (int i = 0; i < 8; ++i) p.positions.emplace_back(i & 1 ? 0.5f : -0.5f, i & 2 ? 0.5f : -0.5f, i & 4 ? 0.5f : -0.5f);
    p.normals.assign(8, glm::vec3(0, 1, 0));
    p.indices = {0, 1, 3, 0, 3, 2};
    for (const glm::vec3& v : p.positions) p.bounds.extend(glm::dvec3(v));
    return p;
}

// A triangle whose object box is much larger than its rotated self.
Primitive thinTriangle() {
    Primitive p;
    p.positions = {{0, 0, 0}, {1, 1, 0}, {1, 1, 0.01f}};
    p.normals.assign(3, glm::vec3(0, 0, 1));
    p.indices = {0, 1, 2};
    for (const glm::vec3& v : p.positions) p.bounds.extend(glm::dvec3(v));
    return p;
}

Scene sceneWith(Primitive p) {
    Scene s;
    s.meshes.push_back(Mesh{"m", {std::move(p)}});
    return s;
}

TEST(WorldTransforms, ChildComposesWithItsParent) {
    Scene s = sceneWith(unitCube());
    s.nodes.resize(2);
    s.nodes[0].translation = {10, 0, 0};
    s.nodes[0].rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
    s.nodes[0].children = {1};
    s.nodes[1].parent = 0;
    s.nodes[1].translation = {0, 0, 2};  // +z in the parent turns into +x after the 90 degree yaw
    s.nodes[1].scale = {2, 2, 2};
    s.nodes[1].mesh = 0;
    s.roots = {0};
    updateWorldTransforms(s);
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.instances[0].node, 1);
    expectVec(glm::dvec3(s.nodes[1].world[3]), glm::dvec3(12, 0, 0), 1e-6);
    expectVec(s.bounds.min, glm::dvec3(11, -1, -1), 1e-6);
    expectVec(s.bounds.max, glm::dvec3(13, 1, 1), 1e-6);
    EXPECT_EQ(s.instances[0].worldBounds, s.bounds);
    EXPECT_FALSE(s.instances[0].mirrored);
    EXPECT_EQ(s.triangleCount(), 2u);
}

TEST(WorldTransforms, RotatedInstanceBoundsAreTheVerticesNotTheBoxCorners) {
    Scene s = sceneWith(thinTriangle());
    s.nodes.resize(1);
    s.nodes[0].rotation = glm::angleAxis(glm::radians(45.0f), glm::vec3(0, 0, 1));
    s.nodes[0].mesh = 0;
    s.roots = {0};
    updateWorldTransforms(s);
    // (1,1,0) rotated by 45 degrees about z lands on (0, sqrt 2, 0): x stays at 0.
    expectVec(s.bounds.min, glm::dvec3(0, 0, 0), 1e-6);
    expectVec(s.bounds.max, glm::dvec3(0, std::sqrt(2.0), 0.01), 1e-6);
    // The transformed object box would have reached x = -0.707.
    EXPECT_LT(s.meshes[0].primitives[0].bounds.transformed(s.nodes[0].world).min.x, -0.7);
}

TEST(WorldTransforms, MatrixWinsOverTrsAndMirroringIsFlagged) {
    Scene s = sceneWith(unitCube());
    s.nodes.resize(1);
    s.nodes[0].translation = {100, 100, 100};  // ignored: the node has a matrix
    s.nodes[0].hasMatrix = true;
    s.nodes[0].matrix = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 5, 0)), glm::dvec3(-1, 1, 1));
    s.nodes[0].mesh = 0;
    updateWorldTransforms(s);  // no roots given: parentless nodes are roots
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_TRUE(s.instances[0].mirrored);
    expectVec(s.bounds.center(), glm::dvec3(0, 5, 0), 1e-9);
}

TEST(WorldTransforms, LightsAndCamerasFollowTheirNodes) {
    Scene s = sceneWith(unitCube());
    s.nodes.resize(2);
    s.nodes[0].light = 0;
    s.nodes[1].camera = 0;
    s.nodes[1].scale = {3, 3, 3};  // cameras get an orthonormal frame regardless
    s.lights.push_back(Light{});
    s.lights[0].node = 0;
    s.lights[0].type = LightType::Spot;
    s.cameras.push_back(Camera{});
    s.cameras[0].node = 1;
    s.roots = {0, 1};
    s.nodes[0].translation = {1, 2, 3};
    s.nodes[0].rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
    s.nodes[1].translation = {0, 0, 7};
    updateWorldTransforms(s);
    expectVec(s.lights[0].position, glm::dvec3(1, 2, 3), 1e-6);
    expectVec(s.lights[0].direction, glm::dvec3(-1, 0, 0), 1e-6);  // -Z yawed by +90 degrees
    const glm::dmat4& c = s.cameras[0].cameraToWorld;
    expectVec(glm::dvec3(c[3]), glm::dvec3(0, 0, 7), 1e-9);
    EXPECT_NEAR(glm::length(glm::dvec3(c[0])), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(glm::dvec3(c[2])), 1.0, 1e-12);
    // Moving the node (as animation does) and recomputing moves the light.
    s.nodes[0].translation = {4, 5, 6};
    updateWorldTransforms(s);
    expectVec(s.lights[0].position, glm::dvec3(4, 5, 6), 1e-6);
}

TEST(WorldTransforms, SurvivesACycleAndBadLinksInAHandBuiltScene) {
    Scene s = sceneWith(unitCube());
    s.nodes.resize(2);
    s.nodes[0].children = {1, 7, -3};
    s.nodes[1].children = {0};
    s.nodes[1].mesh = 0;
    s.nodes[0].mesh = 5;  // no such mesh
    s.roots = {0};
    updateWorldTransforms(s);
    EXPECT_EQ(s.instances.size(), 1u);
}

TEST(WorldTransforms, InstancesWithoutNodesKeepTheirMatrices) {
    Scene s = sceneWith(unitCube());
    MeshInstance instance;
    instance.mesh = 0;
    instance.world = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -4));
    s.instances.push_back(instance);
    updateWorldTransforms(s);
    ASSERT_EQ(s.instances.size(), 1u);
    expectVec(s.bounds.center(), glm::dvec3(0, 0, -4), 1e-9);
}

// Every corner of the bounds lies inside the framing camera's frustum (square viewport).
void expectFramed(const Scene& s, const Camera& c) {
    const glm::dmat4 view = glm::inverse(c.cameraToWorld);
    const double t = std::tan(0.5 * double(c.yfov));
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 p = glm::dvec3(view * glm::dvec4(s.bounds.corner(i), 1.0));
        EXPECT_LT(p.z, 0.0);
        EXPECT_GT(-p.z, double(c.znear));
        EXPECT_LT(-p.z, double(c.zfar));
        EXPECT_LE(std::abs(p.y), -p.z * t + 1e-9);
        EXPECT_LE(std::abs(p.x), -p.z * t + 1e-9);
    }
}

TEST(Defaults, SunFromAboveAndSidewaysAndAFramingCamera) {
    Scene s = sceneWith(unitCube());
    s.nodes.resize(1);
    s.nodes[0].mesh = 0;
    s.nodes[0].translation = {1000, 20, -300};
    s.nodes[0].scale = {40, 5, 10};
    updateWorldTransforms(s);
    addDefaultsIfMissing(s);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_TRUE(s.defaultLight);
    const Light& sun = s.lights[0];
    EXPECT_EQ(sun.name, "Default Sun");
    EXPECT_EQ(sun.type, LightType::Directional);
    EXPECT_EQ(sun.node, -1);
    EXPECT_NEAR(glm::length(sun.direction), 1.0, 1e-12);
    EXPECT_LT(sun.direction.y, -0.8);                                       // from above
    EXPECT_GT(std::abs(sun.direction.x) + std::abs(sun.direction.z), 0.1);  // slightly sideways
    ASSERT_EQ(s.cameras.size(), 1u);
    EXPECT_TRUE(s.defaultCamera);
    const Camera& c = s.cameras[0];
    EXPECT_FALSE(c.orthographic);
    EXPECT_NEAR(c.yfov, glm::radians(60.0f), 1e-6);
    EXPECT_LT(c.znear, c.zfar);
    const glm::dvec3 forward = -glm::dvec3(c.cameraToWorld[2]);
    // A diagonal view: not along an axis.
    EXPECT_GT(std::abs(forward.x), 0.2);
    EXPECT_GT(std::abs(forward.y), 0.2);
    EXPECT_GT(std::abs(forward.z), 0.2);
    // It looks at the centre of the bounds.
    const glm::dvec3 toCenter = glm::normalize(s.bounds.center() - glm::dvec3(c.cameraToWorld[3]));
    EXPECT_NEAR(glm::dot(toCenter, forward), 1.0, 1e-9);
    expectFramed(s, c);
}

TEST(Defaults, NothingAddedWhenTheSceneHasItsOwn) {
    Scene s = sceneWith(unitCube());
    s.lights.push_back(Light{});
    s.cameras.push_back(Camera{});
    addDefaultsIfMissing(s);
    EXPECT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.cameras.size(), 1u);
    EXPECT_FALSE(s.defaultLight);
    EXPECT_FALSE(s.defaultCamera);
}

TEST(Defaults, EmptyAndFlatScenesGetFiniteDefaults) {
    Scene empty;
    updateWorldTransforms(empty);
    addDefaultsIfMissing(empty);
    ASSERT_EQ(empty.cameras.size(), 1u);
    EXPECT_TRUE(std::isfinite(empty.cameras[0].znear) && std::isfinite(empty.cameras[0].zfar));
    EXPECT_GT(empty.cameras[0].znear, 0.0f);
    for (int i = 0; i < 16; ++i) EXPECT_TRUE(std::isfinite(empty.cameras[0].cameraToWorld[i / 4][i % 4]));

    const LoadResult flat = loadScene(kScenes + "/SimpleMeshes/glTF/SimpleMeshes.gltf");
    ASSERT_TRUE(flat.ok()) << flat.error;
    EXPECT_EQ(flat.scene->bounds.extent().z, 0.0);
    expectFramed(*flat.scene, flat.scene->cameras[0]);
}

TEST(DescribeScene, ListsCountsLightsCamerasBoundsAndWarnings) {
    const LoadResult box = loadScene(kScenes + "/Box/glTF-Binary/Box.glb");
    ASSERT_TRUE(box.ok()) << box.error;
    const std::string text = describeScene(*box.scene);
    for (const char* line : {"nodes: 2 (1 roots)", "mesh instances: 1", "triangles: 12 drawn (12 unique)",
                             "materials: 1", "textures: 0", "lights: 1 (none in the file: default sun added)",
                             "\"Default Sun\" directional, direction (", "cameras: 1 (none in the file: framing camera added)",
                             "perspective, yfov 60 deg", "bounds: min (-0.5, -0.5, -0.5) max (0.5, 0.5, 0.5) size (1, 1, 1)",
                             "warnings: 0"})
        EXPECT_NE(text.find(line), std::string::npos) << "missing '" << line << "' in:\n" << text;

    const LoadResult lamp = loadScene(kScenes + "/LightsPunctualLamp/glTF/LightsPunctualLamp.gltf");
    ASSERT_TRUE(lamp.ok()) << lamp.error;
    const std::string lampText = describeScene(*lamp.scene);
    EXPECT_NE(lampText.find("lights: 5\n"), std::string::npos) << lampText;
    EXPECT_NE(lampText.find("\"Point.004\" point, position ("), std::string::npos) << lampText;
    EXPECT_NE(lampText.find("triangles: 6000 drawn"), std::string::npos) << lampText;
    EXPECT_NE(lampText.find("  - optional extension KHR_materials_transmission is ignored"), std::string::npos)
        << lampText;

    const LoadResult cameras = loadScene(kScenes + "/Cameras/glTF/Cameras.gltf");
    ASSERT_TRUE(cameras.ok()) << cameras.error;
    const std::string camText = describeScene(*cameras.scene);
    EXPECT_NE(camText.find("cameras: 2\n"), std::string::npos) << camText;
    EXPECT_NE(camText.find("orthographic, xmag 1, ymag 1"), std::string::npos) << camText;
    EXPECT_NE(camText.find("perspective, yfov 40.11 deg"), std::string::npos) << camText;
}

}  // namespace
}  // namespace shadowlab
