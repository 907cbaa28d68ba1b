#include "frame/frame_setup.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

glm::dvec3 cameraForward(const CameraSettings& camera) {
    const double yaw = glm::radians(camera.yawDeg), pitch = glm::radians(camera.pitchDeg);
    return {std::cos(pitch) * std::cos(yaw), std::sin(pitch), std::cos(pitch) * std::sin(yaw)};
}

ViewFrustum viewFrustum(const CameraSettings& camera, double aspect) {
    ViewFrustum v;
    v.eye = camera.position;
    v.forward = cameraForward(camera);
    v.up = {0.0, 1.0, 0.0};
    v.fovY = glm::radians(camera.fovYDeg);
    v.aspect = aspect > 0.0 ? aspect : 1.0;
    v.zNear = camera.nearPlane;
    v.zFar = camera.farPlane;
    return v;
}

CameraSettings cameraFromScene(const Camera& camera, const CameraSettings& base) {
    CameraSettings out = base;
    out.position = glm::dvec3(camera.cameraToWorld[3]);
    glm::dvec3 forward = -glm::dvec3(camera.cameraToWorld[2]);
    const double len = glm::length(forward);
    forward = len > 0.0 && std::isfinite(len) ? forward / len : glm::dvec3(0, 0, -1);
    out.pitchDeg = glm::degrees(std::asin(std::clamp(forward.y, -1.0, 1.0)));
    out.yawDeg = glm::degrees(std::atan2(forward.z, forward.x));
    if (!camera.orthographic) out.fovYDeg = glm::degrees(double(camera.yfov));
    out.nearPlane = camera.znear > 0.0f ? camera.znear : base.nearPlane;
    out.farPlane = camera.zfar > camera.znear ? camera.zfar : std::max(base.farPlane, out.nearPlane * 1000.0);
    return out;
}

namespace {

glm::dvec3 directionFromAngles(double azimuthDeg, double elevationDeg) {
    // Azimuth/elevation say where the light comes FROM; the light travels the other way.
    const double az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
    const glm::dvec3 towardsLight{std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az)};
    return -towardsLight;
}

}  // namespace

LightFrame resolveLight(const Scene& scene, const LightSettings& settings, double seconds) {
    LightFrame frame;
    frame.radiance = settings.color * settings.intensity;
    if (settings.source == LightSource::Scene && settings.sceneLight < int(scene.lights.size())) {
        const Light& l = scene.lights[std::size_t(settings.sceneLight)];
        frame.type = l.type;
        frame.name = l.name;
        frame.direction = glm::length(l.direction) > 0.0 ? glm::normalize(l.direction) : glm::dvec3(0, -1, 0);
        frame.position = l.position;
        // glTF intensities are photometric (lux, candela); the viewer shows relative radiance, so
        // the colour is kept and the brightness comes from the settings.
        frame.radiance = glm::dvec3(l.color) * settings.intensity;
        frame.outerConeAngle = l.outerConeAngle;
        frame.cosOuter = std::cos(double(l.outerConeAngle));
        frame.cosInner = std::cos(double(std::min(l.innerConeAngle, l.outerConeAngle * 0.999f)));
        frame.range = l.range;
    } else if (settings.source == LightSource::Spot) {
        frame.type = LightType::Spot;
        frame.name = "Spot (settings)";
        frame.position = settings.spotPosition;
        frame.direction = directionFromAngles(settings.azimuthDeg, settings.elevationDeg);
        frame.outerConeAngle = glm::radians(settings.spotOuterConeDeg);
        frame.cosOuter = std::cos(frame.outerConeAngle);
        frame.cosInner = std::cos(frame.outerConeAngle * 0.8);
        frame.range = settings.spotRange;
    } else {
        frame.type = LightType::Directional;
        frame.name = "Sun (settings)";
        const double azimuth = settings.azimuthDeg + (settings.animateSun ? seconds * settings.sunDegreesPerSecond : 0.0);
        frame.direction = directionFromAngles(azimuth, settings.elevationDeg);
    }
    if (frame.type == LightType::Point) {
        frame.castsShadow = false;
        frame.note = "'" + frame.name + "' is a point light: lit, but omnidirectional shadows are not supported";
    }
    return frame;
}

ShadowLight shadowLight(const LightFrame& light) {
    ShadowLight s;
    s.kind = light.type == LightType::Spot ? ShadowLightKind::Spot : ShadowLightKind::Directional;
    s.direction = light.direction;
    s.position = light.position;
    s.outerConeAngle = light.outerConeAngle;
    s.range = light.range;
    return s;
}

ClipPlanes clipPlanes(const glm::dmat4& m) {
    // Gribb & Hartmann: the clip-space conditions -w <= x, y, z <= w as world-space planes.
    const glm::dvec4 row0{m[0][0], m[1][0], m[2][0], m[3][0]}, row1{m[0][1], m[1][1], m[2][1], m[3][1]},
        row2{m[0][2], m[1][2], m[2][2], m[3][2]}, row3{m[0][3], m[1][3], m[2][3], m[3][3]};
    return {{row3 + row0, row3 - row0, row3 + row1, row3 - row1, row3 + row2, row3 - row2}};
}

bool boxMayBeVisible(const ClipPlanes& c, const Aabb& box) {
    if (box.empty()) return false;
    for (const glm::dvec4& p : c.planes) {
        // The box corner farthest along the plane normal (the "p-vertex").
        const glm::dvec3 far{p.x >= 0 ? box.max.x : box.min.x, p.y >= 0 ? box.max.y : box.min.y,
                             p.z >= 0 ? box.max.z : box.min.z};
        if (glm::dot(glm::dvec3(p), far) + p.w < 0.0) return false;
    }
    return true;
}

bool warpImageCheck(const Settings& settings) {
    return (settings.method == ShadowMethod::Lispsm && settings.lispsm.imageCheck) ||
           (settings.method == ShadowMethod::Psm && settings.psm.guard);
}

ShadowParams shadowParams(const Settings& settings, const ViewFrustum& view, const Aabb& sceneBounds) {
    ShadowParams p;
    p.method = settings.method;
    // The polygon lists of B, V, S, P are for the wireframe overlays only; skip them otherwise.
    const OverlaySettings& o = settings.overlays;
    p.collectPolygons = o.observerInset || o.lightViewInset;
    p.psmGuard = settings.psm.guard;
    p.imageCheck = warpImageCheck(settings);
    p.lispsm.useBodyVector = settings.lispsm.useBodyVector;
    p.lispsm.overrideN = settings.lispsm.overrideN;
    p.lispsm.n = settings.lispsm.n;
    if (settings.lispsm.autoVirtualFar) {
        // Thesis 9.2.5: z_f = the farthest visible depth. The renderer measures it with a depth
        // pre-pass and replaces this; without one, the farthest scene point in front of the
        // camera bounds it.
        double farthest = 0.0;
        for (int i = 0; i < 8 && !sceneBounds.empty(); ++i)
            farthest = std::max(farthest, glm::dot(sceneBounds.corner(i) - view.eye, view.forward));
        p.lispsm.virtualFar = std::clamp(farthest, view.zNear * 1.001, view.zFar);
    } else {
        p.lispsm.virtualFar = settings.lispsm.virtualFar;
    }
    return p;
}

}  // namespace shadowlab
