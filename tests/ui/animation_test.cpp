// The GL-free animation sampler: hand-built channels (linear, step, cubic spline, rotations along
// the short arc, clamping, looping, bad input) and the real BoxAnimated sample from Khronos.
#include "scenes/animation.h"
#include "scenes/gltf_loader.h"

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <filesystem>

namespace shadowlab {
namespace {

AnimationChannel channel(AnimationPath path, Interpolation interpolation, std::vector<float> times,
                         std::vector<glm::vec4> values) {
    AnimationChannel c;
    c.node = 0;
    c.path = path;
    c.interpolation = interpolation;
    c.times = std::move(times);
    c.values = std::move(values);
    return c;
}

glm::vec4 quatXyzw(const glm::quat& q) { return {q.x, q.y, q.z, q.w}; }

void expectNear(const glm::vec4& a, const glm::vec4& b, float tol = 1e-5f) {
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(a[i], b[i], tol) << "component " << i;
}

// The same rotation (q and -q are one rotation): compare by rotating a vector.
void expectSameRotation(const glm::vec4& a, const glm::quat& b) {
    const glm::quat qa(a.w, a.x, a.y, a.z);
    for (const glm::vec3 v : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)}) {
        const glm::vec3 ra = qa * v, rb = b * v;
        EXPECT_NEAR(glm::distance(ra, rb), 0.0f, 1e-4f);
    }
}

TEST(AnimationSampler, LinearTranslationInterpolatesAndClamps) {
    const auto c = channel(AnimationPath::Translation, Interpolation::Linear, {1.0f, 3.0f},
                           {glm::vec4(0, 0, 0, 0), glm::vec4(4, -2, 8, 0)});
    expectNear(sampleChannel(c, 2.0).value, {2, -1, 4, 0});
    expectNear(sampleChannel(c, 1.5).value, {1, -0.5f, 2, 0});
    expectNear(sampleChannel(c, -5.0).value, {0, 0, 0, 0});   // before the first key: the first value
    expectNear(sampleChannel(c, 99.0).value, {4, -2, 8, 0});  // after the last key: the last value
}

TEST(AnimationSampler, StepHoldsThePreviousKey) {
    const auto c = channel(AnimationPath::Scale, Interpolation::Step, {0.0f, 1.0f, 2.0f},
                           {glm::vec4(1), glm::vec4(2), glm::vec4(3)});
    expectNear(sampleChannel(c, 0.99).value, glm::vec4(1));
    expectNear(sampleChannel(c, 1.0).value, glm::vec4(2));
    expectNear(sampleChannel(c, 1.7).value, glm::vec4(2));
    expectNear(sampleChannel(c, 2.5).value, glm::vec4(3));
}

TEST(AnimationSampler, LinearRotationIsSlerpOnTheShortArc) {
    const glm::quat a = glm::angleAxis(0.0f, glm::vec3(0, 1, 0));
    const glm::quat b = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
    auto c = channel(AnimationPath::Rotation, Interpolation::Linear, {0.0f, 1.0f}, {quatXyzw(a), quatXyzw(b)});
    // Slerp, not lerp: a quarter of the time is exactly a quarter of the angle.
    expectSameRotation(sampleChannel(c, 0.25).value, glm::angleAxis(glm::radians(22.5f), glm::vec3(0, 1, 0)));
    expectSameRotation(sampleChannel(c, 0.5).value, glm::angleAxis(glm::radians(45.0f), glm::vec3(0, 1, 0)));
    // The second key stored as -q (same rotation): still the 90 degree short way, not 270.
    c.values[1] = -quatXyzw(b);
    expectSameRotation(sampleChannel(c, 0.5).value, glm::angleAxis(glm::radians(45.0f), glm::vec3(0, 1, 0)));
    EXPECT_NEAR(glm::length(sampleChannel(c, 0.3).value), 1.0f, 1e-5f);
}

