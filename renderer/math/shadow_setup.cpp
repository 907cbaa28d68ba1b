#include "math/shadow_setup.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMaxSpotHalfAngle = 85.0 * 3.14159265358979323846 / 180.0;
// L's near plane as a fraction of its far plane (a spot map cannot start at the apex).
constexpr double kSpotNearFraction = 1e-4;
// PSM: a post-perspective point light farther than this many radii of B' is treated as
// directional (Stamminger & Drettakis 3.1, the "parallel to the image plane" case); the
// perspective from that far differs from the orthographic map by less than 1/kPsmFarLight.
constexpr double kPsmFarLight = 1e4;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

glm::dvec3 anyPerpendicular(const glm::dvec3& n) {
    const glm::dvec3 helper = std::abs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(helper, n));
}

glm::dvec4 row(const glm::dmat4& m, int r) { return {m[0][r], m[1][r], m[2][r], m[3][r]}; }
glm::dmat4 fromRows(const glm::dvec4& r0, const glm::dvec4& r1, const glm::dvec4& r2, const glm::dvec4& r3) {
    glm::dmat4 m;
    for (int c = 0; c < 4; ++c) {
        m[c][0] = r0[c];
        m[c][1] = r1[c];
        m[c][2] = r2[c];
        m[c][3] = r3[c];
    }
    return m;
}

// World -> frame: rows are the axes, origin at `o` (the inverse of the frame matrix L_v).
glm::dmat4 frameInverse(const glm::dvec3& x, const glm::dvec3& y, const glm::dvec3& z, const glm::dvec3& o) {
    return fromRows({x, -glm::dot(x, o)}, {y, -glm::dot(y, o)}, {z, -glm::dot(z, o)}, {0, 0, 0, 1});
}

struct ViewBasis {
    glm::dvec3 forward, right, up;
};
ViewBasis viewBasis(const ViewFrustum& v) {
    ViewBasis b;
    b.forward = glm::normalize(v.forward);
    glm::dvec3 r = glm::cross(b.forward, v.up);
    const double len = glm::length(r);
    b.right = len > 1e-12 * glm::length(v.up) && std::isfinite(len) ? r / len : anyPerpendicular(b.forward);
    b.up = glm::cross(b.right, b.forward);
    return b;
}

// Fit of one clip row: maps t = (row . h) / (w . h) from [lo, hi] to [-1, 1] (or [1, -1]).
struct Range {
    double lo = kInf, hi = -kInf;
    void add(double t) {
        lo = std::min(lo, t);
        hi = std::max(hi, t);
    }
};
glm::dvec4 fitRow(const glm::dvec4& r, const glm::dvec4& w, Range range, bool reversed, double scale) {
    // Flat ranges (zero-thickness or edge-on bodies) get a width of at least 1e-4 of the widest
    // axis: the map never stretches one axis 1e4 times more than another, which keeps the matrix
    // well conditioned (its rounding at world offsets of 1e5 stays far below the 1e-4 tolerance).
    const double minWidth = 1e-4 * scale + 1e-9 * std::max(std::abs(range.lo), std::abs(range.hi)) + 1e-300;
    if (range.hi - range.lo < minWidth) {
        const double mid = 0.5 * (range.lo + range.hi);
        range.lo = mid - 0.5 * minWidth;
        range.hi = mid + 0.5 * minWidth;
    }
    const double s = 2.0 / (range.hi - range.lo), o = -(range.hi + range.lo) / (range.hi - range.lo);
    const glm::dvec4 out = s * r + o * w;
    return reversed ? -out : out;
}

