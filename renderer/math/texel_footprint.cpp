#include "math/texel_footprint.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {

bool projectedGradient(const glm::dmat4& m, const glm::dvec3& p, glm::dvec2 scale, glm::dvec3& gx, glm::dvec3& gy) {
    const glm::dvec4 h = m * glm::dvec4(p, 1.0);
    if (!(h.w > 0.0)) return false;
    const glm::dvec3 r0{m[0][0], m[1][0], m[2][0]}, r1{m[0][1], m[1][1], m[2][1]}, r3{m[0][3], m[1][3], m[2][3]};
    // d(h.x / h.w)/dp = (r0 - (h.x / h.w) r3) / h.w.
    gx = (r0 - (h.x / h.w) * r3) * (scale.x / h.w);
    gy = (r1 - (h.y / h.w) * r3) * (scale.y / h.w);
    return true;
}

double footprintFromGradients(const glm::dvec3& gu, const glm::dvec3& gv, const glm::dvec3& gx, const glm::dvec3& gy,
                              const glm::dvec3& t1, const glm::dvec3& t2) {
    // A = d(texel)/d(tangent), S = d(pixel)/d(tangent); J^-1 = d(pixel)/d(texel) = S A^-1.
    const double a11 = glm::dot(gu, t1), a12 = glm::dot(gu, t2), a21 = glm::dot(gv, t1), a22 = glm::dot(gv, t2);
    const double det = a11 * a22 - a12 * a21;
    if (!(std::abs(det) > 0.0)) return std::numeric_limits<double>::infinity();
    const double s11 = glm::dot(gx, t1), s12 = glm::dot(gx, t2), s21 = glm::dot(gy, t1), s22 = glm::dot(gy, t2);
    // Columns of S A^-1: S (a22, -a21) / det and S (-a12, a11) / det.
    const double c1x = s11 * a22 - s12 * a21, c1y = s21 * a22 - s22 * a21;
    const double c2x = -s11 * a12 + s12 * a11, c2y = -s21 * a12 + s22 * a11;
    return std::sqrt(std::max(c1x * c1x + c1y * c1y, c2x * c2x + c2y * c2y)) / std::abs(det);
}

double texelFootprint(const glm::dmat4& worldToShadowClip, double mapSize, const FootprintCamera& camera,
                      const glm::dvec3& point, const glm::dvec3& normal) {
    glm::dvec3 gu, gv, gx, gy;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (!projectedGradient(worldToShadowClip, point, glm::dvec2(0.5 * mapSize), gu, gv)) return nan;
    if (!projectedGradient(camera.viewProjection, point, 0.5 * glm::dvec2(camera.widthPx, camera.heightPx), gx, gy))
        return nan;
    const glm::dvec3 n = glm::normalize(normal);
    const glm::dvec3 helper = std::abs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 t1 = glm::normalize(glm::cross(helper, n)), t2 = glm::cross(n, t1);
    return footprintFromGradients(gu, gv, gx, gy, t1, t2);
}

}  // namespace shadowlab