TEST(AnimationSampler, CubicSplineIsHermiteWithTangentsScaledByTheInterval) {
    // in-tangent, value, out-tangent per key; interval length 2 s.
    const glm::vec4 v0(0, 0, 0, 0), b0(1, 0, 0, 0), a1(-1, 0, 0, 0), v1(1, 0, 0, 0);
    const auto c = channel(AnimationPath::Translation, Interpolation::CubicSpline, {0.0f, 2.0f},
                           {glm::vec4(9), v0, b0, a1, v1, glm::vec4(9)});
    for (double t : {0.0, 0.3, 1.0, 1.6, 2.0}) {
        const float s = float(t / 2.0), dt = 2.0f;
        const float expected = (2 * s * s * s - 3 * s * s + 1) * v0.x + (s * s * s - 2 * s * s + s) * dt * b0.x +
                               (-2 * s * s * s + 3 * s * s) * v1.x + (s * s * s - s * s) * dt * a1.x;
        EXPECT_NEAR(sampleChannel(c, t).value.x, expected, 1e-5f) << "t = " << t;
    }
    // Hand-computed midpoint: 0.5 v0 + 0.125*2*1 + 0.5*1 + (-0.125)*2*(-1) = 1.0.
    EXPECT_NEAR(sampleChannel(c, 1.0).value.x, 1.0f, 1e-5f);
    // The keys themselves are hit exactly (the tangent entries 9 are never returned as values).
    expectNear(sampleChannel(c, 0.0).value, v0);
    expectNear(sampleChannel(c, 2.0).value, v1);
}

TEST(AnimationSampler, CubicSplineRotationIsRenormalised) {
    const glm::quat a(1, 0, 0, 0), b = glm::angleAxis(glm::radians(120.0f), glm::vec3(0, 0, 1));
    const auto c = channel(AnimationPath::Rotation, Interpolation::CubicSpline, {0.0f, 1.0f},
                           {glm::vec4(0), quatXyzw(a), glm::vec4(0), glm::vec4(0), quatXyzw(b), glm::vec4(0)});
    EXPECT_NEAR(glm::length(sampleChannel(c, 0.5).value), 1.0f, 1e-5f);
}

TEST(AnimationSampler, BadChannelsAreRejectedNotRead) {
    EXPECT_FALSE(sampleChannel(channel(AnimationPath::Translation, Interpolation::Linear, {}, {}), 0.0).valid);
    // Cubic spline needs three values per key.
    EXPECT_FALSE(sampleChannel(channel(AnimationPath::Translation, Interpolation::CubicSpline, {0.0f, 1.0f},
                                       {glm::vec4(0), glm::vec4(1)}),
                               0.5)
                     .valid);
    EXPECT_FALSE(
        sampleChannel(channel(AnimationPath::Translation, Interpolation::Linear, {0.0f}, {glm::vec4(1)}), std::nan(""))
            .valid);
    // A zero quaternion key becomes the identity instead of NaN.
    const auto zero = channel(AnimationPath::Rotation, Interpolation::Step, {0.0f}, {glm::vec4(0)});
    expectNear(sampleChannel(zero, 0.0).value, {0, 0, 0, 1});
}

TEST(AnimationSampler, LoopTime) {
    EXPECT_DOUBLE_EQ(loopTime(5.5, 2.0), 1.5);
    EXPECT_DOUBLE_EQ(loopTime(-0.5, 2.0), 1.5);
    EXPECT_DOUBLE_EQ(loopTime(3.0, 0.0), 0.0);
}

TEST(AnimationSampler, ApplySkipsMissingAndMatrixNodes) {
    Scene scene;
    scene.nodes.resize(2);
    scene.nodes[1].hasMatrix = true;
    Animation anim;
    auto c = channel(AnimationPath::Translation, Interpolation::Linear, {0.0f, 1.0f}, {glm::vec4(0), glm::vec4(2)});
    anim.channels.push_back(c);  // node 0: applied
    c.node = 1;
    anim.channels.push_back(c);  // matrix node: skipped
    c.node = 7;
    anim.channels.push_back(c);  // no such node: skipped
    scene.animations.push_back(anim);
    EXPECT_EQ(applyAnimations(scene, 0.5), 1);
    EXPECT_NEAR(scene.nodes[0].translation.x, 1.0f, 1e-6f);
    EXPECT_EQ(scene.nodes[1].translation, glm::vec3(0.0f));
    // Looping: 1.25 s into a 1 s animation is 0.25 s.
    applyAnimations(scene, 1.25);
    EXPECT_NEAR(scene.nodes[0].translation.x, 0.5f, 1e-6f);
}

