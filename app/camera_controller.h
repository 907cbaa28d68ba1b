#pragma once
// Orbit and fly camera over CameraSettings (GL-free, GLFW-free: the viewer feeds it input).
#include "settings/settings.h"

namespace shadowlab::app {

struct CameraInput {
    double dt = 0.0;                 // seconds since the last frame
    glm::dvec3 move{0.0};            // WASD/QE: x right, y up, z forward, each in [-1, 1]
    bool fast = false;               // shift
    glm::dvec2 lookDelta{0.0};       // left drag, pixels: fly look
    glm::dvec2 orbitDelta{0.0};      // right drag, pixels: orbit around the pivot
    double scroll = 0.0;             // wheel: dolly towards / away from the pivot
};

class CameraController {
public:
    // Distance in front of the camera of the point orbiting turns around.
    double orbitDistance = 10.0;
    void apply(CameraSettings& camera, const CameraInput& input) const;
};

}  // namespace shadowlab::app
