// Skins and morph targets (scenes/skinning.h) against hand-computed poses of the Khronos samples
// SimpleSkin and SimpleMorph, the weights sampler, pose bounds, and the loader's checks of
// JOINTS_0 / WEIGHTS_0 / morph targets (clear messages on bad files).
#include "gltf_fixture.h"
#include "scenes/animation.h"
#include "scenes/gltf_loader.h"
#include "scenes/skinning.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <filesystem>
#include <string>

namespace shadowlab {
namespace {

using namespace testing_files;
namespace fs = std::filesystem;

const fs::path kSharedScenes = SHADOWLAB_SHARED_SCENES;

Scene loadShared(const std::string& relative) {
    const fs::path file = kSharedScenes / relative;
    if (!fs::exists(file)) return Scene{};
    LoadResult r = loadScene(file);
    EXPECT_TRUE(r.ok()) << r.error;
    return r.ok() ? std::move(*r.scene) : Scene{};
}

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tolerance = 1e-5) {
    EXPECT_NEAR(a.x, b.x, tolerance) << "x";
    EXPECT_NEAR(a.y, b.y, tolerance) << "y";
    EXPECT_NEAR(a.z, b.z, tolerance) << "z";
}

bool contains(const Aabb& box, const glm::dvec3& p, double slack = 1e-6) {
    return glm::all(glm::lessThanEqual(box.min - slack, p)) && glm::all(glm::lessThanEqual(p, box.max + slack));
}

// SimpleSkin: a 1 x 2 strip, joint 0 at the origin, joint 1 (node 2) one unit up, weights from
// (1, 0) at y = 0 to (0, 1) at y = 2; at t = 1 s joint 1 has turned 90 degrees about +Z.
TEST(Skinning, SimpleSkinMatchesTheHandComputedPose) {
    Scene s = loadShared("SimpleSkin/glTF/SimpleSkin.gltf");
    if (s.nodes.empty()) GTEST_SKIP() << "shared scenes missing";
    ASSERT_EQ(s.skins.size(), 1u);
    ASSERT_EQ(s.skins[0].joints, (std::vector<int>{1, 2}));
    ASSERT_EQ(s.instances.size(), 1u);
    const Primitive& p = s.meshes[0].primitives[0];
    ASSERT_TRUE(p.skinned());
    EXPECT_EQ(p.joints[9], glm::u16vec4(0, 1, 0, 0));
    EXPECT_FLOAT_EQ(p.skinWeights[5].x + p.skinWeights[5].y, 1.0f);

    ASSERT_TRUE(animateScene(s, 1.0));
    const Pose pose = instancePose(s, s.instances[0]);
    ASSERT_EQ(pose.joints.size(), 2u);
    // jointMatrix[1] = T(0,1,0) * Rz(90) * inverseBind (T(0,-1,0)).
    expectNear(glm::dvec3(pose.joints[1] * glm::dvec4(0.5, 2.0, 0.0, 1.0)), glm::dvec3(-1.0, 1.5, 0.0));
    expectNear(glm::dvec3(pose.joints[0] * glm::dvec4(0.5, 2.0, 0.0, 1.0)), glm::dvec3(0.5, 2.0, 0.0));

    std::vector<glm::vec3> positions, normals;
    deformPrimitive(p, pose, positions, &normals);
    expectNear(positions[9], glm::dvec3(-1.0, 1.5, 0.0));   // all joint 1
    expectNear(positions[5], glm::dvec3(0.25, 1.25, 0.0));  // half (0.5, 1) + half (0, 1.5)
    expectNear(positions[1], glm::dvec3(0.5, 0.0, 0.0));    // all joint 0: does not move
    expectNear(normals[9], glm::dvec3(0.0, 0.0, 1.0));      // a turn about Z keeps the strip's normal

    // The pose's bounds hold every deformed vertex and left the bind pose (x reaches -1).
    const Aabb& bounds = s.instances[0].worldBounds;
    for (const glm::vec3& v : positions) EXPECT_TRUE(contains(bounds, glm::dvec3(v)));
    EXPECT_LT(bounds.min.x, -0.99);
    EXPECT_LT(s.bounds.min.x, -0.99);
}

// The spec's rule: the mesh node's own transform is undone by the joint matrices and applied by
// the instance, so world * jointMatrix = world(joint) * inverseBind whatever the mesh node does.
TEST(Skinning, TheMeshNodeTransformCancels) {
    Scene s = loadShared("SimpleSkin/glTF/SimpleSkin.gltf");
    if (s.nodes.empty()) GTEST_SKIP() << "shared scenes missing";
    s.nodes[0].translation = glm::vec3(5.0f, -2.0f, 3.0f);
    s.nodes[0].scale = glm::vec3(2.0f);
    animateScene(s, 1.0);
    const MeshInstance& instance = s.instances[0];
    const Pose pose = instancePose(s, instance);
    const glm::dmat4 expected = s.nodes[2].world * s.skins[0].inverseBindMatrices[1];
    const glm::dmat4 got = instance.world * pose.joints[1];
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(got[c][r], expected[c][r], 1e-9);
    // A singular mesh node has nothing to undo: identity joint matrices, no NaN.
    s.nodes[0].scale = glm::vec3(0.0f);
    updateWorldTransforms(s);
    for (const glm::dmat4& m : instancePose(s, s.instances[0]).joints) EXPECT_EQ(m, glm::dmat4(1.0));
}

// SimpleMorph: vertex 2 at (0.5, 0.5) with displacements (-1, 1) and (1, 1); default weights
// (0.5, 0.5); the animation's weights are (0, 1) at 1 s and (1, 1) at 2 s.
TEST(Morph, SimpleMorphMatchesTheHandComputedShape) {
    Scene s = loadShared("SimpleMorph/glTF/SimpleMorph.gltf");
    if (s.nodes.empty()) GTEST_SKIP() << "shared scenes missing";
    const Primitive& p = s.meshes[0].primitives[0];
    ASSERT_EQ(p.targets.size(), 2u);
    EXPECT_EQ(s.nodes[0].weights, (std::vector<float>{0.5f, 0.5f}));
    std::vector<glm::vec3> positions;
    deformPrimitive(p, instancePose(s, s.instances[0]), positions, nullptr);
    expectNear(positions[2], glm::dvec3(0.5, 1.5, 0.0));

    ASSERT_TRUE(animateScene(s, 1.5));  // weights (0.5, 1)
    EXPECT_FLOAT_EQ(s.nodes[0].weights[0], 0.5f);
    EXPECT_FLOAT_EQ(s.nodes[0].weights[1], 1.0f);
    deformPrimitive(p, instancePose(s, s.instances[0]), positions, nullptr);
    expectNear(positions[2], glm::dvec3(1.0, 2.0, 0.0));
    for (const glm::vec3& v : positions) EXPECT_TRUE(contains(s.instances[0].worldBounds, glm::dvec3(v)));
    EXPECT_GE(s.instances[0].worldBounds.max.y, 2.0 - 1e-6);  // the base shape reaches only 0.5
}

TEST(Morph, WeightsChannelsInterpolatePerTarget) {
    AnimationChannel c;
    c.path = AnimationPath::Weights;
    c.targets = 2;
    c.times = {0.0f, 2.0f};
    c.weights = {0.0f, 1.0f, 1.0f, -1.0f};
    std::vector<float> w;
    ASSERT_TRUE(sampleWeights(c, 0.5, w));
    EXPECT_FLOAT_EQ(w[0], 0.25f);
    EXPECT_FLOAT_EQ(w[1], 0.5f);
    ASSERT_TRUE(sampleWeights(c, 9.0, w));  // clamped to the last key
    EXPECT_FLOAT_EQ(w[1], -1.0f);
    c.interpolation = Interpolation::Step;
    ASSERT_TRUE(sampleWeights(c, 1.9, w));
    EXPECT_FLOAT_EQ(w[0], 0.0f);
    // Cubic spline, zero tangents: the Hermite basis at s = 0.5 is an even blend.
    c.interpolation = Interpolation::CubicSpline;
    c.weights = {0, 0, 0, 0, 0, 0, /*key 1*/ 0, 0, 1, 2, 0, 0};
    ASSERT_TRUE(sampleWeights(c, 1.0, w));
    EXPECT_FLOAT_EQ(w[0], 0.5f);
    EXPECT_FLOAT_EQ(w[1], 1.0f);
    c.weights.resize(5);  // too few values: unusable, not a read past the end
    EXPECT_FALSE(sampleWeights(c, 1.0, w));
}

// A negative weight scales the displacement box the other way round (the Minkowski sum).
TEST(Morph, PoseBoundsFollowNegativeWeights) {
    Primitive p;
    p.positions = {glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f)};
    p.bounds.extend(glm::dvec3(0.0));
    p.bounds.extend(glm::dvec3(1.0, 0.0, 0.0));
    MorphTarget t;
    t.positions = {glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0.0f)};
    for (const glm::vec3& d : t.positions) t.positionBounds.extend(glm::dvec3(d));
    p.targets.push_back(t);
    Pose pose;
    pose.weights = {-1.5f};
    std::vector<glm::vec3> positions;
    deformPrimitive(p, pose, positions, nullptr);
    expectNear(positions[0], glm::dvec3(0.0, -3.0, 0.0));
    const Aabb b = posedBounds(p, pose);
    EXPECT_TRUE(contains(b, glm::dvec3(positions[0])));
    EXPECT_TRUE(contains(b, glm::dvec3(positions[1])));
    EXPECT_NEAR(b.min.y, -3.0, 1e-9);
}

