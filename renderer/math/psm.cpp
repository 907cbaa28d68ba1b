// Perspective shadow maps (Stamminger & Drettakis 2002, sections 3 and 4.2).
#include "math/psm.h"

namespace shadowlab::detail {

namespace {

// PSM: a post-perspective point light farther than this many radii of B' is treated as
// directional (Stamminger & Drettakis 3.1, the "parallel to the image plane" case); the
// perspective from that far differs from the orthographic map by less than 1/kPsmFarLight.
constexpr double kPsmFarLight = 1e4;


// Perspective shadow maps (Stamminger & Drettakis). One attempt for a given virtual camera.
bool psmAttempt(const ViewFrustum& view, const ViewBasis& basis, const ShadowLight& light, const glm::dvec3& l,
                const std::vector<glm::dvec3>& bv, double moveBack, const Range& depth, double maxTan, PsmResult& r) {
    // Section 4.2: the virtual camera moved back by `moveBack`; its near plane pushed as far as B
    // allows (B's nearest depth), its far plane at B's far end.
    ViewFrustum cam = view;
    cam.eye = view.eye - basis.forward * moveBack;
    cam.zNear = std::max(depth.lo + moveBack, view.zNear);
    cam.zFar = std::max(depth.hi + moveBack, cam.zNear * (1.0 + 1e-9) + 1e-300);
    r.moveBack = moveBack;
    r.zNear = cam.zNear;
    r.zFar = cam.zFar;
    const glm::dmat4 Mc = cam.projectionMatrix() * cam.viewMatrix();
    // B' in post-perspective space (w >= zNear > 0 for all of B).
    std::vector<glm::dvec3> bp;
    bp.reserve(bv.size());
    glm::dvec3 centroid{0.0};
    for (const auto& p : bv) {
        bp.push_back(project(Mc, p));
        centroid += bp.back();
    }
    centroid /= double(bp.size());
    double radius = 0.0;
    for (const auto& q : bp) radius = std::max(radius, glm::length(q - centroid));
    // Section 3: the light in post-perspective space (homogeneous): a directional light is the
    // point at infinity (-l, 0), a spot light its position.
    const bool spot = light.kind == ShadowLightKind::Spot;
    const glm::dvec4 lh = spot ? Mc * glm::dvec4(light.position, 1.0) : Mc * glm::dvec4(-l, 0.0);
    const glm::dvec3 lxyz{lh};
    r.hasLightWorld = false;
    glm::dmat4 pre{1.0};
    if (glm::length(lxyz - lh.w * centroid) > kPsmFarLight * std::max(radius, 1e-300) * std::abs(lh.w)) {
        // Section 3.1: a light parallel to the image plane stays directional. It comes from
        // +lxyz (the limit of lh.xyz - lh.w * b' as w -> 0) and travels along -lxyz.
        r.kind = PostPerspectiveLight::Directional;
        r.reverse = false;
        const glm::dvec3 travel = -glm::normalize(lxyz);
        const glm::dvec3 x = anyPerpendicular(travel), y = glm::cross(travel, x);
        pre = fromRows({x, 0}, {y, 0}, {travel, 0}, {0, 0, 0, 1});  // image x, image y, depth
        r.matrix = fitToPoints(pre * Mc, bv, false);
        return finite(r.matrix) && minW(r.matrix, bv) > 0.0;
    }
    // Point light (w > 0) or inverted point light (w < 0: lights from behind, section 3.1/3.2:
    // the rays converge, so the occluder is the hit farthest from the point: reversed test).
    const glm::dvec3 pLight = lxyz / lh.w;
    r.kind = lh.w > 0.0 ? PostPerspectiveLight::Point : PostPerspectiveLight::InvertedPoint;
    r.reverse = lh.w < 0.0;
    const glm::dvec4 wh = glm::inverse(Mc) * glm::dvec4(pLight, 1.0);
    if (std::abs(wh.w) > 0.0 && finite(glm::dvec3(wh) / wh.w)) {
        r.lightWorld = glm::dvec3(wh) / wh.w;
        r.hasLightWorld = true;
    }
    // A perspective from pLight looking at B': all of B' in front, within atan(maxTan) of the axis.
    auto tryAxis = [&](glm::dvec3 axis) {
        const double len = glm::length(axis);
        if (!(len > 0.0) || !std::isfinite(len)) return false;
        axis /= len;
        const glm::dvec3 x = anyPerpendicular(axis), y = glm::cross(axis, x);
        double sMin = kInf, sMax = 0.0, tanMax = 0.0;
        for (const auto& q : bp) {
            const glm::dvec3 d = q - pLight;
            const double sq = glm::dot(d, axis);
            sMin = std::min(sMin, sq);
            sMax = std::max(sMax, sq);
            if (!(sq > 0.0)) return false;
            tanMax = std::max({tanMax, std::abs(glm::dot(d, x)) / sq, std::abs(glm::dot(d, y)) / sq});
        }
        if (!(sMin > 1e-9 * sMax) || !(tanMax <= maxTan)) return false;
        // Rows on post-perspective homogeneous coordinates (X, Y, Z, W): view-space x, y and the
        // distance s along the axis (each times W); the depth source W / s = 1/s.
        pre = fromRows({x, -glm::dot(x, pLight)}, {y, -glm::dot(y, pLight)}, {0, 0, 0, 1},
                       {axis, -glm::dot(axis, pLight)});
        return true;
    };
    std::vector<glm::dvec3> dirs;
    dirs.reserve(bp.size());
    glm::dvec3 mean{0.0};
    for (const auto& q : bp) {
        dirs.push_back(glm::normalize(q - pLight));
        mean += dirs.back();
    }
    if (!tryAxis(centroid - pLight) && !tryAxis(mean)) {
        // Wide sets of directions: a few subgradient steps toward the axis that maximizes the
        // smallest cosine (the axis of the smallest enclosing cone).
        glm::dvec3 axis = glm::length(mean) > 0.0 ? glm::normalize(mean) : dirs[0];
        bool found = false;
        for (int it = 0; it < 64 && !found; ++it) {
            std::size_t worst = 0;
            double worstDot = kInf;
            for (std::size_t i = 0; i < dirs.size(); ++i) {
                const double d = glm::dot(dirs[i], axis);
                if (d < worstDot) {
                    worstDot = d;
                    worst = i;
                }
            }
            axis = glm::normalize(axis + dirs[worst] * (1.0 / (1.0 + 0.25 * it)));
            found = tryAxis(axis);
        }
        if (!found) return false;
    }
    // 1/s falls with distance: reversed fit, so the depth grows away from pLight.
    r.matrix = fitToPoints(pre * Mc, bv, true);
    return finite(r.matrix) && minW(r.matrix, bv) > 0.0;
}

}  // namespace

PsmResult perspectiveShadowMap(const ViewFrustum& view, const ViewBasis& basis, const ShadowLight& light,
                               const glm::dvec3& l, const std::vector<glm::dvec3>& bv) {
    PsmResult r;
    Range depth;
    for (const auto& p : bv) depth.add(glm::dot(p - view.eye, basis.forward));
    // Section 4.2: move back just enough that all of B is in front of the near plane.
    const double required = std::max(0.0, view.zNear - depth.lo);
    // When the post-perspective light then sees B' only through a (near) 180-degree frustum (a
    // light close to the infinity plane with a huge far/near ratio), move back further: the
    // parameterization degrades continuously toward the uniform map (section 4.2).
    double extra = 0.0;
    const double step = 0.05 * (depth.hi - depth.lo) + view.zNear;
    constexpr double kMaxTan = 5.67;  // tan(80 deg): wider shadow frusta waste most of the map
    for (int attempt = 0; attempt < 40; ++attempt) {
        if (psmAttempt(view, basis, light, l, bv, required + extra, depth, kMaxTan, r)) {
            r.ok = true;
            r.extraMoveBack = extra;
            return r;
        }
        extra = extra == 0.0 ? step : extra * 2.0;
    }
    // Wide spot cones need a wide frustum whatever the move-back: accept any angle below 90 deg.
    r.ok = psmAttempt(view, basis, light, l, bv, required, depth, kInf, r);
    return r;
}

}  // namespace shadowlab::detail
