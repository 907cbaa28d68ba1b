// The loader over the real Khronos sample models and Sponza in ../shared/scenes: counts, bounds
// and values are what the files contain (measured independently from the JSON and .bin).
#include "scenes/gltf_loader.h"
#include "shared_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

namespace shadowlab {
namespace {

using scene_test::expectVec;
using scene_test::kScenes;

Scene load(const std::string& relative) {
    LoadResult r = loadScene(kScenes + "/" + relative);
    EXPECT_TRUE(r.ok()) << r.error;
    EXPECT_TRUE(r.error.empty());
    return r.ok() ? std::move(*r.scene) : Scene{};
}

std::size_t primitiveCount(const Scene& s) {
    std::size_t n = 0;
    for (const Mesh& m : s.meshes) n += m.primitives.size();
    return n;
}

bool hasWarningContaining(const Scene& s, const std::string& text) {
    return std::any_of(s.warnings.begin(), s.warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

class BoxContainers : public testing::TestWithParam<const char*> {};

TEST_P(BoxContainers, LoadsTheUnitCubeWithItsHierarchyAndDefaults) {
    const Scene s = load(GetParam());
    ASSERT_EQ(s.nodes.size(), 2u);
    EXPECT_EQ(s.roots, std::vector<int>{0});
    EXPECT_EQ(s.nodes[1].parent, 0);
    EXPECT_TRUE(s.nodes[0].hasMatrix);
    ASSERT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.meshes[0].primitives.size(), 1u);
    const Primitive& p = s.meshes[0].primitives[0];
    EXPECT_EQ(p.positions.size(), 24u);
    EXPECT_EQ(p.normals.size(), 24u);
    EXPECT_TRUE(p.texcoords.empty());
    EXPECT_EQ(p.triangleCount(), 12u);
    EXPECT_EQ(p.material, 0);
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.instances[0].node, 1);
    EXPECT_FALSE(s.instances[0].mirrored);
    EXPECT_EQ(s.triangleCount(), 12u);
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_NEAR(s.materials[0].baseColorFactor.r, 0.8, 1e-6);
    EXPECT_NEAR(s.materials[0].baseColorFactor.g, 0.0, 1e-6);
    // The root's matrix swaps y and z (Z-up to Y-up): the unit cube stays a unit cube.
    expectVec(s.bounds.min, glm::dvec3(-0.5), 1e-6);
    expectVec(s.bounds.max, glm::dvec3(0.5), 1e-6);
    for (const glm::vec3& n : p.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    // No light and no camera in the file: the defaults are added.
    EXPECT_TRUE(s.defaultLight);
    EXPECT_TRUE(s.defaultCamera);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].name, "Default Sun");
    ASSERT_EQ(s.cameras.size(), 1u);
}

INSTANTIATE_TEST_SUITE_P(ThreeContainers, BoxContainers,
                         testing::Values("Box/glTF/Box.gltf", "Box/glTF-Binary/Box.glb", "Box/glTF-Embedded/Box.gltf"));

TEST(LoaderSamples, BoxInThreeContainersGivesIdenticalGeometry) {
    const Scene a = load("Box/glTF/Box.gltf");
    const Scene b = load("Box/glTF-Binary/Box.glb");
    const Scene c = load("Box/glTF-Embedded/Box.gltf");
    ASSERT_FALSE(a.meshes.empty());
    ASSERT_FALSE(b.meshes.empty());
    ASSERT_FALSE(c.meshes.empty());
    EXPECT_EQ(a.meshes[0].primitives[0].positions, b.meshes[0].primitives[0].positions);
    EXPECT_EQ(a.meshes[0].primitives[0].positions, c.meshes[0].primitives[0].positions);
    EXPECT_EQ(a.meshes[0].primitives[0].indices, b.meshes[0].primitives[0].indices);
    EXPECT_EQ(a.meshes[0].primitives[0].indices, c.meshes[0].primitives[0].indices);
    EXPECT_EQ(a.bounds, b.bounds);
    EXPECT_EQ(a.bounds, c.bounds);
}

TEST(LoaderSamples, BoxTexturedDecodesItsPngToRgba8WithTheSampler) {
    for (const char* file : {"BoxTextured/glTF/BoxTextured.gltf", "BoxTextured/glTF-Binary/BoxTextured.glb",
                             "BoxTextured/glTF-Embedded/BoxTextured.gltf"}) {
        SCOPED_TRACE(file);
        const Scene s = load(file);
        ASSERT_EQ(s.textures.size(), 1u);
        const Texture& t = s.textures[0];
        EXPECT_GT(t.width, 0);
        EXPECT_GT(t.height, 0);
        ASSERT_EQ(t.rgba8.size(), std::size_t(t.width) * t.height * 4);
        EXPECT_EQ(t.sampler.magFilter, 9729);
        EXPECT_EQ(t.sampler.minFilter, 9986);
        EXPECT_EQ(t.sampler.wrapS, 10497);
        ASSERT_EQ(s.materials.size(), 1u);
        EXPECT_EQ(s.materials[0].baseColorTexture, 0);
        ASSERT_EQ(s.meshes.size(), 1u);
        const Primitive& p = s.meshes[0].primitives[0];
        EXPECT_EQ(p.texcoords.size(), p.positions.size());
        // Not a flat colour: the Cesium logo has several distinct colours.
        std::size_t distinct = 0;
        for (std::size_t i = 4; i < t.rgba8.size(); i += 4)
            if (!std::equal(t.rgba8.begin() + long(i), t.rgba8.begin() + long(i) + 3, t.rgba8.begin())) ++distinct;
        EXPECT_GT(distinct, std::size_t(t.width));
    }
}

TEST(LoaderSamples, DuckHasItsTrianglesCameraAndScaledBounds) {
    const Scene s = load("Duck/glTF/Duck.gltf");
    EXPECT_EQ(s.nodes.size(), 3u);
    EXPECT_EQ(s.triangleCount(), 4212u);
    EXPECT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(s.textures.size(), 1u);
    ASSERT_EQ(s.cameras.size(), 1u);
    EXPECT_FALSE(s.defaultCamera);
    EXPECT_TRUE(s.defaultLight);
    // Accessor min/max of POSITION scaled by the root's 0.01 (no rotation on the path).
    expectVec(s.bounds.min, glm::dvec3(-0.6929850006, 0.0992936993, -0.6132819748), 1e-5);
    expectVec(s.bounds.max, glm::dvec3(0.9617990112, 1.6397000122, 0.5392519760), 1e-5);
    // Camera placed by its node's matrix (times the root's 0.01), orthonormal frame.
    const Camera& c = s.cameras[0];
    expectVec(glm::dvec3(c.cameraToWorld[3]), glm::dvec3(4.00113, 4.63264, -4.31078), 1e-4);
    EXPECT_NEAR(glm::length(glm::dvec3(c.cameraToWorld[0])), 1.0, 1e-9);
    EXPECT_NEAR(glm::length(glm::dvec3(c.cameraToWorld[2])), 1.0, 1e-9);
}

TEST(LoaderSamples, QuantizedDuckMatchesTheFloatDuck) {
    const Scene plain = load("Duck/glTF/Duck.gltf");
    const Scene quantized = load("Duck/glTF-Quantized/Duck.gltf");
    EXPECT_EQ(quantized.triangleCount(), plain.triangleCount());
    EXPECT_EQ(quantized.triangleCount(), 4212u);
    // int16 positions dequantized by the node scale: same world box within the quantization step.
    expectVec(quantized.bounds.min, plain.bounds.min, 2e-3);
    expectVec(quantized.bounds.max, plain.bounds.max, 2e-3);
    ASSERT_EQ(quantized.meshes.size(), 1u);
    const Primitive& q = quantized.meshes[0].primitives[0];
    for (const glm::vec3& n : q.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-4f);
    // uint16 texcoords are only meaningful through KHR_texture_transform, which is baked in.
    ASSERT_EQ(q.texcoords.size(), q.positions.size());
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (const glm::vec2& t : q.texcoords) {
        lo = glm::min(lo, t);
        hi = glm::max(hi, t);
    }
    EXPECT_NEAR(lo.x, 0.0264, 2e-3);
    EXPECT_NEAR(lo.y, 0.0200, 2e-3);
    EXPECT_NEAR(hi.x, 0.9833, 2e-3);
    EXPECT_NEAR(hi.y, 0.9800, 2e-3);
}

TEST(LoaderSamples, SimpleMeshesInstancesOneMeshTwiceWithTheDefaultMaterial) {
    for (const char* file : {"SimpleMeshes/glTF/SimpleMeshes.gltf", "SimpleMeshes/glTF-Embedded/SimpleMeshes.gltf"}) {
        SCOPED_TRACE(file);
        const Scene s = load(file);
        EXPECT_EQ(s.nodes.size(), 2u);
        EXPECT_EQ(s.meshes.size(), 1u);
        ASSERT_EQ(s.instances.size(), 2u);
        EXPECT_EQ(s.instances[0].mesh, s.instances[1].mesh);
        EXPECT_EQ(s.triangleCount(), 2u);
        EXPECT_TRUE(s.materials.empty());
        EXPECT_EQ(s.meshes[0].primitives[0].material, -1);
        // Flat scene: zero extent in z, x spans the two instances (second one moved by +1).
        EXPECT_EQ(s.bounds.extent().z, 0.0);
        expectVec(s.bounds.min, glm::dvec3(0.0, 0.0, 0.0), 1e-6);
        expectVec(s.bounds.max, glm::dvec3(2.0, 1.0, 0.0), 1e-6);
    }
}

TEST(LoaderSamples, TriangleWithoutIndicesGetsSequentialIndicesAndComputedNormals) {
    for (const char* file :
         {"TriangleWithoutIndices/glTF/TriangleWithoutIndices.gltf",
          "TriangleWithoutIndices/glTF-Embedded/TriangleWithoutIndices.gltf"}) {
        SCOPED_TRACE(file);
        const Scene s = load(file);
        ASSERT_EQ(s.meshes.size(), 1u);
        const Primitive& p = s.meshes[0].primitives[0];
        EXPECT_EQ(p.indices, (std::vector<std::uint32_t>{0, 1, 2}));
        ASSERT_EQ(p.normals.size(), 3u);
        // Counter-clockwise in the xy plane: the computed normal is +z.
        for (const glm::vec3& n : p.normals) expectVec(glm::dvec3(n), glm::dvec3(0, 0, 1), 1e-6);
        EXPECT_EQ(s.triangleCount(), 1u);
    }
}

TEST(LoaderSamples, LightsPunctualLampHasFivePointLightsPlacedByMatrixNodes) {
    const Scene s = load("LightsPunctualLamp/glTF/LightsPunctualLamp.gltf");
    EXPECT_EQ(s.nodes.size(), 8u);
    EXPECT_FALSE(s.defaultLight);
    ASSERT_EQ(s.lights.size(), 5u);
    for (const Light& l : s.lights) {
        EXPECT_EQ(l.type, LightType::Point);
        EXPECT_GE(l.node, 0);
        EXPECT_EQ(s.nodes[std::size_t(l.node)].light, int(&l - s.lights.data()));
    }
    EXPECT_EQ(s.lights[0].name, "Point");
    EXPECT_FLOAT_EQ(s.lights[0].intensity, 15.0f);
    EXPECT_NEAR(s.lights[0].color.g, 0.631875, 1e-6);
    expectVec(s.lights[0].position, glm::dvec3(0.0462236, 0.9077973, 0.0066966), 1e-6);
    EXPECT_EQ(s.triangleCount(), 6000u);
    // The lamp shade's transmission extension is reported, not silently dropped.
    EXPECT_TRUE(hasWarningContaining(s, "KHR_materials_transmission"));
}

TEST(LoaderSamples, BoxAnimatedHasItsTwoLinearChannels) {
    for (const char* file : {"BoxAnimated/glTF/BoxAnimated.gltf", "BoxAnimated/glTF-Binary/BoxAnimated.glb"}) {
        SCOPED_TRACE(file);
        const Scene s = load(file);
        EXPECT_EQ(s.nodes.size(), 4u);
        ASSERT_EQ(s.animations.size(), 1u);
        const Animation& a = s.animations[0];
        ASSERT_EQ(a.channels.size(), 2u);
        EXPECT_EQ(a.channels[0].node, 2);
        EXPECT_EQ(a.channels[0].path, AnimationPath::Rotation);
        EXPECT_EQ(a.channels[0].interpolation, Interpolation::Linear);
        EXPECT_EQ(a.channels[0].times.size(), a.channels[0].values.size());
        EXPECT_FLOAT_EQ(a.channels[0].times.back(), 2.5f);
        EXPECT_EQ(a.channels[1].node, 0);
        EXPECT_EQ(a.channels[1].path, AnimationPath::Translation);
        EXPECT_NEAR(a.duration, 3.70833, 1e-5);
        for (const glm::vec4& q : a.channels[0].values) EXPECT_NEAR(glm::length(q), 1.0f, 1e-3f);
        EXPECT_EQ(s.triangleCount(), 254u);
    }
}

TEST(LoaderSamples, CamerasLoadsAPerspectiveAndAnOrthographicCamera) {
    const Scene s = load("Cameras/glTF/Cameras.gltf");
    ASSERT_EQ(s.cameras.size(), 2u);
    EXPECT_FALSE(s.defaultCamera);
    EXPECT_FALSE(s.cameras[0].orthographic);
    EXPECT_FLOAT_EQ(s.cameras[0].yfov, 0.7f);
    EXPECT_FLOAT_EQ(s.cameras[0].aspectRatio, 1.0f);
    EXPECT_FLOAT_EQ(s.cameras[0].znear, 0.01f);
    EXPECT_FLOAT_EQ(s.cameras[0].zfar, 100.0f);
    EXPECT_TRUE(s.cameras[1].orthographic);
    EXPECT_FLOAT_EQ(s.cameras[1].xmag, 1.0f);
    EXPECT_FLOAT_EQ(s.cameras[1].ymag, 1.0f);
    for (const Camera& c : s.cameras) expectVec(glm::dvec3(c.cameraToWorld[3]), glm::dvec3(0.5, 0.5, 3.0), 1e-9);
    EXPECT_EQ(s.triangleCount(), 2u);
}

TEST(LoaderSamples, SimpleSparseAccessorSubstitutesTheSparseVertices) {
    for (const char* file :
         {"SimpleSparseAccessor/glTF/SimpleSparseAccessor.gltf",
          "SimpleSparseAccessor/glTF-Embedded/SimpleSparseAccessor.gltf"}) {
        SCOPED_TRACE(file);
        const Scene s = load(file);
        ASSERT_EQ(s.meshes.size(), 1u);
        const Primitive& p = s.meshes[0].primitives[0];
        ASSERT_EQ(p.positions.size(), 14u);
        // Dense data has (k, 1, 0) in the upper row; the sparse part lifts vertices 8, 10, 12.
        EXPECT_EQ(p.positions[8], glm::vec3(1, 2, 0));
        EXPECT_EQ(p.positions[10], glm::vec3(3, 3, 0));
        EXPECT_EQ(p.positions[12], glm::vec3(5, 4, 0));
        EXPECT_EQ(p.positions[9], glm::vec3(2, 1, 0));  // not substituted
        EXPECT_EQ(p.triangleCount(), 12u);
        expectVec(s.bounds.max, glm::dvec3(6, 4, 0), 1e-9);
    }
}

TEST(LoaderSamples, SponzaHasWhatTheFileHolds) {
    const auto start = std::chrono::steady_clock::now();
    const Scene s = load("Sponza/Sponza.gltf");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    RecordProperty("load_seconds", std::to_string(seconds));
    std::printf("Sponza load: %.3f s\n", seconds);
    EXPECT_EQ(s.nodes.size(), 174u);
    EXPECT_EQ(s.meshes.size(), 44u);
    EXPECT_EQ(s.instances.size(), 170u);  // 4 of the 174 nodes carry the cameras
    EXPECT_EQ(s.triangleCount(), 262087u);
    EXPECT_EQ(s.materials.size(), 24u);
    EXPECT_EQ(s.textures.size(), 21u);  // the base colour textures (normal/roughness maps are not loaded)
    ASSERT_EQ(s.cameras.size(), 4u);
    EXPECT_EQ(s.cameras[0].name, "CameraMain");
    EXPECT_TRUE(s.defaultLight);
    // Exact world bounds of the transformed vertices (computed independently from Sponza.bin).
    expectVec(s.bounds.min, glm::dvec3(-26.8448346, 2.2819204, -16.4777503), 1e-4);
    expectVec(s.bounds.max, glm::dvec3(24.1774166, 23.6168867, 14.8996711), 1e-4);
    int masked = 0;
    for (const Material& m : s.materials)
        if (m.alphaMode == AlphaMode::Mask) {
            ++masked;
            EXPECT_TRUE(m.doubleSided) << m.name;
        }
    EXPECT_EQ(masked, 3);
    for (const Texture& t : s.textures) EXPECT_EQ(t.rgba8.size(), std::size_t(t.width) * t.height * 4) << t.name;
    std::size_t instanceTriangles = 0;
    for (const MeshInstance& i : s.instances) {
        ASSERT_FALSE(i.worldBounds.empty());
        EXPECT_LE(i.worldBounds.min.x, i.worldBounds.max.x);
        for (const Primitive& p : s.meshes[std::size_t(i.mesh)].primitives) instanceTriangles += p.triangleCount();
    }
    EXPECT_EQ(instanceTriangles, 262087u);
    EXPECT_GT(primitiveCount(s), 0u);
}

}  // namespace
}  // namespace shadowlab

