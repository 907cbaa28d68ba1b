// The viewer's orbit / fly camera (GL-free, GLFW-free): input deltas in, CameraSettings out.
#include "viewer/camera_controller.h"
#include "frame/frame_setup.h"

#include <gtest/gtest.h>

namespace shadowlab::app {
namespace {

CameraSettings startCamera() {
    CameraSettings c;
    c.position = {0.0, 2.0, 10.0};
    c.yawDeg = -90.0;  // looking along -Z
    c.pitchDeg = 0.0;
    c.moveSpeed = 4.0;
    return c;
}

TEST(CameraController, FlyMovesAlongTheViewAxesAtTheSetSpeed) {
    CameraController controller;
    CameraSettings c = startCamera();
    CameraInput in;
    in.flight = {0.0, 0.0, 0.5};  // W held for 0.5 s
    controller.apply(c, in);
    EXPECT_NEAR(c.position.z, 10.0 - 4.0 * 0.5, 1e-9);
    EXPECT_NEAR(c.position.x, 0.0, 1e-9);
    in.flight = {0.5, 0.0, 0.0};  // D: right of -Z is +X
    in.fast = true;             // shift: 4x
    controller.apply(c, in);
    EXPECT_NEAR(c.position.x, 4.0 * 4.0 * 0.5, 1e-9);
}

TEST(CameraController, OrbitTurnsAroundThePivotAndKeepsItOnScreen) {
    CameraController controller;
    controller.pivot = {1.0, 0.5, -3.0};  // the scene centre, off the view axis
    CameraSettings c = startCamera();
    auto local = [&](const CameraSettings& cam) {
        const glm::dvec3 f = cameraForward(cam);
        const glm::dvec3 r = glm::normalize(glm::cross(f, glm::dvec3(0, 1, 0)));
        const glm::dvec3 d = controller.pivot - cam.position;
        return glm::dvec3(glm::dot(d, r), glm::dot(d, glm::cross(r, f)), glm::dot(d, f));
    };
    const glm::dvec3 before = local(c);
    const double distance = glm::distance(c.position, controller.pivot);
    CameraInput in;
    in.orbitDelta = {150.0, -60.0};
    controller.apply(c, in);
    EXPECT_NE(c.yawDeg, -90.0);
    EXPECT_NEAR(glm::distance(c.position, controller.pivot), distance, 1e-9);
    EXPECT_NEAR(glm::distance(local(c), before), 0.0, 1e-9);  // same place in the camera's frame
}

TEST(CameraController, FramedCameraSeesEveryCornerOfTheBounds) {
    Aabb bounds;
    bounds.extend(glm::dvec3(-0.2, 0.0, -0.1));
    bounds.extend(glm::dvec3(0.3, 0.4, 0.2));  // a small model far from a camera made for a big scene
    CameraSettings c = startCamera();
    c.position = {40.0, 30.0, 80.0};
    for (double aspect : {0.5, 1.0, 16.0 / 9.0}) {
        const CameraSettings framed = framedCamera(c, bounds, aspect);
        EXPECT_EQ(framed.yawDeg, c.yawDeg);  // the view direction is kept
        const ViewFrustum v = viewFrustum(framed, aspect);
        const glm::dmat4 m = v.projectionMatrix() * v.viewMatrix();
        for (int i = 0; i < 8; ++i) {
            const glm::dvec4 clip = m * glm::dvec4(bounds.corner(i), 1.0);
            ASSERT_GT(clip.w, 0.0);
            EXPECT_LE(std::abs(clip.x / clip.w), 1.0) << "aspect " << aspect << " corner " << i;
            EXPECT_LE(std::abs(clip.y / clip.w), 1.0) << "aspect " << aspect << " corner " << i;
            EXPECT_LE(std::abs(clip.z / clip.w), 1.0) << "aspect " << aspect << " corner " << i;
        }
        // Tight: the bounds' sphere touches the frustum, so the model fills a good part of the view.
        EXPECT_LT(glm::distance(framed.position, bounds.center()), 3.0 * glm::length(bounds.extent()));
    }
    EXPECT_EQ(framedCamera(c, Aabb{}, 1.0), c);  // empty bounds: unchanged
}

TEST(CameraController, LookClampsThePitchShortOfTheVertical) {
    CameraController controller;
    CameraSettings c = startCamera();
    CameraInput in;
    in.lookDelta = {0.0, -1e5};  // drag far up
    controller.apply(c, in);
    EXPECT_LE(c.pitchDeg, 89.0);
    EXPECT_GT(c.pitchDeg, 80.0);
    // Still a valid frame: moving right is well defined.
    in = {};
    in.flight = {1.0, 0.0, 0.0};
    const glm::dvec3 before = c.position;
    controller.apply(c, in);
    EXPECT_TRUE(std::isfinite(c.position.x) && std::isfinite(c.position.z));
    EXPECT_NEAR(glm::distance(c.position, before), c.moveSpeed, 1e-6);
}

TEST(CameraController, ScrollDolliesTowardsThePivot) {
    CameraController controller;
    controller.pivot = {0.0, 2.0, 0.0};  // 10 in front of the camera
    CameraSettings c = startCamera();
    CameraInput in;
    in.scroll = 2.0;  // two notches: 2 x a tenth of the way
    controller.apply(c, in);
    EXPECT_NEAR(c.position.z, 10.0 - 2.0, 1e-9);
}

}  // namespace
}  // namespace shadowlab::app