// Khronos BoxAnimated: node 0 translates (0 -> 2.52 -> 2.52 -> 0 in y at 0, 1.25, 2.5, 3.708 s),
// node 2 rotates from (0,0,0,-1) to (1,0,0,0) between 1.25 and 2.5 s (180 degrees about x).
class BoxAnimatedTest : public ::testing::Test {
protected:
    void SetUp() override {
        const std::filesystem::path file =
            std::filesystem::path(SHADOWLAB_SHARED_SCENES) / "BoxAnimated/glTF/BoxAnimated.gltf";
        if (!std::filesystem::exists(file)) GTEST_SKIP() << "missing " << file;
        LoadResult r = loadScene(file);
        ASSERT_TRUE(r.ok()) << r.error;
        scene = std::move(*r.scene);
    }
    Scene scene;
};

TEST_F(BoxAnimatedTest, ChannelsMatchTheFile) {
    ASSERT_EQ(scene.animations.size(), 1u);
    EXPECT_NEAR(animationDuration(scene.animations[0]), 3.7083, 1e-3);
    applyAnimations(scene, 0.625);
    EXPECT_NEAR(scene.nodes[0].translation.y, 1.26f, 1e-4f);
    applyAnimations(scene, 1.875);
    EXPECT_NEAR(scene.nodes[0].translation.y, 2.52f, 1e-4f);
    // Halfway through a 180 degree turn about x: local +y lies along z. (The two keys are 180
    // degrees apart, so the stored w = 4.5e-11 of the second key picks the direction: the spec's
    // slerp takes the sign of the dot product, here negative, and turns +y to +z.)
    const glm::vec3 up = scene.nodes[2].rotation * glm::vec3(0, 1, 0);
    EXPECT_NEAR(glm::distance(up, glm::vec3(0, 0, 1)), 0.0f, 1e-4f);
    const glm::vec3 axis = scene.nodes[2].rotation * glm::vec3(1, 0, 0);
    EXPECT_NEAR(glm::distance(axis, glm::vec3(1, 0, 0)), 0.0f, 1e-4f);
    // Before the first rotation key: the first value; after the last: 180 degrees.
    applyAnimations(scene, 1.0);
    EXPECT_NEAR(glm::distance(scene.nodes[2].rotation * glm::vec3(0, 1, 0), glm::vec3(0, 1, 0)), 0.0f, 1e-4f);
    applyAnimations(scene, 3.0);
    EXPECT_NEAR(glm::distance(scene.nodes[2].rotation * glm::vec3(0, 1, 0), glm::vec3(0, -1, 0)), 0.0f, 1e-4f);
    EXPECT_NEAR(scene.nodes[0].translation.y, 2.52f * float(1.0 - (3.0 - 2.5) / (3.708333 - 2.5)), 1e-3f);
}

TEST_F(BoxAnimatedTest, AnimatingMovesTheInstancesAndTheBounds) {
    ASSERT_TRUE(animateScene(scene, 0.0));
    const Aabb before = scene.bounds;
    ASSERT_TRUE(animateScene(scene, 1.875));
    const Aabb after = scene.bounds;
    // The translated part is lifted by 2.52 at its peak: the scene bounds grow upwards.
    EXPECT_GT(after.max.y, before.max.y + 1.0);
    // A static scene is left alone.
    Scene still;
    EXPECT_FALSE(animateScene(still, 1.0));
}

}  // namespace
}  // namespace shadowlab
