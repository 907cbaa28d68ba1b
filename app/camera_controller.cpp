#include "camera_controller.h"

#include "frame_setup.h"

#include <algorithm>

namespace shadowlab::app {

void CameraController::apply(CameraSettings& camera, const CameraInput& in) const {
    constexpr double kDegreesPerPixel = 0.2;
    glm::dvec3 forward = cameraForward(camera);
    if (in.orbitDelta != glm::dvec2(0.0)) {
        const glm::dvec3 pivot = camera.position + forward * orbitDistance;
        camera.yawDeg += in.orbitDelta.x * kDegreesPerPixel;
        camera.pitchDeg = std::clamp(camera.pitchDeg - in.orbitDelta.y * kDegreesPerPixel, -89.0, 89.0);
        forward = cameraForward(camera);
        camera.position = pivot - forward * orbitDistance;
    }
    camera.yawDeg += in.lookDelta.x * kDegreesPerPixel;
    camera.pitchDeg = std::clamp(camera.pitchDeg - in.lookDelta.y * kDegreesPerPixel, -89.0, 89.0);
    forward = cameraForward(camera);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
    const double speed = camera.moveSpeed * (in.fast ? 4.0 : 1.0);
    camera.position += (right * in.move.x + glm::dvec3(0, 1, 0) * in.move.y + forward * in.move.z) * speed * in.dt;
    // Zoom: each wheel notch moves a tenth of the way to the pivot.
    camera.position += forward * (in.scroll * 0.1 * orbitDistance);
}

}  // namespace shadowlab::app
