// Walk mode and the default fly speed on the generated forest's hills (GL-free): the ground under
// the eye comes from a ray down into the scene (app/ground_probe.h).
#include "frame/frame_setup.h"
#include "scenes/gltf_loader.h"
#include "viewer/camera_controller.h"
#include "ground_probe.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace shadowlab::app {
namespace {

const Scene& forest() {
    static const Scene scene = [] {
        LoadResult loaded = loadScene(FOREST_SCENE);
        EXPECT_TRUE(loaded.ok()) << loaded.error;
        return loaded.ok() ? std::move(*loaded.scene) : Scene{};
    }();
    return scene;
}

// The forest with its terrain only: the truth "below the ground" is checked against (trees and
// their crowns are not ground).
const Scene& terrainOnly() {
    static const Scene scene = [] {
        Scene s = forest();
        std::vector<MeshInstance> kept;
        for (const MeshInstance& i : s.instances)
            if (i.mesh >= 0 && s.meshes[std::size_t(i.mesh)].name.rfind("Terrain", 0) == 0) kept.push_back(i);  // the tiles
        s.instances = kept;
        return s;
    }();
    return scene;
}

double terrainHeight(double x, double z) {
    return groundBelow(terrainOnly(), x, z, terrainOnly().bounds.max.y + 10.0).value_or(-1e9);
}

TEST(GroundProbe, FindsTheNearestSurfaceBelowOnly) {
    Scene scene;
    Mesh quad;  // a 2 x 2 m floor at y = 0 and a ceiling at y = 3
    Primitive p;
    p.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, {-1, 3, -1}, {1, 3, -1}, {1, 3, 1}, {-1, 3, 1}};
    p.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    for (const auto& v : p.positions) p.bounds.extend(glm::dvec3(v));
    quad.primitives.push_back(p);
    scene.meshes.push_back(quad);
    MeshInstance instance;
    instance.mesh = 0;
    instance.world = glm::dmat4(1.0);
    instance.world[3] = glm::dvec4(10.0, 1.0, 0.0, 1.0);  // moved: floor at y = 1, ceiling at 4
    instance.worldBounds.extend(glm::dvec3(9, 1, -1));
    instance.worldBounds.extend(glm::dvec3(11, 4, 1));
    scene.instances.push_back(instance);
    EXPECT_NEAR(groundBelow(scene, 10.2, 0.3, 2.5).value_or(-1.0), 1.0, 1e-12);   // under the ceiling
    EXPECT_NEAR(groundBelow(scene, 10.2, 0.3, 9.0).value_or(-1.0), 4.0, 1e-12);   // above it: the ceiling
    EXPECT_FALSE(groundBelow(scene, 12.5, 0.0, 9.0));                              // beside the quads
    EXPECT_FALSE(groundBelow(scene, 10.0, 0.0, 0.5));                              // below the floor
    EXPECT_FALSE(groundBelow(scene, std::nan(""), 0.0, 9.0));
}

TEST(GroundProbe, TheIndexedProbeAgreesWithTheFullSearchOnTheForest) {
    const GroundProbe probe(forest());
    std::mt19937 random(3);
    std::uniform_real_distribution<double> xz(-250.0, 250.0), y(-10.0, 30.0);
    for (int i = 0; i < 60; ++i) {
        const double x = xz(random), z = xz(random), from = y(random);
        const auto full = groundBelow(forest(), x, z, from), indexed = probe.below(x, z, from);
        ASSERT_EQ(full.has_value(), indexed.has_value()) << x << " " << z << " " << from;
        if (full) {
            EXPECT_EQ(*full, *indexed) << x << " " << z << " " << from;
        }
    }
}

TEST(GroundProbe, TheForestStartsAtAWalkersSpeedAndTheAerialCameraFaster) {
    ASSERT_FALSE(forest().cameras.empty());
    const CameraSettings eyeLevel = cameraFromScene(forest().cameras[0], CameraSettings{});
    const double speed = defaultFlySpeed(forest(), eyeLevel.position);
    // 1.8 m over the ground: 5.4 m/s (a tenth of the diagonal was 72.6 m/s).
    EXPECT_LE(speed, 6.0);
    EXPECT_GE(speed, 1.5);
    const auto aerial = std::find_if(forest().cameras.begin(), forest().cameras.end(),
                                     [](const Camera& c) { return c.name == "Camera_Aerial"; });
    ASSERT_NE(aerial, forest().cameras.end());
    EXPECT_GT(defaultFlySpeed(forest(), cameraFromScene(*aerial, CameraSettings{}).position), 50.0);
}

// Walks (or flies, walkOn null) 120 frames of 1.6 s in random directions at 4 x 5.4 m/s (shift)
// from the first camera; returns how far the eye got below eye/2 over the terrain, at worst.
double worstDepthUnderTerrain(bool walk, double& eye) {
    static const GroundProbe probe(forest());
    CameraController controller;
    CameraSettings camera = cameraFromScene(forest().cameras[0], CameraSettings{});
    camera.moveSpeed = 5.4;
    eye = camera.position.y - groundBelow(forest(), camera.position.x, camera.position.z, camera.position.y).value();
    if (walk) {
        controller.walkOn = &probe;
        controller.walkEyeHeight = eye;
    }
    std::mt19937 random(7);
    std::uniform_real_distribution<double> yaw(-180.0, 180.0);
    double worst = -1e9;
    for (int frame = 0; frame < 120; ++frame) {
        camera.yawDeg = yaw(random);
        CameraInput in;
        in.flight = {0.0, 0.0, 1.6};
        in.fast = frame % 2 == 0;
        controller.apply(camera, in);
        // Stay on the terrain (512 m): turn back towards the middle when near its edge.
        if (std::abs(camera.position.x) > 200.0 || std::abs(camera.position.z) > 200.0) {
            camera.yawDeg = glm::degrees(std::atan2(-camera.position.z, -camera.position.x));
            in.flight = {0.0, 0.0, 8.0};
            controller.apply(camera, in);
        }
        worst = std::max(worst, terrainHeight(camera.position.x, camera.position.z) + 0.5 * eye - camera.position.y);
    }
    return worst;
}

TEST(GroundProbe, WalkModeNeverGoesBelowTheGroundOnTheForestHills) {
    ASSERT_FALSE(terrainOnly().instances.empty()) << "the forest's terrain tiles";
    double eye = 0.0;
    EXPECT_LT(worstDepthUnderTerrain(true, eye), 0.0) << "eye " << eye;
    EXPECT_NEAR(eye, 1.8, 0.2);
    // Flying at a constant height over the same path does go under the hills.
    EXPECT_GT(worstDepthUnderTerrain(false, eye), 1.0);
}

}  // namespace
}  // namespace shadowlab::app