// Rows 0..2 of `pre` become image x, image y and depth, fitted so every point lands in [-1,1]^3.
// All points must have (pre * p).w > 0. Depth is reversed when `depthReversed` (so that it grows
// along the light's travel).
glm::dmat4 fitToPoints(const glm::dmat4& pre, const std::vector<glm::dvec3>& pts, bool depthReversed) {
    Range rx, ry, rz;
    for (const auto& p : pts) {
        const glm::dvec4 h = pre * glm::dvec4(p, 1.0);
        rx.add(h.x / h.w);
        ry.add(h.y / h.w);
        rz.add(h.z / h.w);
    }
    // Rounding: evaluating the final matrix at world coordinates (offsets up to 1e5) differs from
    // the exact map by about eps * (sum of |terms|) / w. Pad each range by a bound of that, so the
    // evaluated image of every point still lands inside the clip cube.
    {
        const Range* ranges[3] = {&rx, &ry, &rz};
        double pad[3] = {0.0, 0.0, 0.0};
        constexpr double kEps = 8.0 * std::numeric_limits<double>::epsilon();
        for (const auto& p : pts) {
            const glm::dvec4 ph{p, 1.0};
            double absW = 0.0;
            for (int j = 0; j < 4; ++j) absW += std::abs(pre[j][3] * ph[j]);
            const double w = (pre * ph).w;
            for (int r = 0; r < 3; ++r) {
                double absR = 0.0;
                for (int j = 0; j < 4; ++j) absR += std::abs(pre[j][r] * ph[j]);
                const double center = 0.5 * std::abs(ranges[r]->lo + ranges[r]->hi);
                const double t = std::max(std::abs(ranges[r]->lo), std::abs(ranges[r]->hi));
                pad[r] = std::max(pad[r], kEps * (absR + (t + center) * absW) / std::abs(w));
            }
        }
        rx.lo -= 4.0 * pad[0];
        rx.hi += 4.0 * pad[0];
        ry.lo -= 4.0 * pad[1];
        ry.hi += 4.0 * pad[1];
        rz.lo -= 4.0 * pad[2];
        rz.hi += 4.0 * pad[2];
    }
    // A flat axis (zero-thickness B) gets a width relative to the other axes, so the fit's
    // scale stays bounded and rounding in the composed matrix stays below the tolerance.
    double scale = 0.0;
    for (const Range* r : {&rx, &ry, &rz}) scale = std::max(scale, r->hi - r->lo);
    const glm::dvec4 w = row(pre, 3);
    const glm::dmat4 fitted = fromRows(fitRow(row(pre, 0), w, rx, false, scale), fitRow(row(pre, 1), w, ry, false, scale),
                                       fitRow(row(pre, 2), w, rz, depthReversed, scale), w);
    return fitted;
}

double minW(const glm::dmat4& m, const std::vector<glm::dvec3>& pts) {
    double w = kInf;
    for (const auto& p : pts) w = std::min(w, (m * glm::dvec4(p, 1.0)).w);
    return w;
}

// --- Light space (thesis 9.2.3) ---------------------------------------------------------------

struct LightSpace {
    glm::dmat4 L{1.0};  // world -> light space: L = L_r L_p L_v^-1 (projective for spot lights)
    glm::dvec3 up{0.0};  // the frame's up vector (view direction or body vector)
    bool spot = false;
};

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

glm::dvec3 project(const glm::dmat4& m, const glm::dvec3& p) {
    const glm::dvec4 h = m * glm::dvec4(p, 1.0);
    return glm::dvec3(h) / h.w;
}

// e_world (thesis 9.2.3): the vertices of L n V n S nearest to the eye (max view-space z),
// averaged over those within a small distance of the nearest.
glm::dvec3 nearestVisiblePoint(const ConvexBody& lvs, const ViewFrustum& view, const ViewBasis& basis) {
    const auto verts = lvs.vertices();
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

struct LightSpaceExtent {
    Range x, y, z;
};
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

}  // namespace

glm::dmat4 ViewFrustum::viewMatrix() const {
    const ViewBasis b = viewBasis(*this);
    return frameInverse(b.right, b.up, -b.forward, eye);
}

glm::dmat4 ViewFrustum::projectionMatrix() const {
    const double f = 1.0 / std::tan(0.5 * fovY);
    glm::dmat4 p(0.0);
    p[0][0] = f / aspect;
    p[1][1] = f;
    p[2][2] = -(zFar + zNear) / (zFar - zNear);
    p[2][3] = -1.0;
    p[3][2] = -2.0 * zFar * zNear / (zFar - zNear);
    return p;
}

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

namespace {
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
}  // namespace