// The five sample files with skins or morph targets open without "ignored" warnings, posed at
// several times with bounds that hold every deformed vertex.
TEST(Skinning, SamplesOpenWithoutIgnoredWarningsAndBoundsHoldThePose) {
    for (const char* file : {"Fox/glTF-Binary/Fox.glb", "CesiumMan/glTF-Binary/CesiumMan.glb",
                             "SimpleSkin/glTF/SimpleSkin.gltf", "AnimatedMorphCube/glTF-Binary/AnimatedMorphCube.glb",
                             "SimpleMorph/glTF/SimpleMorph.gltf"}) {
        SCOPED_TRACE(file);
        if (!fs::exists(kSharedScenes / file)) GTEST_SKIP() << "shared scenes missing";
        LoadResult r = loadScene(kSharedScenes / file);
        ASSERT_TRUE(r.ok()) << r.error;
        for (const std::string& w : r.warnings) EXPECT_EQ(w.find("ignored"), std::string::npos) << w;
        Scene& s = *r.scene;
        bool deformed = false;
        for (double t : {0.3, 0.9, 1.7}) {
            animateScene(s, t);
            for (const MeshInstance& instance : s.instances) {
                if (!isDeformed(s, instance)) continue;
                deformed = true;
                const Pose pose = instancePose(s, instance);
                for (const Primitive& p : s.meshes[std::size_t(instance.mesh)].primitives) {
                    std::vector<glm::vec3> positions;
                    deformPrimitive(p, pose, positions, nullptr);
                    const double slack = 1e-4 * glm::length(instance.worldBounds.extent());
                    for (const glm::vec3& v : positions)
                        ASSERT_TRUE(contains(instance.worldBounds, glm::dvec3(instance.world * glm::dvec4(glm::dvec3(v), 1.0)), slack));
                }
            }
        }
        EXPECT_TRUE(deformed);
    }
}

