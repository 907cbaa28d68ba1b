// The instance BVH keeps exactly what the linear loop keeps, for the view frustum and for caster
// culling against B, after builds and refits, and visits far fewer nodes than there are
// instances when little is visible.
#include "culling/instance_culling.h"

#include <gtest/gtest.h>

#include <random>

namespace shadowlab {
namespace {

Scene boxScene(std::size_t count, std::uint32_t seed, double spread = 100.0) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-spread, spread), size(0.05, 3.0);
    Scene scene;
    scene.instances.resize(count);
    for (MeshInstance& inst : scene.instances) {
        const glm::dvec3 c{pos(rng), pos(rng) * 0.1, pos(rng)};
        const glm::dvec3 h{size(rng), size(rng), size(rng)};
        inst.worldBounds.extend(c - h);
        inst.worldBounds.extend(c + h);
        scene.bounds.extend(inst.worldBounds);
    }
    return scene;
}

Settings cameraAt(glm::dvec3 eye, double yaw, double pitch, double farPlane = 80.0) {
    Settings s;
    s.camera.position = eye;
    s.camera.yawDeg = yaw;
    s.camera.pitchDeg = pitch;
    s.camera.farPlane = farPlane;
    return s;
}

InstanceList linearVisible(const Scene& scene, const ClipPlanes& planes) {
    InstanceList out;
    for (std::size_t i = 0; i < scene.instances.size(); ++i)
        if (boxMayBeVisible(planes, scene.instances[i].worldBounds)) out.push_back(std::uint32_t(i));
    return out;
}

ClipPlanes planesOf(const Settings& s) {
    const ViewFrustum v = viewFrustum(s.camera, 16.0 / 9.0);
    return clipPlanes(v.projectionMatrix() * v.viewMatrix());
}

TEST(InstanceBvh, NoInstancesGiveAnEmptyTreeAndNothingKept) {
    InstanceBvh bvh;
    bvh.build({});
    InstanceList kept;
    bvh.query([](const Aabb&) { return true; }, kept);
    EXPECT_TRUE(bvh.empty());
    EXPECT_TRUE(kept.empty());
}

TEST(InstanceBvh, EmptyBoxesAreLeftOutAndAnAcceptAllQueryKeepsTheRestAscending) {
    std::vector<Aabb> boxes(10);
    for (int i = 0; i < 10; ++i)
        if (i % 3 != 0) boxes[i].extend(glm::dvec3(i)), boxes[i].extend(glm::dvec3(i + 0.5));
    InstanceBvh bvh;
    bvh.build(boxes);
    InstanceList kept;
    bvh.query([](const Aabb&) { return true; }, kept);
    EXPECT_EQ(kept, (InstanceList{1, 2, 4, 5, 7, 8}));
}

TEST(InstanceBvh, AllCentroidsEqualStillBuildsABoundedTree) {
    std::vector<Aabb> boxes(1000);
    for (Aabb& b : boxes) b.extend(glm::dvec3(-1)), b.extend(glm::dvec3(1));
    InstanceBvh bvh;
    bvh.build(boxes);
    EXPECT_LE(bvh.depth(), 20u);
    InstanceList kept;
    bvh.query([](const Aabb&) { return true; }, kept);
    EXPECT_EQ(kept.size(), 1000u);
}

TEST(InstanceCulling, ViewFrustumThroughTheTreeKeepsExactlyWhatTheLinearLoopKeeps) {
    const Scene scene = boxScene(5000, 7);
    InstanceCuller culler;
    culler.setScene(scene);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> pos(-120.0, 120.0), yaw(-180.0, 180.0), pitch(-60.0, 60.0);
    for (int k = 0; k < 50; ++k) {
        const ClipPlanes planes = planesOf(cameraAt({pos(rng), pos(rng) * 0.1, pos(rng)}, yaw(rng), pitch(rng)));
        InstanceList tree, linear;
        culler.visible(scene, planes, true, tree);
        culler.visible(scene, planes, false, linear);
        EXPECT_EQ(tree, linear) << "camera " << k;
        EXPECT_EQ(tree, linearVisible(scene, planes));
    }
}