ConvexBody intersectionBody(const ViewFrustum& view, const ShadowLight& light, const Aabb& sceneBounds,
                            ConvexBody* visibleLit) {
    // Thesis 9.2.2 (eq. 4.2): B = ((V n S) + l) n S n L.
    ConvexBody body = frustumBody(view);
    body.clip(sceneBounds);
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

namespace {

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
                const ViewFrustum& view, const ViewBasis& basis) {
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
    if (!ls.spot) {
        // Eq. 8.11 with z_n = the distance of the plane through e_world (= zNear when the near
        // plane intersects B) and d = B's light-space depth (thesis 9.2.5).
        const double zn = std::max(glm::dot(eWorld - view.eye, basis.forward), 1e-300);
        // gamma: angle between the frame's up vector and the light direction (light-space y = -l).
        const double sinGamma = glm::length(glm::cross(glm::normalize(ls.up), glm::dvec3(row(ls.L, 1))));
        c.nOpt = lispsmNOptDirectional(zn, c.d, sinGamma);
        c.warp = warpDirectional(zn, c.d, sinGamma);
        c.ok = std::isfinite(c.warp);
    } else {
        c.nOpt = lispsmNOptGeneral(c.d, c.z0, c.z1);  // eq. 8.13
        c.warp = warpGeneral(c.d, c.z0, c.z1);
        c.ok = std::isfinite(c.warp);
    }
    return c;
}

}  // namespace

namespace {

struct PsmResult {
    bool ok = false;
    glm::dmat4 matrix{1.0};
    bool reverse = false;
    double moveBack = 0.0, extraMoveBack = 0.0, zNear = 0.0, zFar = 0.0;
    PostPerspectiveLight kind = PostPerspectiveLight::None;
    glm::dvec3 lightWorld{0.0};
    bool hasLightWorld = false;
};

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

}  // namespace

