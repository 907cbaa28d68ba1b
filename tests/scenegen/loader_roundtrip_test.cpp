// The generated scenes through the project's own loader (scenes/gltf_loader.h): what
// `shadowlab info` and the viewer see must be what the generator documents.
#include "scenes/generators/scene_generators.h"
#include "scenes/gltf_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace shadowlab::test {
namespace {

namespace fs = std::filesystem;

class LoaderRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(LoaderRoundTrip, LoadsWithTheGeneratorsCountsAndWithoutDefaults) {
    const fs::path file = fs::path(::testing::TempDir()) / ("roundtrip-" + GetParam() + ".glb");
    const scenegen::GenerateResult generated = scenegen::generateScene(GetParam(), {}, file);
    ASSERT_TRUE(generated.ok) << generated.error;
    const LoadResult loaded = loadScene(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    const Scene& scene = *loaded.scene;
    EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
    const scenegen::SceneStats& s = generated.stats;
    EXPECT_EQ(scene.nodes.size(), s.nodes);
    EXPECT_EQ(scene.instances.size(), s.meshInstances);
    EXPECT_EQ(scene.triangleCount(), s.triangles);
    EXPECT_EQ(scene.meshes.size(), s.meshes);
    EXPECT_EQ(scene.materials.size(), s.materials);
    EXPECT_EQ(scene.cameras.size(), s.cameras);
    EXPECT_EQ(scene.lights.size(), s.lights);
    EXPECT_FALSE(scene.defaultLight) << "the file's own light is used";
    EXPECT_FALSE(scene.defaultCamera) << "the file's own cameras are used";
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(scene.bounds.min[i], s.boundsMin[i], 1e-3);
        EXPECT_NEAR(scene.bounds.max[i], s.boundsMax[i], 1e-3);
    }
    for (const Camera& c : scene.cameras) {
        EXPECT_FALSE(c.name.empty());
        EXPECT_NEAR(c.yfov, std::numbers::pi / 3.0, 1e-6) << c.name;
        EXPECT_NEAR(c.znear, 0.1f, 1e-7) << c.name;
    }
    for (const Material& m : scene.materials) EXPECT_FALSE(m.name.empty());
    for (const Node& n : scene.nodes) EXPECT_FALSE(n.name.empty());
}

INSTANTIATE_TEST_SUITE_P(Scenes, LoaderRoundTrip,
                         ::testing::Values("forest", "cubes", "chessboard", "street", "plane-box", "interior"),
                         [](const auto& info) {
                             std::string n = info.param;
                             std::replace(n.begin(), n.end(), '-', '_');
                             return n;
                         });

TEST(LoaderRoundTrip, ForestCamerasAndSunAsTheThesisSetsThem) {
    const fs::path file = fs::path(::testing::TempDir()) / "roundtrip-forest-cameras.glb";
    ASSERT_TRUE(scenegen::generateScene("forest", {}, file).ok);
    const LoadResult loaded = loadScene(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    const Scene& scene = *loaded.scene;
    ASSERT_EQ(scene.cameras.size(), 5u);
    EXPECT_EQ(scene.cameras.front().name, "Camera_AlongGround_SunSide");
    for (const Camera& c : scene.cameras) EXPECT_FLOAT_EQ(c.zfar, 70.0f) << c.name;
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, LightType::Directional);
    EXPECT_NEAR(std::asin(-scene.lights[0].direction.y) * 180.0 / std::numbers::pi, 30.0, 1e-3);
    // The side camera looks perpendicular to the sun's horizontal direction.
    const glm::dvec3 view = -glm::dvec3(scene.cameras.front().cameraToWorld[2]);
    const glm::dvec3 sun = scene.lights[0].direction;
    EXPECT_NEAR(glm::dot(glm::normalize(glm::dvec3(view.x, 0, view.z)), glm::normalize(glm::dvec3(sun.x, 0, sun.z))), 0.0, 1e-5);
}

TEST(LoaderRoundTrip, SkyBoxLoadsSingleSidedWithItsTexture) {
    const fs::path file = fs::path(::testing::TempDir()) / "roundtrip-interior-skybox.glb";
    scenegen::GenerateOptions options;
    options.skyBox = true;
    const scenegen::GenerateResult generated = scenegen::generateScene("interior", options, file);
    ASSERT_TRUE(generated.ok) << generated.error;
    const LoadResult loaded = loadScene(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
    const Scene& scene = *loaded.scene;
    EXPECT_EQ(scene.triangleCount(), generated.stats.triangles);
    const auto sky = std::find_if(scene.materials.begin(), scene.materials.end(), [](const Material& m) { return m.name == "SkyBox_Sky"; });
    ASSERT_NE(sky, scene.materials.end());
    EXPECT_FALSE(sky->doubleSided);
    ASSERT_GE(sky->baseColorTexture, 0);
    ASSERT_LT(std::size_t(sky->baseColorTexture), scene.textures.size());
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(scene.bounds.min[i], generated.stats.boundsMin[i], 1e-3);
        EXPECT_NEAR(scene.bounds.max[i], generated.stats.boundsMax[i], 1e-3);
    }
}

TEST(LoaderRoundTrip, ChessboardSpotLightIsASpot) {
    const fs::path file = fs::path(::testing::TempDir()) / "roundtrip-chessboard-spot.glb";
    ASSERT_TRUE(scenegen::generateScene("chessboard", {}, file).ok);
    const LoadResult loaded = loadScene(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    ASSERT_EQ(loaded.scene->lights.size(), 1u);
    const Light& spot = loaded.scene->lights[0];
    EXPECT_EQ(spot.type, LightType::Spot);
    EXPECT_NEAR(spot.position.x, -6.0, 1e-6);
    EXPECT_NEAR(spot.position.y, 9.0, 1e-6);
    EXPECT_NEAR(spot.outerConeAngle, 40.0 * std::numbers::pi / 180.0, 1e-6);
}

}  // namespace
}  // namespace shadowlab::test
