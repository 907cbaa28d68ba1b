#pragma once
// Small helpers shared by the shadow-math files (intersection body, light space, SSM/LiSPSM/PSM
// fits). Internal to shadowlab_math: not part of the public API in shadow_setup.h.
#include "math/shadow_setup.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace shadowlab::detail {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxSpotHalfAngle = 85.0 * kPi / 180.0;

inline bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::dmat4& m);

glm::dvec3 anyPerpendicular(const glm::dvec3& n);

inline glm::dvec4 row(const glm::dmat4& m, int r) { return {m[0][r], m[1][r], m[2][r], m[3][r]}; }
glm::dmat4 fromRows(const glm::dvec4& r0, const glm::dvec4& r1, const glm::dvec4& r2, const glm::dvec4& r3);

// World -> frame: rows are the axes, origin at `o` (the inverse of the frame matrix L_v).
glm::dmat4 frameInverse(const glm::dvec3& x, const glm::dvec3& y, const glm::dvec3& z, const glm::dvec3& o);

inline glm::dvec3 project(const glm::dmat4& m, const glm::dvec3& p) {
    const glm::dvec4 h = m * glm::dvec4(p, 1.0);
    return glm::dvec3(h) / h.w;
}

struct ViewBasis {
    glm::dvec3 forward, right, up;
};
ViewBasis viewBasis(const ViewFrustum& v);

struct Range {
    double lo = kInf, hi = -kInf;
    void add(double t) {
        lo = std::min(lo, t);
        hi = std::max(hi, t);
    }
};

// Rows 0..2 of `pre` become image x, image y and depth, fitted so every point lands in [-1,1]^3.
// All points must have (pre * p).w > 0. Depth is reversed when `depthReversed`.
glm::dmat4 fitToPoints(const glm::dmat4& pre, const std::vector<glm::dvec3>& pts, bool depthReversed);
double minW(const glm::dmat4& m, const std::vector<glm::dvec3>& pts);

// The spot light's cone as a (square) frustum body between L's near and far planes.
ConvexBody spotBody(const ShadowLight& light, const SpotFrustum& spot);

}  // namespace shadowlab::detail