namespace shadowlab {
namespace {

// LoadOptions::progress (the viewer's progress bar): fractions in [0, 1], never decreasing, one
// per mesh and per decoded texture at least, ending at exactly 1; printed with their times, the
// measurement behind the step weights of gltf_internal.h.
TEST(LoaderProgress, SponzaReportsAFractionPerStepEndingAtOne) {
    std::vector<std::pair<double, double>> reports;  // fraction, seconds since the start
    const auto start = std::chrono::steady_clock::now();
    LoadOptions options;
    options.progress = [&](double fraction) {
        reports.emplace_back(fraction, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    };
    const LoadResult r = loadScene(kScenes + "/Sponza/Sponza.gltf", options);
    ASSERT_TRUE(r.ok()) << r.error;
    ASSERT_FALSE(reports.empty());
    EXPECT_GE(reports.size(), r.scene->meshes.size() + 4);  // meshes + read, JSON, parse, nodes
    for (std::size_t i = 0; i < reports.size(); ++i) {
        EXPECT_GE(reports[i].first, 0.0);
        EXPECT_LE(reports[i].first, 1.0);
        if (i > 0) {
            EXPECT_GE(reports[i].first, reports[i - 1].first) << i;
        }
    }
    EXPECT_EQ(reports.back().first, 1.0);
    double last = -1.0;
    for (const auto& [fraction, seconds] : reports)
        if (fraction - last >= 0.02 || fraction == 1.0) {
            std::printf("progress %.3f at %.3f s\n", fraction, seconds);
            last = fraction;
        }
}

TEST(LoaderProgress, AFailedLoadNeverReportsOne) {
    std::vector<double> reports;
    LoadOptions options;
    options.progress = [&](double fraction) { reports.push_back(fraction); };
    const LoadResult r = loadScene(kScenes + "/does-not-exist.glb", options);
    EXPECT_FALSE(r.ok());
    for (double f : reports) EXPECT_LT(f, 1.0);
    // A load without a callback is the same load.
    EXPECT_TRUE(loadScene(kScenes + "/Box/glTF-Binary/Box.glb").ok());
}

}  // namespace
}  // namespace shadowlab
