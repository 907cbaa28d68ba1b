// Sample distribution cascades: split depths and tight per-split bounds (see cascades_sdsm.h).
#include "math/cascades_sdsm.h"

#include "math/cascades.h"
#include "math/shadow_internal.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

const char* splitPlacementName(SplitPlacement p) { return p == SplitPlacement::Sdsm ? "sdsm" : "lambda"; }

std::vector<double> sdsmSplitDepths(const VisibleSamples& samples, const glm::dvec3& eye, const glm::dvec3& forward,
                                    double zNear, double zFar, int splits) {
    if (splits < 1 || !(zNear > 0.0 && zFar > zNear)) return {};
    detail::Range depth;
    for (const glm::dvec3& p : samples.points) {
        const double z = glm::dot(p - eye, forward);
        if (std::isfinite(z) && z > 0.0) depth.add(z);
    }
    if (!(depth.lo <= depth.hi)) return {};
    const double lo = std::clamp(depth.lo, zNear, zFar), hi = std::clamp(depth.hi, zNear, zFar);
    // Everything visible at one depth: nothing to split (the caller keeps the practical scheme).
    if (!(hi > lo * (1.0 + 1e-6))) return {};
    return practicalSplitDepths(lo, hi, splits, 1.0);
}

std::vector<glm::dvec3> samplesBetween(const VisibleSamples& samples, const glm::dvec3& eye, const glm::dvec3& forward,
                                       double zLow, double zHigh) {
    std::vector<glm::dvec3> out;
    for (const glm::dvec3& p : samples.points) {
        const double z = glm::dot(p - eye, forward);
        if (z >= zLow && z < zHigh) out.push_back(p);
    }
    return out;
}

std::vector<glm::dvec4> sampleBoundPlanes(const std::vector<glm::dvec3>& points, const glm::dvec3& lightDirection,
                                          const glm::dvec3& forward, double pad) {
    const double lightLength = glm::length(lightDirection), forwardLength = glm::length(forward);
    if (!(lightLength > 0.0 && forwardLength > 0.0) || !std::isfinite(lightLength + forwardLength)) return {};
    const glm::dvec3 l = lightDirection / lightLength;
    const glm::dvec3 a = detail::anyPerpendicular(l), b = glm::cross(l, a);
    // Eight directions across the light make the bound's outline in the map an octagon around
    // the samples: at most ~8% wider than their light-space box in any orientation of the map.
    constexpr int kAcross = 8;
    std::vector<glm::dvec3> directions{l, forward / forwardLength};
    for (int k = 0; k < kAcross; ++k) {
        const double angle = detail::kPi * double(k) / kAcross;
        directions.push_back(std::cos(angle) * a + std::sin(angle) * b);
    }
    std::vector<detail::Range> ranges(directions.size());
    bool any = false;
    for (const glm::dvec3& p : points) {
        if (!detail::finite(p)) continue;
        any = true;
        for (std::size_t i = 0; i < directions.size(); ++i) ranges[i].add(glm::dot(directions[i], p));
    }
    if (!any) return {};
    const double margin = std::isfinite(pad) ? std::max(pad, 0.0) : 0.0;
    std::vector<glm::dvec4> planes;
    for (std::size_t i = 0; i < directions.size(); ++i) {
        // A relative margin too, so rounding at large world offsets never cuts a sample off.
        const double scale = std::max(std::abs(ranges[i].lo), std::abs(ranges[i].hi));
        const double widen = margin + 1e-9 * scale;
        planes.push_back({directions[i], -(ranges[i].hi + widen)});
        planes.push_back({-directions[i], ranges[i].lo - widen});
    }
    return planes;
}

}  // namespace shadowlab
