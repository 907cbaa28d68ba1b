// Helpers shared by the shadow-math files: frames, row-wise matrix building and the fit of a
// projective map to a point set (the "focus" step of every parameterization).
#include "math/shadow_internal.h"

namespace shadowlab::detail {

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

ViewBasis viewBasis(const ViewFrustum& v) {
    ViewBasis b;
    b.forward = glm::normalize(v.forward);
    glm::dvec3 r = glm::cross(b.forward, v.up);
    const double len = glm::length(r);
    b.right = len > 1e-12 * glm::length(v.up) && std::isfinite(len) ? r / len : anyPerpendicular(b.forward);
    b.up = glm::cross(b.right, b.forward);
    return b;
}

namespace {
// Fit of one clip row: maps t = (row . h) / (w . h) from [lo, hi] to [-1, 1] (or [1, -1]).
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
}  // namespace

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

}  // namespace shadowlab::detail

namespace shadowlab {

using namespace detail;

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

}  // namespace shadowlab
