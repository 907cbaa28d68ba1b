#pragma once
// Orbit and fly camera over CameraSettings (GL-free, GLFW-free: the viewer feeds it input).
#include "math/aabb.h"
#include "settings/settings.h"

namespace shadowlab::app {

class GroundProbe;

struct CameraInput {
    glm::dvec3 flight{0.0};          // WASD/QE: seconds flown along x right, y up, z forward (FlyKeys)
    bool fast = false;               // shift
    glm::dvec2 lookDelta{0.0};       // left drag, pixels: fly look
    glm::dvec2 orbitDelta{0.0};      // right drag, pixels: orbit around the pivot
    double scroll = 0.0;             // wheel: dolly towards / away from the pivot
};

class CameraController {
public:
    // The point right drag orbits around and the wheel dollies towards: the centre of the scene
    // bounds (a point in front of the camera let small models swing out of view).
    glm::dvec3 pivot{0.0};
    // Walk mode: with a scene, the eye stays walkEyeHeight above the ground under it
    // (ground_probe.h) and W/S move along the ground; E/Q do nothing.
    const GroundProbe* walkOn = nullptr;
    double walkEyeHeight = 1.7;
    void apply(CameraSettings& camera, const CameraInput& input) const;
};

// The camera turned to look at the centre of `bounds` from its current direction, moved back until
// the bounding sphere fits both the vertical and the horizontal field of view (Home / F), with the
// far plane pushed out to the sphere's back if needed. Unchanged for empty or non-finite bounds.
CameraSettings framedCamera(const CameraSettings& camera, const Aabb& bounds, double aspect);

}  // namespace shadowlab::app
