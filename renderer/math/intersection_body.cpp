// The view frustum V, the spot light's frustum L and the intersection body
// B = ((V n S) + l) n S n L (thesis eq. 4.2, 9.2.2).
#include "math/shadow_internal.h"

namespace shadowlab {

using namespace detail;

namespace {
// L's near plane as a fraction of its far plane (a spot map cannot start at the apex).
constexpr double kSpotNearFraction = 1e-4;
}  // namespace

ConvexBody frustumBody(const ViewFrustum& view) {
    const ViewBasis b = viewBasis(view);
    const double ty = std::tan(0.5 * view.fovY), tx = ty * view.aspect;
    glm::dvec3 c[8];
    for (int i = 0; i < 8; ++i) {
        const double dist = (i & 4) ? view.zFar : view.zNear;
        c[i] = view.eye + b.forward * dist + b.right * (((i & 1) ? 1.0 : -1.0) * tx * dist) +
               b.up * (((i & 2) ? 1.0 : -1.0) * ty * dist);
    }
    // Corner bits x = right, y = up, z = far; since right x up = -forward, these loops run
    // counter-clockwise seen from outside (checked by the tests via volume() > 0).
    PolygonList faces = {
        {c[0], c[1], c[3], c[2]}, {c[4], c[6], c[7], c[5]}, {c[0], c[2], c[6], c[4]},
        {c[1], c[5], c[7], c[3]}, {c[0], c[4], c[5], c[1]}, {c[2], c[3], c[7], c[6]},
    };
    return ConvexBody(std::move(faces));
}

SpotFrustum spotFrustum(const ShadowLight& light, const Aabb& sceneBounds) {
    SpotFrustum s;
    const glm::dvec3 axis = glm::normalize(light.direction);
    double farPlane = light.range;
    if (!(farPlane > 0.0)) {
        farPlane = 0.0;
        for (int i = 0; i < 8 && !sceneBounds.empty(); ++i)
            farPlane = std::max(farPlane, glm::dot(sceneBounds.corner(i) - light.position, axis));
    }
    if (!(farPlane > 0.0) || !std::isfinite(farPlane)) return s;  // scene behind the light
    // Near plane: a fixed fraction of far, but never below what double coordinates at this
    // world offset resolve (1e-7 of the position's magnitude), or the projective light space
    // loses its precision near the apex.
    const double m = std::max({std::abs(light.position.x), std::abs(light.position.y), std::abs(light.position.z)});
    s.nearPlane = std::max(farPlane * kSpotNearFraction, 1e-7 * m);
    s.farPlane = std::max(farPlane, 2.0 * s.nearPlane);
    const double half = std::clamp(light.outerConeAngle, 1e-3, kMaxSpotHalfAngle);
    ViewFrustum v;
    v.eye = light.position;
    v.forward = axis;
    v.up = anyPerpendicular(axis);
    v.fovY = 2.0 * half;
    v.aspect = 1.0;
    v.zNear = s.nearPlane;
    v.zFar = s.farPlane;
    s.view = v.viewMatrix();
    s.projection = v.projectionMatrix();
    return s;
}

namespace detail {
ConvexBody spotBody(const ShadowLight& light, const SpotFrustum& spot) {
    ViewFrustum v;
    v.eye = light.position;
    v.forward = glm::normalize(light.direction);
    v.up = anyPerpendicular(v.forward);
    v.fovY = 2.0 * std::clamp(light.outerConeAngle, 1e-3, kMaxSpotHalfAngle);
    v.aspect = 1.0;
    v.zNear = spot.nearPlane;
    v.zFar = spot.farPlane;
    return frustumBody(v);
}
}  // namespace detail

ConvexBody intersectionBody(const ViewFrustum& view, const ShadowLight& light, const Aabb& sceneBounds,
                            ConvexBody* visibleLit, const std::vector<glm::dvec4>& receiverBounds) {
    // Thesis 9.2.2 (eq. 4.2): B = ((V n S) + l) n S n L.
    ConvexBody body = frustumBody(view);
    body.clip(sceneBounds);
    for (const glm::dvec4& plane : receiverBounds) body.clip(plane);
    if (light.kind == ShadowLightKind::Directional) {
        if (visibleLit) *visibleLit = body;
        body.extrude(-glm::normalize(light.direction), sceneBounds);  // convexHullWithDirection(-l)
        body.clip(sceneBounds);
        return body;
    }
    const SpotFrustum spot = spotFrustum(light, sceneBounds);
    if (!(spot.farPlane > 0.0)) {
        if (visibleLit) *visibleLit = ConvexBody();
        return ConvexBody();
    }
    // L's side planes all pass through the apex, and the cone is invariant under scaling about
    // it, so hull(K + apex) n L = hull((K n L) + apex) n {L's near plane} (its far plane is
    // perpendicular to the axis, so the hull of points within it stays within it). Clipping
    // V n S by L first and then taking the hull gives the same B as the thesis' order, with the
    // side clips done on the smaller body.
    const std::vector<glm::dvec4> lightPlanes = spotBody(light, spot).planes();
    const glm::dvec3 axis = glm::normalize(light.direction);
    for (const auto& p : lightPlanes) body.clip(p);  // L n V n S
    if (visibleLit) *visibleLit = body;
    if (body.empty()) return body;
    body.hullWithPoint(light.position);  // convexHullWithPoint(lightPos)
    body.clip(sceneBounds);
    for (const auto& p : lightPlanes)
        if (glm::dot(glm::dvec3(p), -axis) > 0.999) body.clip(p);  // L's near plane
    return body;
}

}  // namespace shadowlab