// Fox has three clips (Survey, Walk, Run) that animate the same joints: one clip at a time, the
// same time in Walk and in Run is another pose (other skinned bounds), all at once is a third, and
// going back to a clip from the rest pose gives exactly its pose again.
TEST(Skinning, FoxClipsPlayOneAtATime) {
    Scene s = loadShared("Fox/glTF-Binary/Fox.glb");
    if (s.instances.empty()) GTEST_SKIP() << "shared scenes missing";
    ASSERT_EQ(s.animations.size(), 3u);
    const RestPose rest = captureRestPose(s);
    auto boundsAt = [&](int clip) {
        restorePose(s, rest);
        animateScene(s, 0.5, clip);
        return s.bounds;
    };
    const Aabb walk = boundsAt(1), run = boundsAt(2), all = boundsAt(kAllClips), walkAgain = boundsAt(1);
    auto differ = [](const Aabb& a, const Aabb& b) { return glm::length(a.min - b.min) + glm::length(a.max - b.max); };
    const double size = glm::length(walk.extent());
    EXPECT_GT(differ(walk, run), 1e-3 * size);
    EXPECT_GT(differ(walk, all), 1e-3 * size);
    EXPECT_EQ(differ(walk, walkAgain), 0.0);
    // A clip past the last plays the first; the loop of one clip is that clip's length.
    EXPECT_EQ(resolveClip(s, 7), 0);
    EXPECT_EQ(sceneAnimationDuration(s, 1), animationDuration(s.animations[1]));
    EXPECT_LT(sceneAnimationDuration(s, 1), sceneAnimationDuration(s, kAllClips));
}

