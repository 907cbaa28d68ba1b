// The viewer's redraw decision for a playing animation (frame/animation_redraw.h): a walker that
// moves in the view, behind the camera, or above the visible ground where its shadow falls (out of
// view but inside B), stepped by the real animation sampler.
#include "frame/animation_redraw.h"
#include "frame/frame_setup.h"
#include "scenes/animation.h"
#include "scenes/gltf_loader.h"

#include <gtest/gtest.h>

namespace shadowlab {
namespace {

Mesh boxMesh(glm::vec3 lo, glm::vec3 hi) {
    Primitive p;
    for (int c = 0; c < 8; ++c) p.positions.push_back({c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z});
    p.normals.assign(8, glm::vec3(0, 1, 0));
    p.indices = {0, 1, 3, 0, 3, 2, 4, 7, 5, 4, 6, 7};
    for (const glm::vec3& v : p.positions) p.bounds.extend(glm::dvec3(v));
    Mesh m;
    m.primitives.push_back(std::move(p));
    return m;
}

// A 40 m ground slab at y = 0 and a unit box (node 1) that an animation moves from `from` to `to`
// over one second; node 2 carries the scene's only light.
Scene walkerScene(glm::vec3 from, glm::vec3 to) {
    Scene scene;
    scene.meshes = {boxMesh({-20, -0.1f, -20}, {20, 0, 20}), boxMesh(glm::vec3(-0.5f), glm::vec3(0.5f))};
    scene.nodes.resize(3);
    scene.nodes[0].mesh = 0;
    scene.nodes[1].mesh = 1;
    scene.nodes[1].translation = from;
    scene.nodes[2].light = 0;
    scene.lights.resize(1);
    scene.lights[0].node = 2;
    scene.roots = {0, 1, 2};
    AnimationChannel walk;
    walk.node = 1;
    walk.times = {0.0f, 1.0f};
    walk.values = {glm::vec4(from, 0.0f), glm::vec4(to, 0.0f)};
    scene.animations.push_back({"walk", {walk}, 1.0f});
    updateWorldTransforms(scene);
    return scene;
}

// The default camera (y = 2 at z = 10, looking along -Z, 60 degree fov, 70 m far) and, with
// `shadowed`, the B of a light straight down (focused SSM).
WatchedVolumes watched(const Scene& scene, bool shadowed) {
    Settings s;
    s.method = ShadowMethod::SsmFocused;
    const double aspect = 16.0 / 9.0;
    const ViewFrustum view = viewFrustum(s.camera, aspect);
    ShadowLight sun;
    sun.direction = {0.0, -1.0, 0.0};
    const ShadowSetup setup = computeShadowSetup(view, sun, scene.bounds, shadowParams(s, view, scene.bounds));
    EXPECT_TRUE(setup.valid);
    return watchedVolumes(s.camera, aspect, shadowed, setup, CascadeSetup{});
}

// Does any step of the walk (0.1 s apart) ask for a redraw?
bool walkNeedsRedraw(Scene& scene, const WatchedVolumes& volumes) {
    bool any = false;
    for (double t = 0.1; t <= 1.0; t += 0.1) {
        const PoseSnapshot before = snapshotPose(scene);
        animateScene(scene, t);
        EXPECT_EQ(movedInstances(before, scene), std::vector<std::uint32_t>{1}) << "t = " << t;
        any = any || animationNeedsRedraw(before, scene, volumes);
    }
    return any;
}

TEST(AnimationRedraw, AWalkerInViewRedraws) {
    Scene scene = walkerScene({0, 0.5f, 0}, {1, 0.5f, 0});
    EXPECT_TRUE(walkNeedsRedraw(scene, watched(scene, false)));
}

TEST(AnimationRedraw, AWalkerBehindTheCameraAndOutsideBDoesNot) {
    Scene scene = walkerScene({0, 0.5f, 20}, {1, 0.5f, 20});
    EXPECT_FALSE(walkNeedsRedraw(scene, watched(scene, true)));
    // The same walk counts when something shows the whole scene (observer inset, compare views).
    Scene again = walkerScene({0, 0.5f, 20}, {1, 0.5f, 20});
    EXPECT_TRUE(walkNeedsRedraw(again, WatchedVolumes{}));
}

TEST(AnimationRedraw, AWalkerOutOfViewThatShadowsTheVisibleGroundRedrawsOnlyWithShadows) {
    // 15 m above the origin: above the frustum (its top is 7.8 m high there), straight above
    // visible ground under a light straight down, so inside B.
    Scene scene = walkerScene({0, 15, 0}, {1, 15, 0});
    EXPECT_FALSE(walkNeedsRedraw(scene, watched(scene, false)));
    Scene shadowed = walkerScene({0, 15, 0}, {1, 15, 0});
    EXPECT_TRUE(walkNeedsRedraw(shadowed, watched(shadowed, true)));
}

TEST(AnimationRedraw, APoseThatMovesNothingNeverRedrawsAndAMovingLightAlwaysDoes) {
    Scene scene = walkerScene({0, 0.5f, 0}, {1, 0.5f, 0});
    animateScene(scene, 2.0);  // past the last key: the pose holds
    PoseSnapshot before = snapshotPose(scene);
    animateScene(scene, 3.0);
    EXPECT_TRUE(movedInstances(before, scene).empty());
    EXPECT_FALSE(animationNeedsRedraw(before, scene, WatchedVolumes{}));
    // The light's node moves (behind the camera): shading and every shadow change.
    Scene hidden = walkerScene({0, 0.5f, 20}, {0, 0.5f, 20});
    before = snapshotPose(hidden);
    hidden.nodes[2].translation = {0, 5, 30};
    updateWorldTransforms(hidden);
    EXPECT_TRUE(animationNeedsRedraw(before, hidden, watched(hidden, true)));
}

TEST(AnimationRedraw, ASkinnedMeshMovesWithItsJointsAndADifferentSceneRedraws) {
    Scene scene = walkerScene({0, 0.5f, 20}, {0, 0.5f, 20});
    scene.skins.push_back({"rig", {2}, {glm::dmat4(1.0)}, -1});
    scene.nodes[1].skin = 0;  // the box follows node 2 (its bounds are left alone here)
    PoseSnapshot before = snapshotPose(scene);
    scene.nodes[2].world[3] = glm::dvec4(0, 1, 0, 1);
    EXPECT_EQ(movedInstances(before, scene), std::vector<std::uint32_t>{1});
    before.instanceBounds.pop_back();
    EXPECT_TRUE(animationNeedsRedraw(before, scene, watched(scene, true)));
}

}  // namespace
}  // namespace shadowlab
