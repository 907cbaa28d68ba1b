// LiSPSM: the choice of n (thesis 8.2-8.3, 9.2.5) and the warp matrix (9.2.4).
#include "math/lispsm.h"

#include "math/image_check.h"
#include "math/lispsm_search.h"

namespace shadowlab {

using namespace detail;

double lispsmNOptDirectional(double zNear, double d, double sinGamma) {
    // Thesis eq. 8.11: n_opt = (z_n + sqrt(z_n (z_n + d sin(gamma)))) / sin(gamma).
    sinGamma = std::abs(sinGamma);
    if (!(sinGamma > 0.0)) return kInf;
    return (zNear + std::sqrt(zNear * (zNear + d * sinGamma))) / sinGamma;
}

double lispsmNOptGeneral(double d, double z0, double z1) {
    // Thesis eq. 8.13. The text renders it as d / sqrt(z1/z0 - 1), but the stated identity with
    // eq. 8.11 (z0 = -z_n, z1 = -(z_n + d sin(gamma))) and eq. 8.12 only holds for
    // n = d / (sqrt(z1/z0) - 1), which is also the form of the authors' reference code.
    if (!(z0 < 0.0) || !(z1 < 0.0)) return kInf;
    const double ratio = z1 / z0;
    if (!(ratio > 1.0) || !std::isfinite(ratio)) return kInf;
    return d / (std::sqrt(ratio) - 1.0);
}

namespace detail {

namespace {


// The LiSPSM pre-fit matrix (thesis 9.2.4), acting on light-space homogeneous coordinates, with
// the warp k = 1/n so that k = 0 is exactly the uniform (SSM) map:
//   z' = B_znear - z      (distance from P's near plane, >= 0 over B; we look along -z)
//   w  = 1 + k z'         (the perspective divide of P; C sits n = 1/k behind the near plane)
//   image x = (x - C_x) / w,   image y = z' / w,   depth source = (y - y_ref) / w  (light rays are
//   lines of constant x, z, so along a ray depth is affine in light-space y: the ray order is kept).
// y_ref is B's lowest light-space y. Without it the depth of a point far from y = 0 is dominated by
// y_ref / w, which varies across the map with w instead of along the rays: a spot light's
// post-projective y, for one, sits within 1e-4 of -1 over all of B, so after fitting the depth
// would be nearly -image y, its true variation along each ray a 1e-4 remainder that slope-scale
// offsets and float depth swamp (all shadows lost). Measured from y_ref, depth along a ray spans
// [0, (y_max - y_ref) / w] and keeps its resolution.
glm::dmat4 lispsmPreFit(double zNear, double cx, double k, double yRef) {
    const glm::dvec4 X{1, 0, 0, 0}, Y{0, 1, 0, 0}, Z{0, 0, 1, 0}, W{0, 0, 0, 1};
    const glm::dvec4 zp = zNear * W - Z;
    return fromRows(X - cx * W, zp, Y - yRef * W, W + k * zp);
}


// 1/n in closed form, continuous at sin(gamma) = 0 (where it is exactly 0, i.e. SSM).
double warpDirectional(double zNear, double d, double sinGamma) {
    sinGamma = std::abs(sinGamma);
    return sinGamma / (zNear + std::sqrt(zNear * (zNear + d * sinGamma)));
}
double warpGeneral(double d, double z0, double z1) {
    if (!(z0 < 0.0) || !(z1 < 0.0) || !(d > 0.0)) return 0.0;
    const double ratio = z1 / z0;
    if (!(ratio > 1.0) || !std::isfinite(ratio)) return 0.0;
    return (std::sqrt(ratio) - 1.0) / d;
}

struct NChoice {
    double warp = 0.0;  // 1/n
    double nOpt = kInf, d = 0.0, z0 = 0.0, z1 = 0.0;
    bool ok = false;
};

// Thesis 9.2.5: n from B's light-space extent (d), and z0/z1 from the plane through e_world
// perpendicular to the view direction (the camera near plane when it intersects B).
NChoice chooseN(const LightSpace& ls, const std::vector<glm::dvec3>& body, const glm::dvec3& eWorld,
                const ViewFrustum& view, const ViewBasis& basis, bool bodyVector) {
    NChoice c;
    if (body.empty()) return c;
    const LightSpaceExtent e = extentIn(ls.L, body);
    const double zNearLs = e.z.hi, zFarLs = e.z.lo;
    c.d = zNearLs - zFarLs;
    const glm::dvec3 els = project(ls.L, eWorld);
    // The plane through e_world with normal = view direction, into light space (inverse transpose).
    const glm::dvec4 worldPlane{basis.forward, -glm::dot(basis.forward, eWorld)};
    const glm::dmat4 Linv = glm::inverse(ls.L);
    const glm::dvec4 pl = glm::transpose(Linv) * worldPlane;
    double y = els.y;
    if (std::abs(pl.y) > 1e-12 * (std::abs(pl.x) + std::abs(pl.y) + std::abs(pl.z)))
        y = -(pl.x * els.x + pl.z * zNearLs + pl.w) / pl.y;
    const glm::dmat4 viewM = view.viewMatrix();
    auto eyeZ = [&](const glm::dvec3& q) {
        const glm::dvec4 h = Linv * glm::dvec4(q, 1.0);
        if (!(std::abs(h.w) > 0.0)) return kInf;
        return (viewM * glm::dvec4(glm::dvec3(h) / h.w, 1.0)).z;
    };
    c.z0 = eyeZ({els.x, y, zNearLs});
    c.z1 = eyeZ({els.x, y, zFarLs});
    if (!ls.spot && !bodyVector) {
        // Eq. 8.11 with z_n = the distance of the plane through e_world (= zNear when the near
        // plane intersects B) and d = B's light-space depth (thesis 9.2.5).
        const double zn = std::max(glm::dot(eWorld - view.eye, basis.forward), 1e-300);
        // gamma: angle between the frame's up vector and the light direction (light-space y = -l).
        const double sinGamma = glm::length(glm::cross(glm::normalize(ls.up), glm::dvec3(row(ls.L, 1))));
        c.nOpt = lispsmNOptDirectional(zn, c.d, sinGamma);
        c.warp = warpDirectional(zn, c.d, sinGamma);
        c.ok = std::isfinite(c.warp);
    } else {
        // Eq. 8.13: spot lights (9.2.3), and the body vector (9.2.6), whose frame is not the view
        // direction's, so z0/z1 are measured in it rather than z_n along the view.
        c.nOpt = lispsmNOptGeneral(c.d, c.z0, c.z1);
        c.warp = warpGeneral(c.d, c.z0, c.z1);
        c.ok = std::isfinite(c.warp);
    }
    return c;
}

}  // namespace

glm::dmat4 uniformMatrix(const LightSpace& ls, const std::vector<glm::dvec3>& pts) {
    return fitToPoints(lispsmPreFit(0.0, 0.0, 0.0, 0.0) * ls.L, pts, true);
}

glm::dmat4 lispsmMatrix(const LispsmInputs& in, const LispsmParams& params, bool collectPolygons,
                        ShadowDiagnostics& diag) {
    const ViewFrustum& view = in.view;
    const ViewBasis& basis = in.basis;
    const ShadowLight& light = in.light;
    const LightSpace& ls = in.ls;
    const std::vector<glm::dvec3>& bv = in.bodyVertices;
    const glm::dvec3& eWorld = in.eWorld;
    const glm::dvec3& up = ls.up;
    const double rayLength = in.rayLength;
    const bool spot = ls.spot;
    const glm::dvec3 l = glm::normalize(light.direction);
    glm::dmat4 M{1.0};
    diag.focused = true;
    const LightSpaceExtent e = extentIn(ls.L, bv);
    const glm::dvec3 els = project(ls.L, eWorld);
    // gamma: angle between the frame's up vector and the light direction, measured in
    // light space as the tilt of the orientation ray from the light rays (the y axis).
    const glm::dvec3 towardLightLs{0, 1, 0};
    {
        const glm::dvec4 eh = ls.L * glm::dvec4(eWorld, 1.0);
        const glm::dvec4 bh = ls.L * glm::dvec4(eWorld + up * rayLength * 1e-3, 1.0);
        glm::dvec3 dir = glm::dvec3(bh) / bh.w - glm::dvec3(eh) / eh.w;
        const double len = glm::length(dir);
        diag.gamma = len > 0.0 && std::isfinite(len)
                         ? std::acos(std::clamp(-glm::dot(dir / len, towardLightLs), -1.0, 1.0))
                         : 0.0;
        if (!spot) diag.gamma = std::acos(std::clamp(glm::dot(up, l), -1.0, 1.0));
    }
    const NChoice real = chooseN(ls, bv, eWorld, view, basis, params.useBodyVector && !spot);
    diag.nOptReal = real.nOpt;
    diag.d = real.d;
    diag.z0 = real.z0;
    diag.z1 = real.z1;
    // The visible depth range the depth pre-pass measured: z_f from the farthest visible depth
    // (thesis 9.2.5, paper 4.4) and, symmetric to it, the nearest (an interior's near plane of
    // 0.01 would otherwise claim the warp for depths nothing is seen at). Used for n only.
    auto within = [&](double z) { return z > view.zNear && z < view.zFar; };
    const double depthNear = within(params.pseudoNear) ? params.pseudoNear : view.zNear;
    const double depthFar = std::max(within(params.virtualFar) ? params.virtualFar : view.zFar, depthNear * (1.0 + 1e-9));
    // The closed form for that range: eq. 8.11 with z_f = z_n + d sin(gamma), i.e.
    // n = (z_n + sqrt(z_n z_f)) / sin(gamma). Spot lights keep eq. 8.13 of the real body.
    const double sinGamma = std::sin(diag.gamma);
    diag.nOptVirtual = spot || params.useBodyVector ? real.nOpt
                       : sinGamma > 0.0            ? (depthNear + std::sqrt(depthNear * depthFar)) / sinGamma
                                                   : kInf;
    const double zNearLs = e.z.hi;
    double k = 0.0;
    if (params.overrideN) {
        k = params.n > 0.0 && std::isfinite(params.n) ? 1.0 / params.n : 0.0;
    } else {
        // The measured choice (lispsm_search.h): never worse than k = 0 (SSM) on its samples.
        const WarpSearchInput search{view,    light,    in.sceneBounds,        ls,
                                     bv,      in.visibleLit, in.visibleLitVertices, in.measuredReceivers,
                                     zNearLs, els.x,    depthNear,             depthFar,
                                     params.standInsJoinFewReceivers};
        const WarpSearchResult found = searchWarp(search, std::isfinite(diag.nOptVirtual) ? 1.0 / diag.nOptVirtual : 0.0);
        k = found.warp;
        diag.warpSamples = found.samples;
        diag.estimatedGainOverSsm = found.worstFootprint > 0.0 ? found.uniformFootprint / found.worstFootprint : 1.0;
    }
    if (!std::isfinite(k) || k < 0.0) {
        k = 0.0;
        diag.fallback = "n is not finite: uniform (SSM) map";
    }
    // Thesis 9.2.4: C_start = (e_ls.x, e_ls.y, B_znear); C = C_start + n along +z.
    auto warped = [&](double kk) { return fitToPoints(lispsmPreFit(zNearLs, els.x, kk, e.y.lo) * ls.L, bv, true); };
    M = warped(k);
    // The closed form's warp for a sun (eq. 8.11 over the measured depth range); a spot's search
    // starts from eq. 8.13 of the real body and is not rescued.
    const double kOpt = !spot && std::isfinite(diag.nOptVirtual) && diag.nOptVirtual > 0.0 ? 1.0 / diag.nOptVirtual : 0.0;
    const double depth = e.z.hi - e.z.lo;
    const bool rescue = kOpt > 0.0 && !(warpAtShareOfU(kOpt, depth, kImageRescueBelowShare) < k);
    if (!params.overrideN && in.imageReceivers && (k > 0.0 || rescue)) {
        const ImageCheck check(view, light, *in.imageReceivers, uniformMatrix(ls, bv));
        double keptLoss = 1.0;  // the uniform map's
        if (k > 0.0) k = imageCheckedWarp(check, k, depth, spot, warped, M, diag, keptLoss);
        if (rescue) k = imageRescuedWarp(check, k, keptLoss, kOpt, depth, warped, M, diag);
    }
    diag.warp = k;
    diag.nUsed = k > 0.0 ? 1.0 / k : kInf;
    if (k > 0.0) {
        const glm::dvec4 ch = glm::inverse(ls.L) * glm::dvec4(els.x, els.y, zNearLs + 1.0 / k, 1.0);
        if (std::abs(ch.w) > 0.0 && finite(glm::dvec3(ch) / ch.w)) {
            diag.projectionCenter = glm::dvec3(ch) / ch.w;
            diag.hasProjectionCenter = true;
        }
    }
    if (collectPolygons) {
        const glm::dmat4 inv = glm::inverse(M);
        bool ok = finite(inv);
        for (int i = 0; i < 8 && ok; ++i) {
            const glm::dvec4 h =
                inv * glm::dvec4((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1, 1.0);
            ok = h.w > 0.0 || h.w < 0.0;
        }
        if (ok) diag.lispsmP = ConvexBody::fromFrustum(inv).faces();
    }
    return M;
}

}  // namespace detail
}  // namespace shadowlab