// A two-joint skin on the fixture's triangle: JOINTS_0 / WEIGHTS_0 appended to its buffer.
class SkinFiles : public LoaderFiles {
protected:
    json j = triangleJson();
    Bytes bin = triangleBin();
    void SetUp() override {
        LoaderFiles::SetUp();
        const std::size_t jointsAt = bin.size();
        for (int v = 0; v < 3; ++v)
            for (std::uint16_t k : {std::uint16_t(v == 2 ? 1 : 0), std::uint16_t(0), std::uint16_t(0), std::uint16_t(0)})
                append(bin, k);
        const std::size_t weightsAt = bin.size();
        for (int v = 0; v < 3; ++v)
            for (float w : {1.0f, 0.0f, 0.0f, 0.0f}) append(bin, w);
        j["buffers"][0]["byteLength"] = bin.size();
        j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", jointsAt}, {"byteLength", 24}});
        j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", weightsAt}, {"byteLength", 48}});
        j["accessors"].push_back({{"bufferView", 2}, {"componentType", 5123}, {"count", 3}, {"type", "VEC4"}});
        j["accessors"].push_back({{"bufferView", 3}, {"componentType", 5126}, {"count", 3}, {"type", "VEC4"}});
        j["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"] = 2;
        j["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = 3;
        j["nodes"][0]["skin"] = 0;
        j["nodes"].push_back({{"translation", {0.0, 3.0, 0.0}}});
        j["nodes"].push_back(json::object());
        j["scenes"][0]["nodes"] = {0, 1, 2};
        j["skins"] = {{{"joints", {1, 2}}}};
    }
};

TEST_F(SkinFiles, ASkinWithoutInverseBindMatricesUsesIdentity) {
    const Scene s = expectLoads(writeGltf(j, bin));
    ASSERT_EQ(s.skins.size(), 1u);
    // Vertices 0 and 1 (y = 0) follow joint 0 (node 1, three units up); vertex 2 (y = 1) joint 1
    // (node 2, at the origin).
    EXPECT_NEAR(s.instances[0].worldBounds.min.y, 1.0, 1e-9);
    EXPECT_NEAR(s.instances[0].worldBounds.max.y, 3.0, 1e-9);
}

TEST_F(SkinFiles, AJointBeyondTheSkinIsRefused) {
    j["skins"][0]["joints"] = {1};
    expectError(writeGltf(j, bin), "has 1 joints");
}

TEST_F(SkinFiles, AMissingJointNodeIsRefused) {
    j["skins"][0]["joints"] = {1, 7};
    expectError(writeGltf(j, bin), "joint node 7 does not exist");
}

TEST_F(SkinFiles, WeightsOfTheWrongCountAreRefused) {
    j["accessors"][3]["count"] = 2;
    expectError(writeGltf(j, bin), "WEIGHTS_0 has 2 entries");
}

TEST_F(SkinFiles, TooFewInverseBindMatricesAreRefused) {
    j["accessors"].push_back({{"bufferView", 0}, {"componentType", 5126}, {"count", 1}, {"type", "MAT4"}});
    j["skins"][0]["inverseBindMatrices"] = 4;
    expectError(writeGltf(j, bin), "fewer matrices");
}

}  // namespace
}  // namespace shadowlab
