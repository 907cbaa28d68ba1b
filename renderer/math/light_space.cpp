// Light space (thesis 9.2.3): L = L_r L_p L_v^-1.
#include "math/light_space.h"

namespace shadowlab::detail {

namespace {

// L_v^-1 (thesis 9.2.3): y = -l, x = v x y, z = x x y; origin at the eye (directional) or the
// light (spot). For v parallel to l (gamma = 0) any x perpendicular to y is as good.
glm::dmat4 lightFrameInverse(const glm::dvec3& towardLight, const glm::dvec3& v, const glm::dvec3& origin) {
    const glm::dvec3 y = towardLight;
    glm::dvec3 x = glm::cross(v, y);
    const double len = glm::length(x);
    x = len > 1e-15 && std::isfinite(len) ? x / len : anyPerpendicular(y);
    const glm::dvec3 z = glm::cross(x, y);
    return frameInverse(x, y, z, origin);
}

// L_p for a spot light in the L_v frame (light looking down -y): a GL-style frustum along -y
// whose post-projective y runs from +1 (near) to -1 (far), so light rays become parallel to y and
// the light sits at y = +infinity, as for a directional light (thesis 9.2.3).
glm::dmat4 spotProjectionAlongY(double n, double f) {
    const double a = (f + n) / (f - n), b = 2.0 * f * n / (f - n);
    return fromRows({1, 0, 0, 0}, {0, a, 0, b}, {0, 0, 1, 0}, {0, -1, 0, 0});
}

}  // namespace

// e_world (thesis 9.2.3): the vertices of L n V n S nearest to the eye (max view-space z),
// averaged over those within a small distance of the nearest.
glm::dvec3 nearestVisiblePoint(const std::vector<glm::dvec3>& verts, const ViewFrustum& view, const ViewBasis& basis) {
    double best = kInf, worst = -kInf;
    for (const auto& p : verts) {
        const double depth = glm::dot(p - view.eye, basis.forward);
        best = std::min(best, depth);
        worst = std::max(worst, depth);
    }
    const double tol = 1e-3 * (worst - best) + 1e-12 * std::abs(best);
    glm::dvec3 sum{0.0};
    int count = 0;
    for (const auto& p : verts)
        if (glm::dot(p - view.eye, basis.forward) <= best + tol) {
            sum += p;
            ++count;
        }
    return count > 0 ? sum / double(count) : view.eye + basis.forward * view.zNear;
}

LightSpace makeLightSpace(const ShadowLight& light, const glm::dvec3& l, const glm::dvec3& up, const SpotFrustum& spot,
                          const glm::dvec3& eWorld, const glm::dvec3& viewDir, double rayLength,
                          const glm::dvec3& eyeOrigin) {
    LightSpace ls;
    ls.up = up;
    if (light.kind == ShadowLightKind::Directional) {
        ls.L = lightFrameInverse(-l, up, eyeOrigin);  // origin at the eye (thesis 9.2.3)
        return ls;
    }
    ls.spot = true;
    const glm::dmat4 lp = spotProjectionAlongY(spot.nearPlane, spot.farPlane) * lightFrameInverse(-l, up, light.position);
    // L_r (thesis 9.2.3): the orientation ray from e_world along v, through L_p; its direction in
    // post-projective space becomes the frame's up (projected on the shadow-map plane x/z).
    glm::dmat4 lr{1.0};
    double t = rayLength;
    for (int i = 0; i < 60; ++i, t *= 0.5) {
        const glm::dvec4 eh = lp * glm::dvec4(eWorld, 1.0), bh = lp * glm::dvec4(eWorld + viewDir * t, 1.0);
        if (!(eh.w > 0.0 && bh.w > 0.0)) continue;
        glm::dvec3 dir = glm::dvec3(bh) / bh.w - glm::dvec3(eh) / eh.w;
        dir.y = 0.0;
        const double len = glm::length(dir);
        if (!(len > 0.0) || !std::isfinite(len)) break;
        // Look-at with (0, 1, 0) as view direction and dir as up: x' = dir x y', z' = x' x y'.
        const glm::dvec3 y{0, 1, 0};
        const glm::dvec3 x = glm::normalize(glm::cross(dir / len, y));
        const glm::dvec3 z = glm::cross(x, y);
        lr = frameInverse(x, y, z, glm::dvec3(0.0));
        break;
    }
    ls.L = lr * lp;
    return ls;
}

LightSpaceExtent extentIn(const glm::dmat4& L, const std::vector<glm::dvec3>& pts) {
    LightSpaceExtent e;
    for (const auto& p : pts) {
        const glm::dvec3 q = project(L, p);
        e.x.add(q.x);
        e.y.add(q.y);
        e.z.add(q.z);
    }
    return e;
}

}  // namespace shadowlab::detail
