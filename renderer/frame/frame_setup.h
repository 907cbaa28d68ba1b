#pragma once
// GL-free glue between the settings contract, the scene and the shadow math: where the camera is,
// which light casts the shadow and how it points. Pure functions, unit-tested without a context.
#include "math/shadow_setup.h"
#include "scenes/scene.h"
#include "settings/settings.h"

#include <string>

namespace shadowlab {

struct LightFrame {
    LightType type = LightType::Directional;
    glm::dvec3 direction{0.0, -1.0, 0.0};  // the way light travels (unit)
    glm::dvec3 position{0.0};
    glm::dvec3 radiance{1.0};  // colour x intensity
    double cosOuter = 0.0, cosInner = 1.0;
    double outerConeAngle = 0.0;  // radians (spot)
    double range = 0.0;
    std::string name;
    // Point lights are lit but cast no shadow (omni maps are not implemented); `note` says so.
    bool castsShadow = true;
    std::string note;
};

glm::dvec3 cameraForward(const CameraSettings& camera);
ViewFrustum viewFrustum(const CameraSettings& camera, double aspect);

// The camera settings that reproduce a glTF camera (roll is dropped: the viewer camera has none).
CameraSettings cameraFromScene(const Camera& camera, const CameraSettings& base);

// The light the settings select, at animation time `seconds` (for the animated sun).
LightFrame resolveLight(const Scene& scene, const LightSettings& light, double seconds);

ShadowLight shadowLight(const LightFrame& light);

// View-frustum culling of the forward pass: may a box be visible through `viewProjection`
// (GL clip conventions)? Conservative: a box straddling a plane is kept.
struct ClipPlanes {
    glm::dvec4 planes[6];  // inside where dot(plane, (p, 1)) >= 0
};
ClipPlanes clipPlanes(const glm::dmat4& viewProjection);
bool boxMayBeVisible(const ClipPlanes& planes, const Aabb& box);
ShadowParams shadowParams(const Settings& settings, const ViewFrustum& view, const Aabb& sceneBounds);
// Whether the method's warp is checked over the pre-pass's fine grid (ShadowParams::imageCheck):
// LiSPSM with lispsm.imageCheck, PSM with its guard.
bool warpImageCheck(const Settings& settings);

}  // namespace shadowlab
