#include "viewer/camera_controller.h"

#include "frame/frame_setup.h"
#include "ground_probe.h"

#include <algorithm>
#include <cmath>

namespace shadowlab::app {

namespace {

constexpr double kDegreesPerPixel = 0.2;

struct Basis {
    glm::dvec3 right, up, forward;
};

Basis cameraBasis(const CameraSettings& camera) {
    const glm::dvec3 forward = cameraForward(camera);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
    return {right, glm::cross(right, forward), forward};
}

}  // namespace

void CameraController::apply(CameraSettings& camera, const CameraInput& in) const {
    if (in.orbitDelta != glm::dvec2(0.0)) {
        // Turn the camera and carry its position around the pivot so the pivot keeps its place in
        // the camera's frame (and on screen).
        const Basis before = cameraBasis(camera);
        const glm::dvec3 offset = pivot - camera.position;
        const glm::dvec3 local{glm::dot(offset, before.right), glm::dot(offset, before.up),
                               glm::dot(offset, before.forward)};
        camera.yawDeg += in.orbitDelta.x * kDegreesPerPixel;
        camera.pitchDeg = std::clamp(camera.pitchDeg - in.orbitDelta.y * kDegreesPerPixel, -89.0, 89.0);
        const Basis after = cameraBasis(camera);
        camera.position = pivot - (after.right * local.x + after.up * local.y + after.forward * local.z);
    }
    camera.yawDeg += in.lookDelta.x * kDegreesPerPixel;
    camera.pitchDeg = std::clamp(camera.pitchDeg - in.lookDelta.y * kDegreesPerPixel, -89.0, 89.0);
    Basis b = cameraBasis(camera);
    const glm::dvec3 from = camera.position;
    glm::dvec3 flight = in.flight;
    if (walkOn) {
        b.forward = glm::normalize(glm::dvec3(b.forward.x, 0.0, b.forward.z));  // pitch stays with the head
        flight.y = 0.0;
    }
    const double speed = camera.moveSpeed * (in.fast ? 4.0 : 1.0);
    camera.position += (b.right * flight.x + glm::dvec3(0, 1, 0) * flight.y + b.forward * flight.z) * speed;
    // Zoom: each wheel notch moves a tenth of the way to the pivot (at least a twentieth of a
    // second of flying, so the camera can pass through the pivot).
    const double step = std::max(0.1 * glm::distance(pivot, camera.position), 0.05 * camera.moveSpeed);
    camera.position += b.forward * (in.scroll * step);
    if (walkOn && camera.position != from) camera.position = walkTo(*walkOn, from, camera.position, walkEyeHeight);
}

CameraSettings framedCamera(const CameraSettings& camera, const Aabb& bounds, double aspect) {
    const double radius = 0.5 * glm::length(bounds.extent());
    if (bounds.empty() || !std::isfinite(radius)) return camera;
    CameraSettings c = camera;
    const double halfY = glm::radians(std::clamp(c.fovYDeg, 1.0, 179.0)) * 0.5;
    const double halfX = std::atan(std::tan(halfY) * std::max(aspect, 1e-3));
    const double distance = std::max(radius, 1e-3) / std::sin(std::min(halfX, halfY));
    c.position = bounds.center() - cameraForward(c) * distance;
    c.farPlane = std::max(c.farPlane, (distance + radius) * 1.01);
    return c;
}

}  // namespace shadowlab::app