ShadowSetup computeShadowSetup(const ViewFrustum& view, const ShadowLight& light, const Aabb& sceneBounds,
                               const ShadowParams& params) {
    ShadowSetup out;
    ShadowDiagnostics& diag = out.diagnostics;
    diag.method = params.method;

    // --- Input validation: a clear message, never a crash.
    auto reject = [&](const char* why) {
        diag.fallback = why;
        out.valid = false;
        return out;
    };
    if (!finite(view.eye) || !finite(view.forward) || !finite(view.up) || !(glm::length(view.forward) > 0.0))
        return reject("invalid view: non-finite position or zero forward vector");
    if (!(view.fovY > 0.0 && view.fovY < 3.14) || !(view.aspect > 0.0) || !std::isfinite(view.aspect))
        return reject("invalid view: fovY must be in (0, pi) and aspect > 0");
    if (!(view.zNear > 0.0) || !(view.zFar > view.zNear) || !std::isfinite(view.zFar))
        return reject("invalid view: need 0 < zNear < zFar");
    if (!finite(light.direction) || !(glm::length(light.direction) > 0.0))
        return reject("invalid light: zero or non-finite direction");
    if (light.kind == ShadowLightKind::Spot && (!finite(light.position) || !std::isfinite(light.outerConeAngle)))
        return reject("invalid spot light: non-finite position or cone angle");
    if (sceneBounds.empty() || !finite(sceneBounds.min) || !finite(sceneBounds.max))
        return reject("empty or non-finite scene bounds");

    const ViewBasis basis = viewBasis(view);
    const glm::dvec3 l = glm::normalize(light.direction);
    const bool spot = light.kind == ShadowLightKind::Spot;
    const SpotFrustum spotF = spot ? spotFrustum(light, sceneBounds) : SpotFrustum{};

    ConvexBody visibleLit;
    const ConvexBody B = intersectionBody(view, light, sceneBounds, &visibleLit);
    if (params.collectPolygons) {
        diag.viewV = frustumBody(view).faces();
        diag.sceneS = ConvexBody::fromAabb(sceneBounds).faces();
        if (spot && spotF.farPlane > 0.0) diag.lightL = spotBody(light, spotF).faces();
        diag.bodyB = B.faces();
    }
    if (B.empty()) return reject("B is empty: nothing visible is lit (everything counts as lit)");

    const std::vector<glm::dvec3> bv = B.vertices();
    out.bodyPlanes = B.planes();
    out.bodyBounds = B.bounds();
    if (spot) {
        // Culling must not lose casters between the apex and L's near plane (B stops there):
        // drop that plane and let the bounds reach the light.
        // The near cap faces the light (normal -axis) at depth `nearPlane`; its plane, fitted to
        // a possibly tiny face at a large offset, is only approximate, so match it loosely (any
        // light-facing plane that close to the apex: dropping one is conservative anyway).
        const glm::dvec3 axis = l;
        std::erase_if(out.bodyPlanes, [&](const glm::dvec4& p) {
            const double depth = p.w - glm::dot(axis, light.position);  // plane: axis . x = p.w
            return glm::dot(glm::dvec3(p), -axis) > 1.0 - 1e-6 && depth <= 2.0 * spotF.nearPlane;
        });
        out.bodyBounds.extend(light.position);
    }

    // Linear depth (TSM, thesis ch. 5) over B, which contains every relevant caster.
    {
        LinearShadowDepth& lin = out.linearDepth;
        lin.radial = spot;
        lin.axis = l;
        lin.origin = spot ? light.position : view.eye;
        Range r;
        for (const auto& p : bv) r.add(spot ? glm::length(p - lin.origin) : glm::dot(p - lin.origin, l));
        if (spot) r.lo = std::min(r.lo, spotF.nearPlane);  // the apex region is not at a vertex
        const double pad = std::max(1e-9 * std::max(std::abs(r.lo), std::abs(r.hi)), 1e-6 * (r.hi - r.lo));
        lin.nearDepth = r.lo - pad;
        lin.farDepth = r.hi + pad;
    }

    // e_world (thesis 9.2.3) from L n V n S (V n S for directional lights).
    // (Only LiSPSM and the spot frame's orientation ray need it.)
    const bool needE = spot || params.method == ShadowMethod::Lispsm;
    const glm::dvec3 eWorld =
        needE ? nearestVisiblePoint(visibleLit.empty() ? B : visibleLit, view, basis) : view.eye;

    // The frame's up vector: view direction, or the body vector (thesis 9.2.6, directional only).
    glm::dvec3 up = basis.forward;
    if (params.method == ShadowMethod::Lispsm && params.lispsm.useBodyVector && !spot) {
        glm::dvec3 sum{0.0};
        for (const auto& p : bv) sum += p - view.eye;
        const double len = glm::length(sum);
        if (len > 0.0 && std::isfinite(len)) up = sum / len;
        else diag.fallback = "body vector is zero: the view direction is used";
    }
    const double rayLength = std::max(glm::length(out.bodyBounds.extent()), view.zNear);
    const LightSpace ls = makeLightSpace(light, l, up, spotF, eWorld, basis.forward, rayLength, view.eye);

    // SSM in the same light frame (k = 0): the limit LiSPSM converges to (thesis 8.2.3).
    auto ssm = [&](const std::vector<glm::dvec3>& pts) {
        return fitToPoints(lispsmPreFit(0.0, 0.0, 0.0, 0.0) * ls.L, pts, true);
    };

    glm::dmat4 M{1.0};
    bool reverse = false;
    switch (params.method) {
        case ShadowMethod::SsmFocused: {
            diag.focused = true;
            M = ssm(bv);
            break;
        }
        case ShadowMethod::SsmUnfocused: {
            diag.focused = false;
            std::vector<glm::dvec3> pts;
            if (spot) {
                ConvexBody sl = ConvexBody::fromAabb(sceneBounds);
                sl.clip(spotBody(light, spotF));
                pts = sl.vertices();
            } else {
                for (int i = 0; i < 8; ++i) pts.push_back(sceneBounds.corner(i));
            }
            if (pts.empty()) pts = bv;
            pts.insert(pts.end(), bv.begin(), bv.end());
            M = ssm(pts);
            break;
        }
        case ShadowMethod::Lispsm: {
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
            const NChoice real = chooseN(ls, bv, eWorld, view, basis);
            diag.nOptReal = real.nOpt;
            NChoice used = real;
            const double zf = params.lispsm.virtualFar;
            if (zf > view.zNear && zf < view.zFar) {
                // Thesis 9.2.5 / paper 4.4: n from a body built with the virtual far plane; the
                // focusing (bv) keeps the real B.
                ViewFrustum virtualView = view;
                virtualView.zFar = zf;
                const ConvexBody Bv = intersectionBody(virtualView, light, sceneBounds);
                const NChoice virt = chooseN(ls, Bv.vertices(), eWorld, view, basis);
                diag.nOptVirtual = virt.nOpt;
                if (!Bv.empty()) used = virt;
                else diag.fallback = "virtual far plane gives an empty body: n from the real far plane";
            } else {
                diag.nOptVirtual = real.nOpt;
            }
            double k = used.warp;
            if (params.lispsm.overrideN) k = params.lispsm.n > 0.0 && std::isfinite(params.lispsm.n) ? 1.0 / params.lispsm.n : 0.0;
            if (!std::isfinite(k) || k < 0.0) {
                k = 0.0;
                diag.fallback = "n is not finite: uniform (SSM) map";
            }
            diag.warp = k;
            diag.nUsed = k > 0.0 ? 1.0 / k : kInf;
            diag.d = used.d;
            diag.z0 = used.z0;
            diag.z1 = used.z1;
            // Thesis 9.2.4: C_start = (e_ls.x, e_ls.y, B_znear); C = C_start + n along +z.
            const double zNearLs = e.z.hi;
            M = fitToPoints(lispsmPreFit(zNearLs, els.x, k, e.y.lo) * ls.L, bv, true);
            if (k > 0.0) {
                const glm::dvec4 ch = glm::inverse(ls.L) * glm::dvec4(els.x, els.y, zNearLs + 1.0 / k, 1.0);
                if (std::abs(ch.w) > 0.0 && finite(glm::dvec3(ch) / ch.w)) {
                    diag.projectionCenter = glm::dvec3(ch) / ch.w;
                    diag.hasProjectionCenter = true;
                }
            }
            if (params.collectPolygons) {
                const glm::dmat4 inv = glm::inverse(M);
                bool ok = finite(inv);
                for (int i = 0; i < 8 && ok; ++i) {
                    const glm::dvec4 h =
                        inv * glm::dvec4((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1, 1.0);
                    ok = h.w > 0.0 || h.w < 0.0;
                }
                if (ok) diag.lispsmP = ConvexBody::fromFrustum(inv).faces();
            }
            break;
        }
        case ShadowMethod::Psm: {
            diag.focused = true;
            const PsmResult psm = perspectiveShadowMap(view, basis, light, l, bv);
            diag.psmMoveBack = psm.moveBack;
            diag.psmNear = psm.zNear;
            diag.psmFar = psm.zFar;
            diag.psmLightKind = psm.kind;
            diag.projectionCenter = psm.lightWorld;
            diag.hasProjectionCenter = psm.hasLightWorld;
            if (psm.ok) {
                M = psm.matrix;
                reverse = psm.reverse;
            } else {
                diag.fallback = "PSM: no shadow frustum from the post-perspective light contains B; focused SSM used";
                M = ssm(bv);
                reverse = false;
            }
            break;
        }
    }
    if (!finite(M) || !(minW(M, bv) > 0.0)) {
        diag.fallback = "non-finite matrix: focused SSM used";
        M = ssm(bv);
        reverse = false;
        diag.focused = true;
    }
    out.worldToShadowClip = M;
    out.reverseDepthTest = reverse;
    out.valid = true;
    return out;
}

bool casterCanReach(const ShadowSetup& setup, const Aabb& box) {
    if (!setup.valid || box.empty()) return false;
    const Aabb& b = setup.bodyBounds;
    const glm::dvec3 scale = glm::max(glm::abs(b.min), glm::abs(b.max)) + glm::abs(b.extent());
    const double tol = 1e-9 * std::max({scale.x, scale.y, scale.z});
    // Separated by B's bounds?
    if (box.min.x > b.max.x + tol || box.max.x < b.min.x - tol || box.min.y > b.max.y + tol ||
        box.max.y < b.min.y - tol || box.min.z > b.max.z + tol || box.max.z < b.min.z - tol)
        return false;
    // Separated by one of B's face planes? (the box corner farthest inside: the n-vertex)
    for (const glm::dvec4& p : setup.bodyPlanes) {
        const glm::dvec3 nearCorner{p.x >= 0 ? box.min.x : box.max.x, p.y >= 0 ? box.min.y : box.max.y,
                                    p.z >= 0 ? box.min.z : box.max.z};
        if (glm::dot(glm::dvec3(p), nearCorner) + p.w > tol) return false;
    }
    return true;
}

}  // namespace shadowlab