TEST(InstanceCulling, CastersThroughTheTreeKeepExactlyWhatCasterCanReachKeeps) {
    const Scene scene = boxScene(5000, 11);
    InstanceCuller culler;
    culler.setScene(scene);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> pos(-90.0, 90.0), yaw(-180.0, 180.0), pitch(-50.0, 20.0);
    std::uniform_real_distribution<double> azimuth(0.0, 360.0), elevation(10.0, 85.0);
    int nonTrivial = 0;
    for (int k = 0; k < 40; ++k) {
        Settings s = cameraAt({pos(rng), 5.0, pos(rng)}, yaw(rng), pitch(rng));
        s.method = k % 2 ? ShadowMethod::Lispsm : ShadowMethod::SsmFocused;
        s.light.source = LightSource::Sun;
        s.light.azimuthDeg = azimuth(rng);
        s.light.elevationDeg = elevation(rng);
        const ViewFrustum view = viewFrustum(s.camera, 16.0 / 9.0);
        const LightFrame light = resolveLight(scene, s.light, 0.0);
        const ShadowSetup setup =
            computeShadowSetup(view, shadowLight(light), scene.bounds, shadowParams(s, view, scene.bounds));
        ASSERT_TRUE(setup.valid);
        InstanceList tree, linear;
        culler.casters(scene, setup, true, tree);
        culler.casters(scene, setup, false, linear);
        EXPECT_EQ(tree, linear) << "view " << k;
        nonTrivial += !tree.empty() && tree.size() < scene.instances.size();
    }
    EXPECT_GT(nonTrivial, 20);  // the cases do cull something and keep something
}

TEST(InstanceCulling, RefitAfterMovingInstancesMatchesTheLinearLoopAndAFreshBuild) {
    Scene scene = boxScene(3000, 13);
    InstanceCuller refitted;
    refitted.setScene(scene);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> move(-30.0, 30.0);
    for (int step = 0; step < 3; ++step) {
        for (MeshInstance& inst : scene.instances) {
            const glm::dvec3 d{move(rng), 0.0, move(rng)};
            inst.worldBounds.min += d;
            inst.worldBounds.max += d;
        }
        scene.instances[std::size_t(step)].worldBounds = Aabb{};  // one instance vanishes: rebuild path
        refitted.updateInstances(scene);
        InstanceCuller fresh;
        fresh.setScene(scene);
        for (double yaw : {-90.0, 0.0, 45.0, 170.0}) {
            const ClipPlanes planes = planesOf(cameraAt({0.0, 3.0, 0.0}, yaw, -10.0));
            InstanceList a, b;
            refitted.visible(scene, planes, true, a);
            fresh.visible(scene, planes, true, b);
            EXPECT_EQ(a, linearVisible(scene, planes));
            EXPECT_EQ(a, b);
        }
    }
}

TEST(InstanceBvh, ANarrowViewTestsFarFewerBoxesThanThereAreInstances) {
    // The point of the hierarchy: the cost follows what is near the frustum, not the scene size.
    const Scene scene = boxScene(100000, 19, 1000.0);
    InstanceCuller culler;
    culler.setScene(scene);
    const ClipPlanes planes = planesOf(cameraAt({0.0, 2.0, 0.0}, 30.0, -5.0, 60.0));
    std::size_t tests = 0;
    InstanceList kept;
    culler.hierarchy().query(
        [&](const Aabb& box) {
            ++tests;
            return boxMayBeVisible(planes, box);
        },
        kept);
    EXPECT_EQ(kept, linearVisible(scene, planes));
    EXPECT_FALSE(kept.empty());
    EXPECT_LT(tests, scene.instances.size() / 20);
}

}  // namespace
}  // namespace shadowlab
