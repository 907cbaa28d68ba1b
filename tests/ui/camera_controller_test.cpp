// The viewer's orbit / fly camera (GL-free, GLFW-free): input deltas in, CameraSettings out.
#include "camera_controller.h"
#include "frame_setup.h"

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
    in.dt = 0.5;
    in.move = {0.0, 0.0, 1.0};  // W
    controller.apply(c, in);
    EXPECT_NEAR(c.position.z, 10.0 - 4.0 * 0.5, 1e-9);
    EXPECT_NEAR(c.position.x, 0.0, 1e-9);
    in.move = {1.0, 0.0, 0.0};  // D: right of -Z is +X
    in.fast = true;             // shift: 4x
    controller.apply(c, in);
    EXPECT_NEAR(c.position.x, 4.0 * 4.0 * 0.5, 1e-9);
}

TEST(CameraController, OrbitKeepsThePivotInFront) {
    CameraController controller;
    controller.orbitDistance = 5.0;
    CameraSettings c = startCamera();
    const glm::dvec3 pivot = c.position + cameraForward(c) * 5.0;
    CameraInput in;
    in.orbitDelta = {150.0, -60.0};
    controller.apply(c, in);
    EXPECT_NEAR(glm::distance(c.position + cameraForward(c) * 5.0, pivot), 0.0, 1e-9);
    EXPECT_NE(c.yawDeg, -90.0);
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
    in.dt = 1.0;
    in.move = {1.0, 0.0, 0.0};
    const glm::dvec3 before = c.position;
    controller.apply(c, in);
    EXPECT_TRUE(std::isfinite(c.position.x) && std::isfinite(c.position.z));
    EXPECT_NEAR(glm::distance(c.position, before), c.moveSpeed, 1e-6);
}

TEST(CameraController, ScrollDolliesTowardsThePivot) {
    CameraController controller;
    controller.orbitDistance = 10.0;
    CameraSettings c = startCamera();
    CameraInput in;
    in.scroll = 2.0;  // two notches: 2 x a tenth of the way
    controller.apply(c, in);
    EXPECT_NEAR(c.position.z, 10.0 - 2.0, 1e-9);
}

}  // namespace
}  // namespace shadowlab::app
